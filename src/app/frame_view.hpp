#pragma once
// What the renderer and the overlays need from a scene and a pose (kept here so that the
// renderer knows nothing of physics and the physics nothing of pictures).
#include <optional>
#include <vector>

#include "overlay/caption.hpp"
#include "physics/simulator.hpp"
#include "render/renderer.hpp"
#include "scene/scene.hpp"

namespace bookspin::app {

/// Renderer settings from the scene's render.* keys; the camera is framed on the book's
/// bounding sphere unless render.camera_distance is set.
render::RenderSettings render_settings_for(const scene::Scene& scene);

/// The renderer's input for one pose.
render::FrameInput frame_input_for(const physics::BookPose& pose);

/// "diverged at t = 31.35".
std::string divergence_text(double t);

/// The caption of a frame: title, model and toggles, time; plus the divergence warning.
std::vector<overlay::CaptionLine> caption_for(const scene::Scene& scene, double t,
                                              std::optional<double> diverged_at);

}  // namespace bookspin::app
