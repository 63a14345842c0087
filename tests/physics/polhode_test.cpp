// The polhode family against its closed form (docs/physics.md §15): every point on the unit
// sphere and on its energy ellipsoid Σ u_i²/I_i = 2E/|L|², both families present, the
// separatrices through the intermediate axis; and the diagnostics' u = RᵀL/|L| against
// L_body = I·ω_body of the rigid models.
#include "physics/polhode.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>
#include <stdexcept>
#include <vector>

namespace bookspin::physics {
namespace {

const Eigen::Vector3d kBookMoments = Book{}.principal_moments();  // I_y < I_x < I_z

TEST(Polhode, SortedAxesOfTheBook) {
  const auto order = principal_order(kBookMoments);
  EXPECT_EQ(order[0], 1);  // y: smallest
  EXPECT_EQ(order[1], 0);  // x: intermediate
  EXPECT_EQ(order[2], 2);  // z: largest
}

TEST(Polhode, EveryPointLiesOnTheSphereAndOnItsEnergyEllipsoid) {
  for (const Eigen::Vector3d& moments :
       {kBookMoments, Eigen::Vector3d(3.0, 1.0, 2.0), Eigen::Vector3d(1.0, 1.0001, 5.0)}) {
    const auto curves = polhode_family(moments, 5);
    ASSERT_FALSE(curves.empty());
    for (const auto& c : curves) {
      ASSERT_GT(c.points.size(), 50u);
      EXPECT_LT((c.points.front() - c.points.back()).norm(), 1e-12) << "closed";
      for (const auto& u : c.points) {
        ASSERT_NEAR(u.norm(), 1.0, 1e-12);
        ASSERT_NEAR(energy_ratio(moments, u), c.energy_ratio, 1e-12 * c.energy_ratio);
      }
    }
  }
}

TEST(Polhode, BothFamiliesAtLeastEightEnergiesAndTwoSeparatrices) {
  const auto curves = polhode_family(kBookMoments);
  const Eigen::Vector3d inv = kBookMoments.cwiseInverse();
  std::set<double> energies;
  int separatrices = 0, around_smallest = 0, around_largest = 0;
  for (const auto& c : curves) {
    if (c.separatrix) {
      ++separatrices;
      EXPECT_DOUBLE_EQ(c.energy_ratio, inv.x());  // 1/I_mid
      continue;
    }
    energies.insert(c.energy_ratio);
    if (c.pole_axis == 1) {  // around y, the smallest: 1/I_mid < 2E/|L|² < 1/I_min
      ++around_smallest;
      EXPECT_GT(c.energy_ratio, inv.x());
      EXPECT_LT(c.energy_ratio, inv.y());
    } else {
      ASSERT_EQ(c.pole_axis, 2);  // around z, the largest
      ++around_largest;
      EXPECT_LT(c.energy_ratio, inv.x());
      EXPECT_GT(c.energy_ratio, inv.z());
    }
    // A polhode circles its pole: the pole component keeps one sign.
    const double first = c.points.front()[c.pole_axis];
    for (const auto& u : c.points) EXPECT_GT(u[c.pole_axis] * first, 0.0);
  }
  EXPECT_GE(energies.size(), 8u);
  EXPECT_EQ(separatrices, 2);
  EXPECT_GE(around_smallest, 8);  // 4 energies × (+pole, −pole)
  EXPECT_GE(around_largest, 8);
}

TEST(Polhode, SeparatricesPassThroughTheIntermediateAxisAndCrossThere) {
  const auto curves = polhode_family(kBookMoments);
  std::vector<Eigen::Vector3d> tangents;
  for (const auto& c : curves) {
    if (!c.separatrix) continue;
    double nearest_plus = 2, nearest_minus = 2;
    for (std::size_t i = 0; i < c.points.size(); ++i) {
      nearest_plus = std::min(nearest_plus, (c.points[i] - Eigen::Vector3d::UnitX()).norm());
      nearest_minus = std::min(nearest_minus, (c.points[i] + Eigen::Vector3d::UnitX()).norm());
    }
    EXPECT_LT(nearest_plus, 1e-12);
    EXPECT_LT(nearest_minus, 1e-12);
    tangents.push_back((c.points[1] - c.points[0]).normalized());  // the curve starts at +x
  }
  ASSERT_EQ(tangents.size(), 2u);
  // Two different great circles: they cross at ±x at an angle (not tangent).
  EXPECT_LT(std::abs(tangents[0].dot(tangents[1])), 0.99);
}

TEST(Polhode, PointsAreCloseEnoughToDrawEvenNearTheSeparatrix) {
  const double max_step = 0.01;
  // levels = 200: the first energy of each family is 0.25% of the way from the separatrix.
  for (const auto& c : polhode_family(kBookMoments, 200, max_step)) {
    for (std::size_t i = 1; i < c.points.size(); ++i)
      ASSERT_LE((c.points[i] - c.points[i - 1]).norm(), max_step * (1 + 1e-12));
  }
}

TEST(Polhode, RejectsBadMomentsAndSettings) {
  EXPECT_THROW(polhode_family(Eigen::Vector3d(1, 0, 2)), std::invalid_argument);
  EXPECT_THROW(polhode_family(Eigen::Vector3d(1, -1, 2)), std::invalid_argument);
  EXPECT_THROW(polhode_family(Eigen::Vector3d(1, NAN, 2)), std::invalid_argument);
  EXPECT_THROW(polhode_family(kBookMoments, 0), std::invalid_argument);
  EXPECT_THROW(polhode_family(kBookMoments, 4, 0.0), std::invalid_argument);
}

TEST(Polhode, SymmetricBodyKeepsOnlyTheFamilyAroundItsOddAxis) {
  const Eigen::Vector3d moments(2.0, 2.0, 5.0);  // I1 = I2 < I3: circles about z
  const int levels = 4;
  int separatrices = 0, around_z = 0;
  for (const auto& c : polhode_family(moments, levels)) {
    ASSERT_GT(c.points.size(), 50u);
    if (c.separatrix) {
      ++separatrices;
      for (const auto& u : c.points) EXPECT_NEAR(u.z(), 0.0, 1e-12);  // the equator
    } else {
      ++around_z;
      EXPECT_EQ(c.pole_axis, 2);
      for (const auto& u : c.points) EXPECT_NEAR(u.z(), c.points.front().z(), 1e-12);
    }
  }
  EXPECT_EQ(around_z, 2 * levels);  // every level, around +z and −z; none around x or y
  EXPECT_EQ(separatrices, 2);       // the equator, drawn twice
}

// The energies are the documented levels (polhode.hpp, docs/physics.md §15): with
// f = (j + 0.5)/levels, 2E/|L|² = 1/I_mid + f (1/I_min − 1/I_mid) around the smallest axis
// and 1/I_mid − f (1/I_mid − 1/I_max) around the largest, each around +axis and −axis.
TEST(Polhode, EnergiesAreTheDocumentedLevels) {
  for (const Eigen::Vector3d& moments : {kBookMoments, Eigen::Vector3d(3.0, 1.0, 2.0)}) {
    for (int levels : {1, 4, 7}) {
      std::vector<double> smallest_axis[2], largest_axis[2];
      const auto order = principal_order(moments);
      const double inv_min = 1.0 / moments[order[0]], inv_mid = 1.0 / moments[order[1]],
                   inv_max = 1.0 / moments[order[2]];
      for (const auto& c : polhode_family(moments, levels)) {
        if (c.separatrix) continue;
        const int side = c.points.front()[c.pole_axis] > 0.0 ? 0 : 1;
        if (c.pole_axis == order[0])
          smallest_axis[side].push_back(c.energy_ratio);
        else if (c.pole_axis == order[2])
          largest_axis[side].push_back(c.energy_ratio);
        else
          ADD_FAILURE() << "a polhode around the intermediate axis";
      }
      for (int side = 0; side < 2; ++side) {
        ASSERT_EQ(smallest_axis[side].size(), static_cast<std::size_t>(levels));
        ASSERT_EQ(largest_axis[side].size(), static_cast<std::size_t>(levels));
        std::sort(smallest_axis[side].begin(), smallest_axis[side].end());
        std::sort(largest_axis[side].begin(), largest_axis[side].end(), std::greater<>());
        for (int j = 0; j < levels; ++j) {
          const double f = (j + 0.5) / levels;
          EXPECT_NEAR(smallest_axis[side][j], inv_mid + f * (inv_min - inv_mid), 1e-15 * inv_min)
              << "levels " << levels << " j " << j;
          EXPECT_NEAR(largest_axis[side][j], inv_mid - f * (inv_mid - inv_max), 1e-15 * inv_min)
              << "levels " << levels << " j " << j;
        }
      }
    }
  }
}

// u = RᵀL/|L| read from the diagnostics equals I·ω_body/|I·ω_body| on the rigid and exact
// models (where L_body = I·ω_body holds exactly), at a state far from the start.
TEST(Polhode, MomentumDirectionFromDiagnosticsIsTheBodyFrameL) {
  const Book book;
  for (const ModelKind kind :
       {ModelKind::exact, ModelKind::rigid_quaternion, ModelKind::rigid_matrix}) {
    ModelConfig config;
    config.kind = kind;
    config.integrator = kind == ModelKind::exact ? Integrator::euler : Integrator::rk4;
    config.normalize = true;
    auto sim = make_simulator(book, config);
    InitialState initial;
    initial.jiggle = 0.001;
    initial.seed = 2012;
    sim->reset(initial);
    for (int i = 0; i < 6000; ++i) sim->step(1.0 / 60.0);
    const Diagnostics d = sim->diagnostics();
    const Eigen::Vector3d expected =
        book.principal_moments().cwiseProduct(d.omega_body).normalized();
    EXPECT_LT((momentum_direction_body(d) - expected).norm(), 1e-9) << to_string(kind);
    EXPECT_GT(std::abs(expected.y()), 0.05) << "far from the start (u = +x)";
  }
}

}  // namespace
}  // namespace bookspin::physics
