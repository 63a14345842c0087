// Poinsot's construction (docs/physics.md §16) against an exact run: the contact point
// ρ = ω/√(2E) on the invariable plane (distance √(2E)/|L| along L) and on the inertia ellipsoid
// xᵀIx = 1, the ellipsoid's normal there along L, the herpolhode's distance from the L axis
// inside (and reaching) its closed-form bounds, the polhode on the ellipsoid.
#include "physics/poinsot.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "model_helpers.hpp"
#include "physics/polhode.hpp"

namespace bookspin::physics {
namespace {

struct Sample {
  PoinsotState state;
  Eigen::Vector3d L;
};

/// The exact model of the book spun about x (the unstable axis) with the figure scenes'
/// jiggle: `count` samples `every` steps of 1/60 apart.
std::vector<Sample> exact_run(const Eigen::Vector3d& omega0, int count, int every) {
  const Book book = testing::original_book();
  auto sim = make_simulator(book, testing::config(ModelKind::exact, false));
  sim->reset({omega0, 1e-3, 2012});
  std::vector<Sample> out;
  testing::run(
      *sim, 1.0 / 60.0, static_cast<long>(count - 1) * every, every, [&](const Simulator& s) {
        const Diagnostics d = s.diagnostics();
        out.push_back(
            {poinsot_state(book.principal_moments(), rotation_from_corners(s.corners()), d.L),
             d.L});
      });
  return out;
}

TEST(Poinsot, ContactPointOnThePlaneAndOnTheEllipsoidWithItsNormalAlongL) {
  const Eigen::Vector3d moments = testing::original_book().principal_moments();
  const auto run = exact_run({0.114819, 0.0, 0.0}, 600, 40);  // 400 time units, ~2 flips
  ASSERT_EQ(run.size(), 600u);
  const double d0 = run.front().state.plane_distance;
  for (const auto& [s, L] : run) {
    // The plane is fixed: its normal and distance are those of the first sample.
    ASSERT_LT((s.normal - run.front().state.normal).norm(), 1e-12);
    ASSERT_NEAR(s.plane_distance, d0, 1e-12 * d0);
    ASSERT_NEAR(s.contact.dot(L.normalized()), d0, 1e-12 * d0) << "on the plane";
    ASSERT_NEAR(inertia_ellipsoid_value(s, moments, s.contact), 1.0, 1e-12) << "on the ellipsoid";
    ASSERT_GT(inertia_ellipsoid_normal(s, moments, s.contact).dot(L.normalized()), 1.0 - 1e-12)
        << "tangent to the plane";
  }
}

TEST(Poinsot, SteadySpinTouchesAtTheEllipsoidsVertex) {
  // ω = (w, 0, 0): E = ½ I_x w², |L| = I_x w, so √(2E)/|L| = 1/√I_x, the semi-axis along x.
  const Eigen::Vector3d moments(0.5, 1.25, 2.0);
  const double w = 3.0;
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).matrix();
  const PoinsotState s = poinsot_state(moments, R, R * Eigen::Vector3d(moments.x() * w, 0, 0));
  EXPECT_NEAR(s.plane_distance, 1.0 / std::sqrt(0.5), 1e-14);
  EXPECT_LT((s.contact - R.col(0) / std::sqrt(0.5)).norm(), 1e-14);
  EXPECT_NEAR(s.energy, 0.5 * 0.5 * w * w, 1e-14);
  const HerpolhodeBounds b = herpolhode_bounds(moments, moments.x() * w, s.energy);
  EXPECT_NEAR(b.min, 0.0, 1e-7);
  EXPECT_NEAR(b.max, 0.0, 1e-7);
}

TEST(Poinsot, HerpolhodeStaysWithinItsClosedFormBoundsAndReachesThem) {
  // One run near the separatrix (the unstable x spin) and one circling the smallest axis.
  for (const Eigen::Vector3d& omega0 :
       {Eigen::Vector3d(0.114819, 0.0, 0.0), Eigen::Vector3d(0.02, 0.12, 0.01)}) {
    const auto run = exact_run(omega0, 3000, 8);  // 400 time units
    const Eigen::Vector3d moments = testing::original_book().principal_moments();
    const double E = run.front().state.energy, Ln = run.front().L.norm();
    const HerpolhodeBounds b = herpolhode_bounds(moments, Ln, E);
    ASSERT_LT(b.min, b.max);
    double seen_min = 1e300, seen_max = 0;
    for (const auto& [s, L] : run) {
      const Eigen::Vector3d n = L.normalized();
      const double r = (s.contact - s.contact.dot(n) * n).norm();
      ASSERT_GE(r, b.min - 1e-9 * b.max);
      ASSERT_LE(r, b.max + 1e-9 * b.max);
      seen_min = std::min(seen_min, r);
      seen_max = std::max(seen_max, r);
    }
    // Sampled every 8/60: the extremes are reached to within a small fraction of the span.
    EXPECT_LT(seen_min - b.min, 0.01 * (b.max - b.min)) << omega0.transpose();
    EXPECT_GT(seen_max - b.max, -0.01 * (b.max - b.min)) << omega0.transpose();
  }
}

TEST(Poinsot, PolhodeOnTheEllipsoidHoldsTheRunsContactPoints) {
  const Eigen::Vector3d moments = testing::original_book().principal_moments();
  const auto run = exact_run({0.02, 0.12, 0.01}, 400, 30);
  const PoinsotState& s0 = run.front().state;
  const Eigen::Vector3d u0 = s0.rotation.transpose() * s0.normal;
  const auto curve = polhode_on_ellipsoid(moments, u0, 0.005);
  ASSERT_GT(curve.size(), 100u);
  EXPECT_LT((curve.front() - curve.back()).norm(), 1e-12);
  for (const Eigen::Vector3d& p : curve) {
    ASSERT_NEAR(p.cwiseAbs2().dot(moments), 1.0, 1e-12);
    // Its tangent plane has the run's plane distance: ρ·(Iρ)/|Iρ| = √(2E)/|L|.
    ASSERT_NEAR(1.0 / p.cwiseProduct(moments).norm(), s0.plane_distance, 1e-12);
  }
  for (const auto& [s, L] : run) {
    const Eigen::Vector3d body = s.rotation.transpose() * s.contact;
    double nearest = 1e300;
    for (const Eigen::Vector3d& p : curve) nearest = std::min(nearest, (p - body).norm());
    ASSERT_LT(nearest, 0.01 * s0.plane_distance);
  }
}

// The curve passes through the start's own point ρ0 = I⁻¹u0/√(Σ u_i²/I_i) (docs/physics.md
// §16), about either end of either pole axis.
TEST(Poinsot, PolhodeOnEllipsoidPassesThroughItsStartAtEitherEnd) {
  const Eigen::Vector3d moments(1.0, 2.0, 3.0);
  for (const Eigen::Vector3d& u :
       {Eigen::Vector3d(0.9, 0.3, 0.2), Eigen::Vector3d(-0.9, 0.3, 0.2),
        Eigen::Vector3d(0.2, 0.3, 0.9), Eigen::Vector3d(0.2, 0.3, -0.9)}) {
    const Eigen::Vector3d u0 = u.normalized();
    const Eigen::Vector3d rho0 =
        u0.cwiseQuotient(moments) / std::sqrt(u0.cwiseAbs2().cwiseQuotient(moments).sum());
    const auto curve = polhode_on_ellipsoid(moments, u0, 0.005);
    double nearest = 1e300;
    for (const Eigen::Vector3d& p : curve) nearest = std::min(nearest, (p - rho0).norm());
    EXPECT_LT(nearest, 0.005) << u0.transpose();
  }
}

TEST(Poinsot, RotationFromCornersOfARotatedBox) {
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(2.1, Eigen::Vector3d(-1, 0.3, 0.4).normalized()).matrix();
  const Corners c = R * testing::original_book().body_corners();
  EXPECT_LT((rotation_from_corners(c) - R).norm(), 1e-14);
}

TEST(Poinsot, BadInputsThrow) {
  const Eigen::Matrix3d I3 = Eigen::Matrix3d::Identity();
  EXPECT_THROW(poinsot_state({1, 0, 2}, I3, {1, 0, 0}), std::invalid_argument);
  EXPECT_THROW(poinsot_state({1, 2, 3}, I3, {0, 0, 0}), std::invalid_argument);
  EXPECT_THROW(herpolhode_bounds({1, 2, 3}, 0.0, 1.0), std::invalid_argument);
}

}  // namespace
}  // namespace bookspin::physics
