#pragma once
// MuJoCo's mj_step on the same free book, as the physics bench's yardstick. Built only when
// CMake finds MuJoCo (BOOKSPIN_HAVE_MUJOCO); otherwise mujoco_missing() says why not.
#include <memory>
#include <string>

#include "physics/book.hpp"

#ifdef BOOKSPIN_HAVE_MUJOCO
#include <mujoco/mujoco.h>

#include "engines/mujoco_model.hpp"
#endif

namespace bookspin::bench {

struct MujocoSetup {
  physics::Book book;           ///< box half-sizes size/2, mass
  Eigen::Vector3d omega0_body;  ///< initial angular velocity, body frame (= world at t = 0)
  double dt = 0.0;
  bool rk4 = false;  ///< integrator="RK4" instead of "Euler"
};

/// Empty when MuJoCo is linked in, else the reason its rows are skipped.
std::string mujoco_missing();

/// One free body with a box geom of the book's half-sizes and mass, no gravity, no
/// contacts, loaded from an XML string through MuJoCo's virtual file system.
class MujocoBook {
 public:
  /// Throws std::runtime_error if MuJoCo is missing or rejects the model.
  explicit MujocoBook(const MujocoSetup& setup);
  ~MujocoBook();
  MujocoBook(const MujocoBook&) = delete;
  MujocoBook& operator=(const MujocoBook&) = delete;

  /// Identity orientation, angular velocity omega0_body, t = 0.
  void reset();
  /// `steps` calls of mj_step.
  void step(long steps);
  /// Body → world rotation from the free joint's quaternion.
  Eigen::Matrix3d orientation() const;
  /// MuJoCo's principal moments of inertia (derived from the geom), ascending.
  Eigen::Vector3d sorted_moments() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

#ifdef BOOKSPIN_HAVE_MUJOCO
/// The engines room's MJCF loader (src/engines/mujoco_model.hpp).
using engines::load_mjcf;
#endif

}  // namespace bookspin::bench
