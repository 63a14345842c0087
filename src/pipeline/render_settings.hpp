#pragma once
// The scene → renderer adapter: what the renderer needs from a scene and a pose (kept here so
// that the renderer knows nothing of physics and the physics nothing of pictures).
#include "physics/simulator.hpp"
#include "render/renderer.hpp"
#include "scene/scene.hpp"

namespace bookspin::pipeline {

/// Renderer settings from the scene's render.* keys; the camera is framed on the book's
/// bounding sphere unless render.camera_distance is set. With render.panel the book is
/// framed in the left kBookShare of the frame, leaving the right for the plots.
render::RenderSettings render_settings_for(const scene::Scene& scene);

/// Same for a width×height image (pixels, even) whose left `book_share` (0 … 1] frames the
/// book: the camera moves sideways (eye and target together), so the projection stays
/// symmetric and the renderer needs no notion of a viewport.
render::RenderSettings render_settings_for(const scene::Scene& scene, int width, int height,
                                           double book_share);

/// The renderer's input for one pose.
render::FrameInput frame_input_for(const physics::BookPose& pose);

}  // namespace bookspin::pipeline
