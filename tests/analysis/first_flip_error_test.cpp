// The judgement's first-flip error (docs/flipcheck.md, "What judge measures"): the motion's
// first turn-over over the exact one's, less one, |first/exact − 1|, a fraction (the accuracy
// table's), not a time. The exact motion shifted by δ turns over δ early; the closed form
// (tests/support/closed_form_flips.hpp, docs/physics.md §8) gives where the exact one lies.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "analysis/conformance.hpp"
#include "analysis/judgement.hpp"
#include "scene/scene.hpp"
#include "support/closed_form_flips.hpp"

namespace bookspin::analysis {
namespace {

TEST(FirstFlipError, IsTheRelativeDifferenceOfTheFirstTurnOvers) {
  const Scenario s = scenario_of(scene::parse_scene(
      std::string(BOOKSPIN_SOURCE_DIR) + "/scenes/flipcheck/book-intermediate-0.05.toml"));
  const physics::ExactRotation exact(s.body.moments, start_omega(s));
  const test::ClosedFormFlips closed = test::closed_form_flips(s.body.moments, start_omega(s));
  const double delta = 0.03 * closed.half_period;
  std::vector<MotionSample> rows;
  for (long long n = 0; n <= s.steps; ++n) {
    const double t = static_cast<double>(n) * s.dt + delta;
    rows.push_back({n, Eigen::Quaterniond(exact.orientation(t)), exact.omega_body(t)});
  }
  const Conformance c = judge_motion(s, rows);
  ASSERT_TRUE(c.first_flip_error.has_value());
  // The first turn-over is found between samples: within 2 dt of first − δ.
  const double expected = delta / closed.first_flip;
  // A first turn-over far from 1 time unit: the fraction δ/first differs from the time δ.
  ASSERT_GT(std::abs(closed.first_flip - 1.0), 0.5);
  EXPECT_NEAR(*c.first_flip_error, expected, 2.0 * s.dt / closed.first_flip);
  // ... and its column holds it.
  const CsvTable table = judgement_table(s, "", {{"run.csv", "run", c}});
  for (std::size_t i = 0; i < table.columns.size(); ++i) {
    if (table.columns[i] == "first_flip_error") {
      EXPECT_NEAR(*std::get<CsvNumber>(table.rows.at(0).at(i)).value, expected,
                  2.0 * s.dt / closed.first_flip);
    }
  }
}

}  // namespace
}  // namespace bookspin::analysis
