#pragma once
// The physics' names listed whole, for a caller that offers them as choices (the explorer page:
// web/bindings.cpp). Each list is in its enum's order; to_string() and the parse functions of
// simulator.hpp and body.hpp name and read each value. The model kinds and the integrators
// come with their table of modes (model_modes.hpp); the body shapes are listed here.
#include <span>

#include "physics/body.hpp"
#include "physics/model_modes.hpp"

namespace bookspin::physics {

/// Every body shape, in BodyShape's order (the book, the presets, then "mesh": a mesh file's).
std::span<const BodyShape> body_shapes();

}  // namespace bookspin::physics
