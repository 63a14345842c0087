#include "engines/models.hpp"

#include <stdexcept>
#include <string>

#include "engines/bullet_model.hpp"
#include "engines/mujoco_model.hpp"
#include "engines/ode_model.hpp"

namespace bookspin::engines {

std::vector<EngineMode> engine_modes() {
  using physics::Integrator;
  using physics::ModelKind;
  return {{ModelKind::mujoco, Integrator::euler},
          {ModelKind::mujoco, Integrator::rk4},
          {ModelKind::mujoco, Integrator::implicit},
          {ModelKind::bullet, Integrator::implicit_body},
          {ModelKind::bullet, Integrator::implicit_world},
          {ModelKind::bullet, Integrator::explicit_gyro},
          {ModelKind::bullet, Integrator::none},
          {ModelKind::ode, Integrator::step},
          {ModelKind::ode, Integrator::quickstep},
          {ModelKind::ode, Integrator::none}};
}

std::unique_ptr<physics::Simulator> make_model(const physics::Body& body,
                                               const physics::ModelConfig& config) {
  if (!physics::is_engine(config.kind)) return physics::make_simulator(body, config);
  if (!physics::supports(config.kind, config.integrator)) {
    throw std::invalid_argument("model '" + std::string(physics::to_string(config.kind)) +
                                "' does not support integrator '" +
                                std::string(physics::to_string(config.integrator)) + "'");
  }
  switch (config.kind) {
    case physics::ModelKind::mujoco:
      return std::make_unique<MujocoModel>(body, config.integrator);
    case physics::ModelKind::bullet:
      return std::make_unique<BulletModel>(body, config.integrator);
    default:
      return std::make_unique<OdeModel>(body, config.integrator);
  }
}

}  // namespace bookspin::engines
