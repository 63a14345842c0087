#pragma once
// The physics' names listed whole, for a caller that offers them as choices (the explorer page:
// web/bindings.cpp). Each list is in its enum's order; to_string() and the parse functions of
// simulator.hpp and body.hpp name and read each value.
#include <span>

#include "physics/body.hpp"
#include "physics/simulator.hpp"

namespace bookspin::physics {

/// Every model kind, in ModelKind's order (bookspin's own, then the other engines': is_engine()).
std::span<const ModelKind> model_kinds();
/// Every integrator, in Integrator's order (bookspin's own, then the other engines' modes).
std::span<const Integrator> integrators();
/// Every body shape, in BodyShape's order (the book, the presets, then "mesh": a mesh file's).
std::span<const BodyShape> body_shapes();

}  // namespace bookspin::physics
