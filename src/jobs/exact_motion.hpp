#pragma once
// Physics only: a conformance scenario's start and its exact motion at every step (`bookspin
// flipcheck export`, docs/flipcheck.md; docs/physics.md §8), as a value the product writes.
#include <Eigen/Core>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "analysis/judgement.hpp"
#include "common/csv_writer.hpp"
#include "common/stop.hpp"
#include "physics/exact_solution.hpp"

namespace bookspin::jobs {

/// One step of the exact motion: physics::ExactRotation::state() (docs/physics.md §8).
using ExactMotionRow = physics::ExactState;

/// physics::ExactRotation::state() at each of `times`, for a body of principal `moments` (body x,
/// y, z, mass·length²) starting at the identity with body-frame ω0 `omega0_body` (rad per time
/// unit). `stop` is polled every few thousand rows. Throws InputError for a moment that is not
/// finite and positive, an ω0 or a t that is not finite, an ω0 component beyond a scene's
/// ±1e6 (initial.angular_velocity), each naming its argument ("moments[i]", "omega0[i]",
/// "t[i]"), for a motion whose energy, |L| or largest |ω| overflows a double (naming the moments
/// and ω0), and for a t beyond the motion's time horizon (physics::ExactRotation::time_horizon():
/// its phase or precession angle past what a long double carries, docs/physics.md §8, "How far in
/// time"), before any row.
std::vector<ExactMotionRow> exact_motion_at(const Eigen::Vector3d& moments,
                                            const Eigen::Vector3d& omega0_body,
                                            const std::vector<double>& times,
                                            const StopPoll& stop = {});

/// Flat arrays that rows of the exact motion go into, row i at i, row-major: t (N), q (N×4: w,
/// x, y, z), ω in the body and the world frame, L in the world (N×3 each, rad per time unit and
/// mass·length²/time), E (N). A null array is not kept. The one layout of the Python module's
/// numpy arrays and the npm package's Float64Arrays.
struct ExactRowArrays {
  double* t = nullptr;
  double* q = nullptr;
  double* omega_body = nullptr;
  double* omega_world = nullptr;
  double* L = nullptr;
  double* E = nullptr;
  /// `row` written as row `i` of each array kept.
  void put(std::size_t i, const ExactMotionRow& row) const;
};

/// exact_motion_at's rows handed to `row(n, state)` one at a time, in the order of `times`, as
/// they are made (the same checks and throws; rows before a throw have been handed over): for a
/// caller that stores them elsewhere (bookspin.exact_motion writes them straight into its numpy
/// arrays, docs/performance-physics.md, "The exact motion per row").
void exact_motion_each(const Eigen::Vector3d& moments, const Eigen::Vector3d& omega0_body,
                       const std::vector<double>& times, const StopPoll& stop,
                       const std::function<void(std::size_t, const ExactMotionRow&)>& row);

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
/// throws Interrupted. Throws InputError, naming the scenario, where the energy, |L| or largest
/// |ω| overflows a double or steps·dt is beyond the motion's time horizon.
ExactMotion exact_motion(const analysis::Scenario& scenario, const StopPoll& stop = {});

/// The exact motion's CSV: t,qw,qx,qy,qz,wx,wy,wz (ω body frame), then
/// wx_world,wy_world,wz_world,Lx,Ly,Lz (world frame) and E; shortest round-trip numbers.
CsvTable exact_motion_csv(const ExactMotion& motion);

/// The bytes of the two files `flipcheck export` writes and the explorer page offers for
/// download (web/judge_bindings.cpp): one writer of each. No I/O. `stop` is asked every 4096
/// rows of the CSV and throws Interrupted.
struct ExportFiles {
  std::string json;  ///< OUT/<scenario>.json: analysis::scenario_file
  std::string csv;   ///< OUT/<scenario>-exact.csv: exact_motion_csv
};
ExportFiles export_files(const ExactMotion& motion, const StopPoll& stop = {});

}  // namespace bookspin::jobs
