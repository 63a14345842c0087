#pragma once
// The door of src/engines: every model, bookspin's own and the other engines' (MuJoCo, Bullet,
// ODE; docs/engines.md), built from a body and a ModelConfig. Callers above physics make their
// simulators here, so that every job and clip runs the engines unchanged.
#include <memory>
#include <vector>

#include "physics/simulator.hpp"

namespace bookspin::engines {

/// The simulator of `body` for `config`: physics::make_simulator() for bookspin's models, the
/// engine's model for mujoco, bullet and ode (each given body.cage.mass and body.moments in
/// the principal frame, never a collision shape's inertia). Throws std::invalid_argument when
/// the model does not support the integrator (physics::supports), or as make_simulator does.
std::unique_ptr<physics::Simulator> make_model(const physics::Body& body,
                                               const physics::ModelConfig& config);

/// One mode of another engine: its kind and its model.integrator value.
struct EngineMode {
  physics::ModelKind kind;
  physics::Integrator integrator;
};

/// Every engine mode (docs/engines.md), each engine's default first: mujoco × {euler, rk4,
/// implicit}, bullet × {implicit-body, implicit-world, explicit, none}, ode × {step,
/// quickstep, none}.
std::vector<EngineMode> engine_modes();

}  // namespace bookspin::engines
