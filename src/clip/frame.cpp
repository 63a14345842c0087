#include "clip/frame.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "charts/decoration.hpp"
#include "clip/render_settings.hpp"
#include "overlay/caption.hpp"

namespace bookspin::clip {

bool advance(analysis::FrameSource& source, int index, const scene::Scene& scene,
             SimulatedFrame& frame) {
  const bool fresh = source.next(frame.pose);
  frame.diverged_at = source.diverged_at();
  if (fresh) {
    const double energy = frame.pose.diagnostics.energy_total;
    if (index == 0) frame.energy0 = energy;
    if (index == 0 || frame.energy0 == 0.0 || std::abs(energy / frame.energy0 - 1.0) < 1.0)
      frame.before_blow_up = frame.pose;
  }
  frame.t = fresh ? frame.pose.diagnostics.t : index * scene.steps_per_frame * scene.dt;
  return fresh;
}

void advance(analysis::FrameSource& source, int index, const scene::Scene& scene,
             ShownFrame& frame) {
  if (advance(source, index, scene, static_cast<SimulatedFrame&>(frame)))
    frame.history.add(frame.pose.diagnostics, &frame.pose.corners);
}

ShownFrame simulate_to(const scene::Scene& scene, int index) {
  if (index < 0 || index >= scene.frames) {
    throw std::out_of_range("frame " + std::to_string(index) + " is outside " + scene.name + " (" +
                            std::to_string(scene.frames) + " frames)");
  }
  analysis::FrameSource source(scene);
  ShownFrame frame;
  for (int i = 0; i <= index; ++i) advance(source, i, scene, frame);
  return frame;
}

RgbaImage render_frame(const scene::Scene& scene, render::Renderer& renderer,
                       const ShownFrame& frame) {
  RgbaImage image = renderer.render(BodyDrawing(scene.body).input_for(frame.picture()));
  decorate_frame(image, scene, frame.t, frame.diverged_at, frame.history);
  return image;
}

RgbaImage render_still(const scene::Scene& scene, render::Renderer& renderer, int index) {
  return render_frame(scene, renderer, simulate_to(scene, index));
}

RgbaImage render_still(const scene::Scene& scene, int index) {
  render::Renderer renderer(render_settings_for(scene));
  return render_still(scene, renderer, index);
}

}  // namespace bookspin::clip
