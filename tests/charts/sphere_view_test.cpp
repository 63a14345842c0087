// The pipeline's side of the momentum sphere (docs/physics.md §15): what the inset shows for
// the book, where it goes, and the acceptance behaviour of the figures' trails: the Euler
// runs leave the polhode they start on, the exact run stays on it.
#include "charts/sphere_view.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "charts/panel.hpp"
#include "clip/frame.hpp"
#include "physics/polhode.hpp"

namespace bookspin::charts {
namespace {

scene::Scene scene_named(const std::string& name) {
  return scene::parse_scene(std::string(BOOKSPIN_SOURCE_DIR) + "/scenes/" + name + ".toml");
}

/// How far a trail gets from the polhode it starts on: max over frames of
/// |c(t) − c(0)| / (1/I_min − 1/I_max), c = Σ u_i²/I_i = 2E/|L|² (the polhode's label; 0 on
/// it, 1 across the whole family).
double max_polhode_departure(const Eigen::Vector3d& moments, const DiagnosticsHistory& h) {
  const double span = moments.minCoeff() > 0 ? 1 / moments.minCoeff() - 1 / moments.maxCoeff() : 1;
  const double c0 = physics::energy_ratio(moments, h.momentum_direction.front());
  double worst = 0;
  for (const auto& u : h.momentum_direction) {
    if (!u.allFinite() || u.squaredNorm() == 0) continue;
    worst = std::max(worst, std::abs(physics::energy_ratio(moments, u) - c0) / span);
  }
  return worst;
}

/// Whether the trail crosses a separatrix: c − 1/I_mid changes sign.
bool crosses_separatrix(const Eigen::Vector3d& moments, const DiagnosticsHistory& h) {
  const double c_sep = 1 / moments[physics::principal_order(moments)[1]];
  int signs = 0;
  for (const auto& u : h.momentum_direction) {
    if (!u.allFinite() || u.squaredNorm() == 0) continue;
    signs |= physics::energy_ratio(moments, u) > c_sep ? 1 : 2;
  }
  return signs == 3;
}

clip::ShownFrame whole_run(const scene::Scene& scene) {
  return clip::simulate_to(scene, scene.frames - 1);
}

TEST(SphereView, EulerTrailLeavesItsPolhodeTheExactOneStaysOnIt) {
  const auto exact = scene_named("exact-unstable-x");
  const auto fig09 = scene_named("fig09-matrix-unstable-x");
  const auto fig10 = scene_named("fig10-matrix-no-normalization");
  const double d_exact = max_polhode_departure(sphere_moments(exact), whole_run(exact).history);
  const double d_fig09 = max_polhode_departure(sphere_moments(fig09), whole_run(fig09).history);
  const double d_fig10 = max_polhode_departure(sphere_moments(fig10), whole_run(fig10).history);
  std::printf("departure from the starting polhode: exact %.3g, fig09 %.3g, fig10 %.3g\n", d_exact,
              d_fig09, d_fig10);
  EXPECT_LT(d_exact, 1e-9);
  EXPECT_GT(d_fig09, 1e-4);
  EXPECT_GT(d_fig10, 0.05);
}

// Where the energy error carries the state: fig09's normalized Euler run starts just on the
// smallest axis's side of the separatrix (c − 1/I_mid ≈ +6e-7 of the family's span) and its
// energy error pushes it further that way (+4e-3 by the end), so it never crosses; fig10 and
// fig11 (no normalization) cross into the family around the largest axis. The exact run
// stays on its side.
TEST(SphereView, UnnormalizedEulerTrailsCrossTheSeparatrix) {
  for (const char* name : {"exact-unstable-x", "fig09-matrix-unstable-x"}) {
    const auto scene = scene_named(name);
    EXPECT_FALSE(crosses_separatrix(sphere_moments(scene), whole_run(scene).history)) << name;
  }
  for (const char* name : {"fig10-matrix-no-normalization", "fig11-quaternion-no-normalization"}) {
    const auto scene = scene_named(name);
    EXPECT_TRUE(crosses_separatrix(sphere_moments(scene), whole_run(scene).history)) << name;
  }
}

TEST(SphereView, SpecOfTheBookLabelsAxesAndColoursTheSeparatrices) {
  const auto scene = scene_named("fig09-matrix-unstable-x");
  const clip::ShownFrame frame = clip::simulate_to(scene, 20);
  const auto spec =
      sphere_spec(sphere_moments(scene), {SphereRun{&frame.history, palette_colour(0)}});
  ASSERT_EQ(spec.axes.size(), 3u);
  EXPECT_EQ(spec.axes[0].label, "y · smallest I");
  EXPECT_EQ(spec.axes[1].label, "x · intermediate I");
  EXPECT_EQ(spec.axes[2].label, "z · largest I");
  const auto separatrices =
      std::count_if(spec.curves.begin(), spec.curves.end(), [](const auto& c) {
        return c.colour.r == kSeparatrixColour.r && c.colour.b == kSeparatrixColour.b;
      });
  EXPECT_EQ(separatrices, 2);
  EXPECT_GE(spec.curves.size(), 18u);  // ≥ 8 energies × 2 poles + 2 separatrices
  ASSERT_EQ(spec.trails.size(), 1u);
  EXPECT_EQ(spec.trails[0].points.size(), frame.history.size());
  // The run starts spinning about +x: its trail starts at the intermediate axis.
  EXPECT_GT(spec.trails[0].points.front().x(), 0.999);
}

TEST(SphereView, InsetStaysInTheBookPartBelowTheCaptionAboveTheBanner) {
  for (const auto& [w, h] : {std::pair{1280, 720}, std::pair{640, 360}, std::pair{720, 1280}}) {
    const double book = panel_rect(w, h).x;
    const PixelRect r = sphere_rect(w, h, book);
    EXPECT_EQ(r.width, r.height);
    EXPECT_GE(r.x, 0);
    EXPECT_LE(r.right(), book);
    EXPECT_GE(r.y, 0.18 * h);
    EXPECT_LE(r.bottom(), 0.82 * h);  // the banner sits in the bottom ~15%
    EXPECT_GE(r.width, 0.2 * std::min(w, h));
  }
}

// A fourth caption line (render.caption_twist) moves the inset at least one line lower and
// below the box. The caption's box
// by hand (overlay/caption.cpp): font f = max(10, 0.026·h) px, margin and padding 0.6 f, lines
// 1.35 f apart, so three lines end at (0.6 + 0.6 + 3·1.35)·f = 5.25 f, four at 6.6 f.
TEST(SphereView, InsetMovesBelowAFourLineCaption) {
  for (const auto& [w, h] : {std::pair{1280, 720}, std::pair{512, 288}, std::pair{256, 256}}) {
    const double book = panel_rect(w, h).x, font = std::max(10.0, 0.026 * h);
    const PixelRect three = sphere_rect(w, h, book), four = sphere_rect(w, h, book, 4);
    EXPECT_GE(three.y, 5.25 * font - 1e-9) << w << "x" << h;
    EXPECT_GE(four.y, 6.6 * font - 1e-9) << w << "x" << h;
    EXPECT_GE(four.y - three.y, 1.35 * font - 1e-9);
    EXPECT_EQ(four.x, three.x);
    EXPECT_EQ(four.width, three.width);
  }
}

TEST(SphereView, SceneKeyDefaultsOffAndIsOnInTheNamedScenes) {
  EXPECT_FALSE(scene_named("fig03-particle-stable-z").render.sphere);
  for (const char* name :
       {"fig05-particle-unstable-x", "fig09-matrix-unstable-x", "fig10-matrix-no-normalization",
        "fig11-quaternion-no-normalization", "exact-unstable-x", "compare-methods-x"})
    EXPECT_TRUE(scene_named(name).render.sphere) << name;
}

TEST(SphereView, ComparisonColumnGivesTheSphereItsTopAndThePlotsTheRest) {
  const PixelRect column{800, 40, 470, 660};
  const auto [sphere, plots] = split_for_sphere(column);
  EXPECT_EQ(sphere.width, sphere.height);
  EXPECT_NEAR(sphere.height, 0.42 * 660, 1e-9);
  EXPECT_GE(sphere.x, column.x);
  EXPECT_LE(sphere.right(), column.right());
  EXPECT_EQ(sphere.y, column.y);
  EXPECT_GT(plots.y, sphere.bottom());  // no overlap
  EXPECT_NEAR(plots.bottom(), column.bottom(), 1e-9);
  EXPECT_EQ(plots.width, column.width);
}

}  // namespace
}  // namespace bookspin::charts
