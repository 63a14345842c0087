#pragma once
// A scene's model in one line of words, as a frame's caption and a plot sheet's header print it.
#include <string>

#include "scene/scene.hpp"

namespace bookspin::scene {

/// "rigid-matrix, euler, dt = 0.01667, normalized": the model kind and, but for the exact
/// motion, its integrator, dt (4 significant digits) and whether it normalizes (not for the
/// engines, which have no such switch: docs/engines.md); for the particle model also
/// "damped"/"undamped" and k. Names are physics' (scenes/README.md's model.kind and
/// model.integrator).
std::string model_line(const Scene& scene);

}  // namespace bookspin::scene
