// The major-axis rule (docs/physics.md §17) on a shortened scenes/major-axis-rule.toml (a
// larger wobble, 300 time units): the damped lattice keeps L to round-off, its kinetic plus
// elastic energy never rises from frame to frame beyond the integrator's bounded oscillation,
// and it goes from the smallest axis to the largest; the rigid tile stays about the smallest.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "analysis/frame_source.hpp"
#include "physics/polhode.hpp"
#include "scene/scene.hpp"

namespace bookspin::analysis {
namespace {

scene::Scene shortened() {
  return scene::parse_scene(std::string(BOOKSPIN_SOURCE_DIR) + "/scenes/major-axis-rule.toml",
                            {"initial.jiggle=0.05", "time.frames=1501"});
}

std::vector<physics::Diagnostics> run(const scene::Scene& tile) {
  analysis::FrameSource source(tile);
  std::vector<physics::Diagnostics> rows;
  physics::Pose pose;
  while (source.next(pose)) rows.push_back(pose.diagnostics);
  EXPECT_FALSE(source.diverged_at());
  return rows;
}

TEST(MajorAxisRule, TheDampedLatticeEndsAboutItsLargestAxisWithLFixed) {
  const scene::Scene scene = shortened();
  ASSERT_EQ(scene.compare.size(), 2u);
  const scene::Scene lattice = scene::tile_scene(scene, scene.compare[0]);
  ASSERT_EQ(lattice.model.kind, physics::ModelKind::particle);
  ASSERT_TRUE(lattice.model.damping);
  ASSERT_FALSE(lattice.model.normalize);
  const auto rows = run(lattice);
  ASSERT_EQ(rows.size(), 1501u);

  const double L0 = rows.front().L.norm();
  double worst_L = 0, worst_rise = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    worst_L = std::max(worst_L, std::abs(rows[i].L.norm() - L0) / L0);
    if (i > 0) {
      const double e0 = rows[i - 1].energy_total, e1 = rows[i].energy_total;
      worst_rise = std::max(worst_rise, (e1 - e0) / e0);
    }
  }
  const double drop = 1 - rows.back().energy_total / rows.front().energy_total;
  std::printf(
      "|L| relative deviation %.3g, largest frame-to-frame energy rise %.3g, energy lost "
      "%.3f, cos(smallest, L) %.4f -> %.4f, cos(largest, L) %.4f -> %.4f\n",
      worst_L, worst_rise, drop, rows.front().cos_principal_L[0], rows.back().cos_principal_L[0],
      rows.front().cos_principal_L[2], rows.back().cos_principal_L[2]);
  EXPECT_LT(worst_L, 1e-9);
  EXPECT_LT(worst_rise, 1e-6);
  EXPECT_GT(std::abs(rows.front().cos_principal_L[0]), 0.99);
  // The last 10 time units, not just the last frame: settled, not passing through.
  for (std::size_t i = rows.size() - 50; i < rows.size(); ++i)
    ASSERT_GT(std::abs(rows[i].cos_principal_L[2]), 0.99) << "frame " << i;
  // At fixed |L| the energy falls from L²/(2 I_min) towards L²/(2 I_max): over half of it.
  EXPECT_GT(drop, 0.5);
  // The momentum direction crossed the separatrix: 2E/|L|² went from above 1/I_mid to below.
  const Eigen::Vector3d I = lattice.body.moments;
  const double c_sep = 1 / I[physics::principal_order(I)[1]];
  const auto ratio = [&](const physics::Diagnostics& d) {
    return physics::energy_ratio(I, physics::momentum_direction_body(d));
  };
  EXPECT_GT(ratio(rows.front()), c_sep);
  EXPECT_LT(ratio(rows.back()), c_sep);
}

TEST(MajorAxisRule, TheRigidTileKeepsSpinningAboutItsSmallestAxis) {
  const scene::Scene scene = shortened();
  const scene::Scene rigid = scene::tile_scene(scene, scene.compare[1]);
  ASSERT_NE(rigid.model.kind, physics::ModelKind::particle);
  const auto rows = run(rigid);
  ASSERT_EQ(rows.size(), 1501u);
  double least = 1;
  for (const auto& d : rows) least = std::min(least, std::abs(d.cos_principal_L[0]));
  std::printf("rigid tile: least |cos(smallest, L)| %.5f\n", least);
  EXPECT_GT(least, 0.99);
}

}  // namespace
}  // namespace bookspin::analysis
