#pragma once
// The door of src/engines: every model, bookspin's own and the other engines' (MuJoCo, Bullet,
// ODE; docs/engines.md), built from a body and a ModelConfig. Callers above physics make their
// simulators here, so that every job and clip runs the engines unchanged.
#include <memory>
#include <vector>

#include "physics/model_modes.hpp"
#include "physics/simulator.hpp"

namespace bookspin::engines {

/// The simulator of `body` for `config`: physics::make_simulator() for bookspin's models, the
/// engine's model for mujoco, bullet and ode (each given body.cage.mass and body.moments in
/// the principal frame, never a collision shape's inertia). Throws std::invalid_argument when
/// the model does not support the integrator (physics::supports), or as make_simulator does;
/// InputError for a body the engine itself refuses (MuJoCo's compiler: mass or a moment at
/// most its mjMINVAL, 1e-15; one line with the body's numbers);
/// InternalError for a kind that is no model's, or an engine's kind that has no model here
/// (bugs, never another model in its place).
std::unique_ptr<physics::Simulator> make_model(const physics::Body& body,
                                               const physics::ModelConfig& config);

/// One mode of another engine: its kind and its model.integrator value.
using EngineMode = physics::ModelMode;

/// Every engine mode: the rows of physics::model_modes() whose kind is another engine's
/// (physics::is_engine), in that table's order, each engine's default first (docs/engines.md).
std::vector<EngineMode> engine_modes();

}  // namespace bookspin::engines
