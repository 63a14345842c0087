#pragma once
// What the particle model of a non-book body is made of (docs/physics.md §13): printed at the
// start of a run so that the lattice's own inertia is seen next to the body's.
#include <string>

#include "scene/scene.hpp"

namespace bookspin::jobs {

/// One line per lattice the scene runs (the scene's model, or each particle tile of a
/// comparison), e.g. "lattice: 24 cells along the longest side, 925 particles, 8748 springs;
/// principal moments 0.2121, 0.4187, 0.5936 against the body's 0.2090, 0.4213, 0.5949
/// (+1.5%, -0.6%, -0.2%)". Empty when no lattice runs (the book is one cell, §2). Builds the
/// lattice (tens of milliseconds); throws std::invalid_argument as physics::build_lattice.
std::string lattice_note(const scene::Scene& scene);

}  // namespace bookspin::jobs
