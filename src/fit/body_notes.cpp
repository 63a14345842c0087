#include "fit/body_notes.hpp"

#include <algorithm>
#include <cstdio>
#include <string>

namespace bookspin::fit {

void body_notes(const FitResult& result, const FitSettings& settings, BodyEstimate& body) {
  const bool fixed = settings.moments.has_value();
  const int tosses = static_cast<int>(result.tosses.size());
  int stable_count = 0;
  for (const TossFit& toss : result.tosses) stable_count += toss.stable;
  if (stable_count == tosses && !fixed) {
    body.moments_determined = false;
    body.notes.push_back(
        std::string("every toss is stable (no flip): the moment ratios are poorly determined; ") +
        kGiveMoments + " to fix them");
  } else if (stable_count > 0) {
    body.notes.push_back(std::to_string(stable_count) +
                         " stable toss(es) (no flip) fitted with the body the others determine");
  }
  if (!fixed && stable_count < tosses) {
    int good = 0;
    double good_seconds = 0.0;
    for (const TossFit& toss : result.tosses)
      if (!toss.stable && !toss.poor_fit)
        ++good, good_seconds += toss.flight.t_end - toss.flight.t_start;
    char line[240];
    if (good == 0) {
      body.moments_determined = false;
      body.notes.push_back(
          "no toss both flips and fits cleanly (every flipping toss is flagged): the moment "
          "ratios are poorly determined");
    } else if (good_seconds < kShortBasis) {
      body.moments_determined = false;
      std::snprintf(line, sizeof line,
                    "the body rests on %d clean flipping toss(es), %.2f s of flight (under %.1f "
                    "s): the moment ratios are poorly determined",
                    good, good_seconds, kShortBasis);
      body.notes.push_back(line);
    }
  }
  if (tosses < 2 && !fixed)
    body.notes.push_back("one toss: no half_period_predicted (it needs the other tosses' body)");
  if (fixed) {
    // Two equal moments: a symmetric body, whose ω only circles its axis; there is no
    // intermediate axis, so no flip to fit or time (docs/physics.md §8).
    Eigen::Vector3d given = settings.moments->cwiseAbs();
    std::sort(given.data(), given.data() + 3);
    const double scale = given[2];
    if (given[1] - given[0] <= 1e-9 * scale || given[2] - given[1] <= 1e-9 * scale)
      body.notes.push_back(
          "--moments: two of the given moments are equal: a symmetric body has no intermediate "
          "axis, so nothing here flips and no half period is timed");
  }
}

}  // namespace bookspin::fit
