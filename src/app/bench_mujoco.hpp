#pragma once
// MuJoCo's mj_step on the same free book, as the physics bench's yardstick. Built only when
// CMake finds MuJoCo (BOOKSPIN_HAVE_MUJOCO); otherwise mujoco_missing() says so.
#include <string>

#include "physics/book.hpp"
#include "physics/exact_solution.hpp"

namespace bookspin::app {

struct MujocoSetup {
  physics::Book book;            ///< box half-sizes size/2, mass
  Eigen::Vector3d omega0_body;   ///< initial angular velocity, body frame (= world at t = 0)
  double dt = 0.0;
  bool rk4 = false;              ///< integrator="RK4" instead of "Euler"
};

struct MujocoResult {
  double ns_per_step = 0.0;        ///< best of the timing runs, thread CPU time
  double orientation_error = 0.0;  ///< rad, against `exact` after `error_steps` steps
  Eigen::Vector3d moments = Eigen::Vector3d::Zero();  ///< MuJoCo's principal moments, sorted
};

/// Empty when MuJoCo is linked in, else the reason the row is skipped.
std::string mujoco_missing();

/// One free body with a box geom of the book's half-sizes and mass, no gravity, no
/// contacts, loaded from an XML string through a virtual file system. Times `timing_steps`
/// of mj_step (best of `repetitions`) and measures the orientation error after
/// `error_steps`. Throws std::runtime_error if MuJoCo is missing or rejects the model.
MujocoResult run_mujoco(const MujocoSetup& setup, const physics::ExactRotation& exact,
                        long error_steps, long timing_steps, int repetitions);

}  // namespace bookspin::app
