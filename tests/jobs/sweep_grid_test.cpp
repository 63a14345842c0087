// The values of a --vary range (jobs/sweep_grid.hpp): an integer scene key takes whole numbers.
#include "jobs/sweep_grid.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace bookspin::jobs {
namespace {

TEST(SweepGrid, AnIntegerKeyOnALogRangeTakesTheNearestWholeNumbers) {
  // 10^(i/2) for i = 0 … 8: 1, 3.16…, 10, 31.6…, 100, … rounded as the scene reader needs.
  const VaryRange every = parse_vary("model.normalize_every=1:10000:9:log");
  EXPECT_EQ(every.values(), (std::vector<double>{1, 3, 10, 32, 100, 316, 1000, 3162, 10000}));
  // A number key keeps the log spacing exactly.
  const VaryRange dt = parse_vary("time.dt=1:10000:9:log");
  EXPECT_NEAR(dt.values()[1], std::sqrt(10.0), 1e-14);
}

}  // namespace
}  // namespace bookspin::jobs
