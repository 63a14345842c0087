#include "analysis/frame_source.hpp"

#include "engines/models.hpp"

namespace bookspin::analysis {

FrameSource::FrameSource(const scene::Scene& scene)
    : scene_(scene), simulator_(engines::make_model(scene.body, scene.model)) {
  simulator_->reset(scene.initial);
}

bool FrameSource::next(physics::Pose& pose) {
  if (diverged_at_ || frame_ + 1 >= scene_.frames) return false;
  if (frame_ >= 0) {
    for (int s = 0; s < scene_.steps_per_frame; ++s) {
      simulator_->step(scene_.dt);
      ++steps_;
      if (!simulator_->finite()) {
        diverged_at_ = static_cast<double>(steps_) * scene_.dt;
        divergence_reason_ = simulator_->divergence_reason();
        return false;
      }
    }
  }
  ++frame_;
  pose = simulator_->pose();
  // Frame time from the step count, not the simulator's running sum, so rows are exact.
  pose.diagnostics.t = static_cast<double>(steps_) * scene_.dt;
  return true;
}

}  // namespace bookspin::analysis
