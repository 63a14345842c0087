#pragma once
// Names, not bytes, for the physics enums that parametrize tests: gtest prints a test's
// parameter into the names ctest registers, and an enum without PrintTo prints as bytes.
#include <ostream>

#include "physics/simulator.hpp"

namespace bookspin::physics {

[[maybe_unused]] inline void PrintTo(ModelKind kind, std::ostream* out) { *out << to_string(kind); }
[[maybe_unused]] inline void PrintTo(Integrator integrator, std::ostream* out) {
  *out << to_string(integrator);
}

}  // namespace bookspin::physics
