#include "analysis/frame_source.hpp"

#include <sstream>
#include <stdexcept>

#include "engines/models.hpp"
#include "scene/model_line.hpp"

namespace bookspin::analysis {

FrameSource::FrameSource(const scene::Scene& scene)
    : FrameSource(scene, engines::make_model(scene.body, scene.model)) {}

FrameSource::FrameSource(const scene::Scene& scene, std::unique_ptr<physics::Simulator> simulator)
    : scene_(scene), simulator_(std::move(simulator)) {
  if (!simulator_) throw std::invalid_argument("FrameSource: no simulator");
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

std::vector<RunFrames> run_frames(const scene::Scene& scene, const StopPoll& stop) {
  const auto run = [&stop](const scene::Scene& s) {
    RunFrames frames{s, {}, std::nullopt, {}};
    FrameSource source(frames.scene);
    physics::Pose pose;
    for (stop_if_asked(stop, "plot frames"); source.next(pose); stop_if_asked(stop, "plot frames"))
      frames.frames.push_back(pose.diagnostics);
    frames.diverged_at = source.diverged_at();
    frames.model_line = scene::model_line(frames.scene);
    return frames;
  };
  std::vector<RunFrames> runs;
  if (scene.compare.empty()) runs.push_back(run(scene));
  for (const auto& tile : scene.compare) runs.push_back(run(scene::tile_scene(scene, tile)));
  return runs;
}

std::string divergence_warning(const std::string& who, double t, const std::string& reason,
                               const std::string& kept) {
  std::ostringstream w;
  w << who << " diverged at t = " << t << (reason.empty() ? "" : "; " + reason) << "; " << kept;
  return w.str();
}

}  // namespace bookspin::analysis
