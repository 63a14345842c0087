#pragma once
// The σ calibrations' count (docs/phone-lab.md, "Error bars"): how many fitted values lie within
// 2σ of the truth.
#include <cmath>

namespace bookspin::fit::test {

struct Tally {
  int within = 0, count = 0;
  /// One value `error` (fitted − truth) off, with its σ.
  void add(double error, double sigma) {
    ++count;
    within += std::abs(error) <= 2.0 * sigma ? 1 : 0;
  }
  /// The share within 2σ (0 with none counted).
  double fraction() const { return count ? static_cast<double>(within) / count : 0.0; }
};

}  // namespace bookspin::fit::test
