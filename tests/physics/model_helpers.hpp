#pragma once
// Shared set-up for the physics tests: the original 2012 program's settings (docs/physics.md §6).
#include <functional>

#include "physics/simulator.hpp"

namespace bookspin::physics::testing {

inline physics::Book original_book() { return physics::Book{{1.878, 2.9085, 0.5}, 8.0}; }

/// Body-frame ω0 of the original's keys 1/2/3: L = (1,0,0), (0,0.5,0), (0,0,1) with the
/// inertia without the M/12 factor.
inline Eigen::Vector3d original_omega0(int axis) {
  const Eigen::Vector3d size = original_book().size;
  const double a2 = size.x() * size.x(), b2 = size.y() * size.y(), c2 = size.z() * size.z();
  const Eigen::Vector3d inertia(b2 + c2, a2 + c2, a2 + b2);
  const Eigen::Vector3d L[3] = {{1, 0, 0}, {0, 0.5, 0}, {0, 0, 1}};
  return L[axis].cwiseQuotient(inertia);
}

inline physics::ModelConfig config(physics::ModelKind kind, bool normalize, bool damping = true,
                                   double k = 10.0) {
  physics::ModelConfig c;
  c.kind = kind;
  c.normalize = normalize;
  c.damping = damping;
  c.spring_constant = k;
  return c;
}

/// Runs `steps` steps of `dt`, calling `visit` every `every` steps (and at step 0).
/// Returns false if the simulation stopped being finite.
inline bool run(physics::Simulator& sim, double dt, long steps, long every,
                const std::function<void(const physics::Simulator&)>& visit) {
  visit(sim);
  for (long s = 1; s <= steps; ++s) {
    sim.step(dt);
    if (!sim.finite()) return false;
    if (s % every == 0) visit(sim);
  }
  return true;
}

}  // namespace bookspin::physics::testing
