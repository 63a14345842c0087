#pragma once
// Every model and its modes, in one table (simulator.cpp): supports(), default_integrator(),
// is_engine() (simulator.hpp), the accuracy rows (analysis::all_methods(),
// engines::engine_modes()) and the scene reader's messages read it, so that a model, an
// engine or an integrator is listed once (docs/physics.md §10, docs/engines.md).
#include <span>
#include <vector>

#include "physics/simulator.hpp"

namespace bookspin::physics {

/// One mode of a model: its kind and an integrator it accepts (the scene's model.kind and
/// model.integrator).
struct ModelMode {
  ModelKind kind;
  Integrator integrator;
};

/// Every mode of every model, by model in the order of ModelKind, each model's default
/// integrator first: particle × {euler, symplectic-euler, velocity-verlet}; rigid-matrix and
/// rigid-quaternion × {euler, rk4, implicit-midpoint, splitting, splitting4,
/// rescaled-euler}; exact × {euler} (the key is unused); mujoco × {euler, rk4, implicit};
/// bullet × {implicit-body, implicit-world, explicit, none}; ode × {step, quickstep, none}. A
/// kind with no row makes no simulator.
std::span<const ModelMode> model_modes();

/// Every model kind, in the order of ModelKind (the names parse_model_kind() accepts).
std::vector<ModelKind> model_kinds();

/// Every integrator, in the order of Integrator (the names parse_integrator() accepts).
std::vector<Integrator> integrators();

}  // namespace bookspin::physics
