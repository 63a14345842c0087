#pragma once
// The median the fit's thresholds are judged against (docs/phone-lab.md, "How the flights are
// found", "Flags", "The times' unit"): one definition for every stage.
#include <algorithm>
#include <vector>

namespace bookspin::fit {

/// The median of `values` (the upper one of an even count); `values` must not be empty.
inline double median_of(std::vector<double> values) {
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

}  // namespace bookspin::fit
