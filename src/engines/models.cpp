#include "engines/models.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "common/errors.hpp"
#include "engines/bullet_model.hpp"
#include "engines/mujoco_model.hpp"
#include "engines/ode_model.hpp"

namespace bookspin::engines {

std::vector<EngineMode> engine_modes() {
  std::vector<EngineMode> modes;
  for (const physics::ModelMode& mode : physics::model_modes())
    if (physics::is_engine(mode.kind)) modes.push_back(mode);
  return modes;
}

std::unique_ptr<physics::Simulator> make_model(const physics::Body& body,
                                               const physics::ModelConfig& config) {
  const std::vector<physics::ModelKind> kinds = physics::model_kinds();
  if (std::find(kinds.begin(), kinds.end(), config.kind) == kinds.end()) {
    throw InternalError("engines::make_model: model kind " +
                        std::to_string(static_cast<int>(config.kind)) + " is no model's");
  }
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
    case physics::ModelKind::ode:
      return std::make_unique<OdeModel>(body, config.integrator);
    default:
      break;
  }
  // An engine with modes in physics' table but no model here: a bug, never another engine.
  throw InternalError("engines::make_model: no model for engine '" +
                      std::string(physics::to_string(config.kind)) + "'");
}

}  // namespace bookspin::engines
