#pragma once
// What the suites' checks of non-finite numbers share: the message of the InternalError a
// call throws, and the numbers that must never be written.
#include <limits>
#include <string>

#include "common/errors.hpp"

namespace bookspin {

inline constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
inline constexpr double kInf = std::numeric_limits<double>::infinity();

/// The InternalError message of `f()`, or "" when it does not throw one.
template <typename F>
std::string internal_error_of(F f) {
  try {
    f();
  } catch (const InternalError& e) {
    return e.what();
  }
  return "";
}

}  // namespace bookspin
