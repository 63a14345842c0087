#include "analysis/conformance.hpp"

#include "analysis/judgement.hpp"
#include "analysis/scenario_file.hpp"
#include "common/errors.hpp"
#include "common/sha256.hpp"
#include "engines/models.hpp"

namespace bookspin::analysis {

Scenario scenario_of(const scene::Scene& scene) {
  if (!scene.compare.empty()) {
    throw InputError(scene.source.string() +
                     ": flipcheck: a comparison scene ([[compare]]) is no scenario; give a scene "
                     "of one model");
  }
  if (scene.initial.omega0_body.isZero() && scene.initial.jiggle == 0.0) {
    throw InputError(scene.source.string() +
                     ": flipcheck: the body is at rest (initial.angular_velocity = [0, 0, 0], "
                     "no jiggle): nothing to judge");
  }
  // A conformance scenario is the torque-free spin every engine can run: a scene's air drag
  // (docs/physics.md §21) is no part of it, and dropping it would judge another motion.
  if (scene.model.drag.active()) {
    throw InputError(
        scene.source.string() + ": flipcheck: model.drag: a scenario is torque-free; " +
        "give the scene without drag (render, simulate, plot and explore show a " + "damped toss)");
  }
  // The scene's name (scene.name, or its file's name) is the scenario's: a scene's name takes
  // a letter of any script, a scenario's ASCII alone; said at the key that gives it, the name
  // as it reads (the scene reader took it: UTF-8, no control character).
  if (const std::string why = scenario_name_problem(scene.name); !why.empty()) {
    throw InputError(scene.source.string() + ": flipcheck: scene.name \"" + scene.name +
                     "\" cannot name a scenario: it " + why +
                     "; give the scene a scene.name of that kind");
  }
  Scenario s;
  s.name = scene.name;
  s.body = scene.body;
  s.initial = scene.initial;
  s.dt = scene.dt;
  s.steps = static_cast<long long>(scene.frames - 1) * scene.steps_per_frame;
  check_scenario(s);  // a name that stays inside OUT, and a run the exact motion can carry
  return s;
}

std::string scenario_sha256(const Scenario& scenario) {
  const std::string file = scenario_file(scenario);
  return sha256_text(file);
}

std::vector<MotionSample> simulated_motion(const Scenario& scenario, const Method& method,
                                           const physics::ModelConfig& model, long long stride,
                                           const StopPoll& stop) {
  BOOKSPIN_ASSERT(stride > 0);
  physics::ModelConfig config = model;
  config.kind = method.kind;
  config.integrator = method.integrator;
  const auto sim = engines::make_model(scenario.body, config);
  sim->reset(scenario.initial);
  std::vector<MotionSample> rows;
  rows.reserve(static_cast<std::size_t>(scenario.steps / stride + 1));
  for (long long step = 0;; ++step) {
    if (step % stride == 0) {
      stop_if_asked(stop, "flipcheck steps");
      if (!sim->finite()) break;
      MotionSample row;
      row.step = step;
      row.q = Eigen::Quaterniond(sim->orientation());
      row.omega_body = sim->diagnostics().omega_body;
      if (!row.q.coeffs().allFinite() || !row.omega_body.allFinite()) break;
      rows.push_back(row);
    }
    if (step >= scenario.steps) break;
    sim->step(scenario.dt);
  }
  return rows;
}

}  // namespace bookspin::analysis
