#pragma once
// Drives a simulator frame by frame for a scene (data flow: Scene → simulator → Pose).
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common/stop.hpp"
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
  /// The same with a simulator made by the caller instead of the scene's model (a motion
  /// given rather than simulated: physics::ReplayModel); reset with scene.initial. Throws
  /// std::invalid_argument for a null simulator.
  FrameSource(const scene::Scene& scene, std::unique_ptr<physics::Simulator> simulator);

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

/// One run of a scene from frame 0 to its end or divergence.
struct RunFrames {
  scene::Scene scene;                        ///< the run's scene (a comparison: its tile's)
  std::vector<physics::Diagnostics> frames;  ///< every frame's diagnostics, frame 0 first
  std::optional<double> diverged_at;         ///< when it diverged (FrameSource::diverged_at)
  std::string model_line;                    ///< what was run, in words (scene::model_line)
};

/// scene => its runs (with their model lines), each to its end or divergence: a single scene one
/// run, a comparison one per [[compare]] tile (scene::tile_scene), in tile order. `stop` is
/// polled before every frame ("plot frames"): a signal throws Interrupted (common/stop.hpp).
std::vector<RunFrames> run_frames(const scene::Scene& scene, const StopPoll& stop = {});

/// The one warning of a run that diverged at `t` (time units), without "bookspin: warning: ":
/// "<who> diverged at t = <t>[; <reason>]; <kept>", e.g. who "fig09: simulation", reason
/// FrameSource::divergence_reason() (may be empty), kept "the clip holds its last frame before
/// the blow-up". `t` as a stream writes a double (six significant digits).
std::string divergence_warning(const std::string& who, double t, const std::string& reason,
                               const std::string& kept);

}  // namespace bookspin::analysis
