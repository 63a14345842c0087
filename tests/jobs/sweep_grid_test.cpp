// A sweep's grid (jobs/sweep_grid.hpp, docs/physics.md §14): the values of a --vary range
// (an integer scene key takes whole numbers), the order of the points, the limits, and the
// overrides each point makes.
#include "jobs/sweep_grid.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "common/errors.hpp"

namespace bookspin::jobs {
namespace {

std::string scene_file(const std::string& name) {
  return std::string(BOOKSPIN_SOURCE_DIR) + "/scenes/" + name + ".toml";
}

TEST(SweepGrid, LinearRangeIsEvenlySpacedWithExactEnds) {
  const VaryRange r = parse_vary("time.dt=0.01:0.05:5");
  EXPECT_EQ(r.key, "time.dt");
  EXPECT_EQ(r.component, -1);
  EXPECT_FALSE(r.log);
  const auto v = r.values();
  ASSERT_EQ(v.size(), 5u);
  for (int i = 0; i < 5; ++i) EXPECT_NEAR(v[i], 0.01 * (i + 1), 1e-16);
  EXPECT_EQ(v.front(), 0.01);
  EXPECT_EQ(v.back(), 0.05);
  EXPECT_EQ(parse_vary("time.dt=0.25:9:1").values(), std::vector<double>{0.25});
  // A whole step keeps every value integral, so integer keys (initial.seed) can be swept.
  const auto seeds = parse_vary("initial.seed=1:1000:1000").values();
  for (std::size_t i = 0; i < seeds.size(); ++i) ASSERT_EQ(seeds[i], static_cast<double>(i + 1));
}

TEST(SweepGrid, LogRangeIsGeometricWithExactEnds) {
  const VaryRange r = parse_vary("initial.angular_velocity[1]=1e-6:1e-2:5:log");
  EXPECT_EQ(r.scene_key, "initial.angular_velocity");
  EXPECT_EQ(r.component, 1);
  EXPECT_TRUE(r.log);
  const auto v = r.values();
  ASSERT_EQ(v.size(), 5u);
  for (int i = 0; i < 5; ++i) EXPECT_NEAR(v[i] / std::pow(10.0, i - 6), 1.0, 1e-13) << i;
  EXPECT_EQ(v.front(), 1e-6);
  EXPECT_EQ(v.back(), 1e-2);
  // The spec written into a shard reads back to the same range.
  const VaryRange again = parse_vary(r.key + "=" + r.spec());
  EXPECT_EQ(again.values(), v);
}

TEST(SweepGrid, FirstRangeVariesSlowestLastFastest) {
  const SweepGrid grid({parse_vary("a.b=1:2:2"), parse_vary("c.d=10:30:3")});
  ASSERT_EQ(grid.size(), 6u);
  const std::vector<std::vector<double>> expected{{1, 10}, {1, 20}, {1, 30},
                                                  {2, 10}, {2, 20}, {2, 30}};
  for (std::size_t i = 0; i < 6; ++i) EXPECT_EQ(grid.point(i), expected[i]) << i;
}

TEST(SweepGrid, BadRangesAreInputErrors) {
  for (const char* bad :
       {"time.dt", "time.dt=1:2", "time.dt=1:2:3:lin", "time.dt=a:2:3", "time.dt=1:2:0",
        "time.dt=1:2:2.5", "time.dt=0:1:3:log", "=1:2:3", "initial.angular_velocity[3]=1:2:3",
        "initial.angular_velocity[x]=1:2:3", "time dt=1:2:3", "time.dt=1:inf:3"}) {
    EXPECT_THROW(parse_vary(bad), InputError) << bad;
  }
  EXPECT_THROW(SweepGrid({}), InputError);
  EXPECT_THROW(SweepGrid({parse_vary("time.dt=1:2:2"), parse_vary("time.dt=3:4:2")}), InputError);
  EXPECT_THROW(SweepGrid({parse_vary("book.size=1:2:2"), parse_vary("book.size[0]=3:4:2")}),
               InputError);
}

TEST(SweepGrid, LimitsAreInclusive) {
  // COUNT up to kMaxVaryCount, and a grid of up to kMaxGridPoints points, are accepted;
  // one more is refused (sweep_grid.hpp).
  ASSERT_EQ(kMaxVaryCount, 1000000);
  ASSERT_EQ(kMaxGridPoints, 10000000u);
  EXPECT_EQ(parse_vary("a.b=1:2:1000000").count, 1000000);
  EXPECT_THROW(parse_vary("a.b=1:2:1000001"), InputError);
  EXPECT_EQ(SweepGrid({parse_vary("a.b=1:2:1000000"), parse_vary("c.d=1:2:10")}).size(), 10000000u);
  // 10 000 001 = 11 · 909 091.
  EXPECT_THROW(SweepGrid({parse_vary("a.b=1:2:909091"), parse_vary("c.d=1:2:11")}), InputError);
}

TEST(SweepGrid, VectorComponentsBecomeOneOverrideOfTheWholeVector) {
  const scene::Scene base = scene::parse_scene(scene_file("exact-unstable-x"));
  const SweepGrid grid({parse_vary("initial.angular_velocity[2]=0.5:0.75:2"),
                        parse_vary("time.dt=0.01:0.02:2"),
                        parse_vary("initial.angular_velocity[1]=1e-3:1e-2:2:log")});
  const auto overrides = point_overrides(base, grid, 5);  // (0.75, 0.01, 1e-2)
  ASSERT_EQ(overrides.size(), 2u);
  EXPECT_EQ(overrides[0], "time.dt=0.01");
  EXPECT_EQ(overrides[1], "initial.angular_velocity=[0.114819,0.01,0.75]");
  const scene::Scene placed = scene::parse_scene(scene_file("exact-unstable-x"), overrides);
  EXPECT_EQ(placed.initial.omega0_body, Eigen::Vector3d(0.114819, 0.01, 0.75));
  EXPECT_EQ(placed.dt, 0.01);
  // A component of a key that is not a vector is named.
  const SweepGrid scalar({parse_vary("time.dt[0]=1:2:2")});
  EXPECT_THROW(point_overrides(base, scalar, 0), InputError);
}

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
