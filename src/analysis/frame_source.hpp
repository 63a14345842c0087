#pragma once
// Drives a simulator frame by frame for a scene (data flow: Scene → simulator → Pose).
#include <memory>
#include <optional>
#include <string>

#include "physics/simulator.hpp"
#include "scene/scene.hpp"

namespace bookspin::analysis {

/// Produces the Pose of frame 0 (the initial state), then of each following frame
/// after `time.steps_per_frame` steps of `time.dt`. Stops at the first step whose state is
/// non-finite or absurdly large (physics::kDivergenceLimit): diverged_at() then holds the
/// time of that step, and the last finite pose stays available.
class FrameSource {
 public:
  explicit FrameSource(const scene::Scene& scene);

  /// Advances to the next frame (the first call yields frame 0). False when the clip is
  /// over or the simulation diverged; `pose` is untouched then.
  bool next(physics::Pose& pose);
  int frame() const { return frame_; }  ///< index of the last frame returned
  std::optional<double> diverged_at() const { return diverged_at_; }
  /// Why the simulator stopped, where it says (an implicit step that did not converge);
  /// empty otherwise (the state grew non-finite or absurdly large).
  const std::string& divergence_reason() const { return divergence_reason_; }

 private:
  const scene::Scene& scene_;
  std::unique_ptr<physics::Simulator> simulator_;
  int frame_ = -1;
  long long steps_ = 0;
  std::optional<double> diverged_at_;
  std::string divergence_reason_;
};

}  // namespace bookspin::analysis
