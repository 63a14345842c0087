#pragma once
// Physics only: a conformance scenario's start and its exact motion at every step (`bookspin
// flipcheck export`, docs/flipcheck.md; docs/physics.md §8), as a value the product writes.
#include <Eigen/Core>
#include <vector>

#include "analysis/conformance.hpp"
#include "common/stop.hpp"

namespace bookspin::jobs {

/// One step of the exact motion.
struct ExactMotionRow {
  double t = 0.0;               ///< step·dt, time units
  Eigen::Vector4d q;            ///< unit quaternion (w, x, y, z) of R(t), body → world, w ≥ 0
  Eigen::Vector3d omega_body;   ///< rad per time unit, body frame
  Eigen::Vector3d omega_world;  ///< R(t)·ω, world frame
  Eigen::Vector3d L;            ///< R(t)·I_body·ω, world frame (mass·length²/time unit)
  double E = 0.0;               ///< ½ ω·I_body ω, energy units
};

/// What an engine needs to run a scenario, and the exact answer.
struct ExactMotion {
  analysis::Scenario scenario;
  double mass = 0.0;                 ///< the body's mass (mass units)
  Eigen::Vector3d omega0_body;       ///< the jiggled start, analysis::start_omega
  Eigen::Vector3d omega0_world;      ///< = omega0_body (q0 = identity)
  std::vector<ExactMotionRow> rows;  ///< steps + 1 rows, step 0 first
};

/// The exact motion (physics::ExactRotation from the jiggled start) of `scenario` at every
/// step n = 0 … steps, t = n·dt as a product. `stop` is polled every few thousand rows and
/// throws Interrupted.
ExactMotion exact_motion(const analysis::Scenario& scenario, const StopPoll& stop = {});

}  // namespace bookspin::jobs
