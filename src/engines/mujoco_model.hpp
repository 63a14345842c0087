#pragma once
// MuJoCo's free body as a bookspin model (docs/engines.md): mj_step with the integrator
// option of its XML ("Euler", "RK4", "implicit"), no gravity, no contacts.
#include <mujoco/mujoco.h>

#include <string>

#include "engines/engine_body.hpp"

namespace bookspin::engines {

/// Loads an MJCF model from `xml` through MuJoCo's virtual file system, as file `file_name`.
/// Throws std::runtime_error naming `what` if MuJoCo rejects it. The caller owns the model
/// (mj_deleteModel). Serialized: MuJoCo's XML reader keeps global state.
mjModel* load_mjcf(const std::string& xml, const char* file_name, const char* what);

/// One body on a free joint with the body's mass and principal moments as its inertial
/// (pos 0, diaginertia = body.moments: the principal frame is the body frame), no geom.
/// State: the free joint's qpos (position, then q = w x y z, body → world) and qvel (linear,
/// then ω in the body frame). step(dt) sets opt.timestep = dt and calls mj_step once.
class MujocoModel final : public EngineBody {
 public:
  /// `integrator`: euler, rk4 or implicit. Throws std::runtime_error if MuJoCo rejects the
  /// model (a body whose moments break A + B ≥ C).
  MujocoModel(const physics::Body& body, physics::Integrator integrator);
  ~MujocoModel() override;
  MujocoModel(const MujocoModel&) = delete;
  MujocoModel& operator=(const MujocoModel&) = delete;

  void reset(const physics::InitialState& initial) override;
  /// One mj_step of dt. Where MuJoCo finds a bad number and resets its state, the run ends
  /// instead: finite() turns false and divergence_reason() says when.
  void step(double dt) override;
  bool finite() const override;
  std::string divergence_reason() const override { return failure_; }

 private:
  Eigen::Quaterniond engine_quaternion() const override;
  Eigen::Vector3d engine_omega_body() const override;

  std::string failure_;  ///< why the run ended; empty while it runs
  mjModel* model_ = nullptr;
  mjData* data_ = nullptr;
};

/// The XML option value of a MuJoCo mode: "Euler", "RK4" or "implicit".
const char* mujoco_integrator_name(physics::Integrator integrator);

}  // namespace bookspin::engines
