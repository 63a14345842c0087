#pragma once
// What the renderer and the overlays need from a scene and a pose (kept here so that the
// renderer knows nothing of physics and the physics nothing of pictures).
#include <optional>
#include <vector>

#include "app/diagnostics_history.hpp"
#include "common/rgba_image.hpp"
#include "overlay/caption.hpp"
#include "physics/simulator.hpp"
#include "render/renderer.hpp"
#include "scene/scene.hpp"

namespace bookspin::app {

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

/// "diverged at t = 31.35".
std::string divergence_text(double t);

/// The caption of a frame: title, model and toggles, time; plus the divergence warning.
std::vector<overlay::CaptionLine> caption_for(const scene::Scene& scene, double t,
                                              std::optional<double> diverged_at);

/// The model line of a caption: "rigid-matrix, euler, dt = 0.01667, normalized".
std::string model_line(const scene::Scene& scene);

/// Decorates a rendered frame of `scene` at time `t`: with render.panel the live plots of
/// `history` (every frame so far) on the right, then the caption (kept within the book's
/// part), then after a divergence the "diverged at" banner.
void decorate_frame(RgbaImage& image, const scene::Scene& scene, double t,
                    std::optional<double> diverged_at, const DiagnosticsHistory& history);

}  // namespace bookspin::app
