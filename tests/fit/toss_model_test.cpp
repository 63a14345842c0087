// The fit's model of a toss against independent numbers: its double-precision Jacobi functions
// (AGM) against Boost.Math's in long double, and its analytic ∂ω/∂θ against central differences
// of physics::ExactRotation's ω itself (Boost, long double) with a step of its own.
#include "fit/toss_model.hpp"

#include <gtest/gtest.h>

#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_2.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>
#include <boost/math/special_functions/jacobi_zeta.hpp>
#include <cmath>

#include "fit/elliptic.hpp"
#include "physics/damped_exact.hpp"

namespace bookspin::fit {
namespace {

TEST(JacobiAgm, AgreesWithBoostInLongDouble) {
  for (const long double k : {0.0L, 0.3L, 0.9L, 0.999999L}) {
    const long double kc2 = (1.0L - k) * (1.0L + k);
    const JacobiAgm agm(static_cast<double>(k), static_cast<double>(kc2));
    const long double K = boost::math::ellint_1(k);
    EXPECT_NEAR(agm.K(), K, 1e-14 * K) << "k " << k;
    EXPECT_NEAR(agm.E_over_K(), boost::math::ellint_2(k) / K, 1e-14) << "k " << k;
    for (long double u = -23.0L; u <= 23.0L; u += 0.37L) {
      long double cn = 0, dn = 0;
      const long double sn = boost::math::jacobi_elliptic(k, u, &cn, &dn);
      const JacobiAgm::Values v = agm(static_cast<double>(u));
      EXPECT_NEAR(v.sn, sn, 1e-13) << "k " << k << " u " << u;
      EXPECT_NEAR(v.cn, cn, 1e-13) << "k " << k << " u " << u;
      EXPECT_NEAR(v.dn, dn, 1e-13) << "k " << k << " u " << u;
      // Z(u) = E(am u) − (E/K) F(am u); Boost's jacobi_zeta takes the amplitude, Z has period π
      // in it.
      const long double zeta = boost::math::jacobi_zeta(k, std::atan2(sn, cn));
      EXPECT_NEAR(v.zeta, zeta, 1e-13) << "k " << k << " u " << u;
    }
  }
}

TEST(JacobiAgm, RefusesAModulusOutsideZeroToOne) {
  EXPECT_THROW(JacobiAgm(1.0, 0.0), std::invalid_argument);
  EXPECT_THROW(JacobiAgm(-0.1, 0.99), std::invalid_argument);
  EXPECT_THROW(JacobiAgm(std::nan(""), 0.5), std::invalid_argument);
  EXPECT_THROW(JacobiAgm(0.1, 1.1), std::invalid_argument);
  // A tiny modulus whose k'², formed from the invariants, rounds just above 1 is k'² = 1.
  const JacobiAgm tiny(1e-9, std::nextafter(1.0, 2.0));
  EXPECT_NEAR(tiny(0.7).sn, std::sin(0.7), 1e-15);
  EXPECT_NEAR(tiny(0.7).dn, 1.0, 1e-15);
}

/// θ = (aa, log ratios, ω0 and the drag rate) of a toss, and its drag law.
struct Theta {
  double aa[3], p[2], w[4];
  physics::DragLaw law = physics::DragLaw::none;
};

/// ω of physics::DampedExactRotation itself at θ (phone frame; ExactRotation's without drag),
/// for the reference differences.
Eigen::Vector3d reference_omega(const Eigen::Matrix3d& R0, const Theta& t, double tau) {
  const Eigen::Matrix3d axes = R0 * rotation_from_angle_axis(t.aa);
  const physics::DampedExactRotation exact(
      Eigen::Vector3d(std::exp(t.p[0]), std::exp(t.p[1]), 1.0),
      axes.transpose() * Eigen::Vector3d(t.w[0], t.w[1], t.w[2]),
      physics::Drag{t.law, t.law == physics::DragLaw::none ? 0.0 : t.w[3]},
      physics::ExactParts::omega_only);
  return axes * exact.omega_body(tau);
}

/// The model's ω and ∂ω/∂θ at τ over a flight against ExactRotation's ω and its central
/// differences (step 1e-5 relative, not the model's 1e-6).
void expect_derivatives(const Eigen::Matrix3d& R0, const Theta& theta, bool closed_form) {
  const TossModel model(R0, theta.aa, theta.p, theta.w, theta.law, true);
  EXPECT_EQ(model.closed_form(), closed_form);
  for (double tau = 0.0; tau <= 1.5; tau += 0.0625) {
    TossModel::Jacobian J;
    const Eigen::Vector3d w = model.omega(tau, &J);
    const Eigen::Vector3d reference = reference_omega(R0, theta, tau);
    EXPECT_LT((w - reference).norm(), 1e-11 * reference.norm()) << "τ " << tau;
    for (int q = 0; q < TossModel::kParameters; ++q) {
      Theta up = theta, down = theta;
      double* u = q < 3 ? &up.aa[q] : q < 5 ? &up.p[q - 3] : &up.w[q - 5];
      double* d = q < 3 ? &down.aa[q] : q < 5 ? &down.p[q - 3] : &down.w[q - 5];
      // The rate of a law-free toss: no column to check but zero.
      const double h = 1e-5 * std::max(1.0, std::abs(*u));
      *u += h;
      *d -= h;
      const Eigen::Vector3d difference =
          (reference_omega(R0, up, tau) - reference_omega(R0, down, tau)) / (2 * h);
      EXPECT_LT((J.col(q) - difference).norm(), 1e-6 * (1.0 + difference.norm()))
          << "τ " << tau << " parameter " << q << ": " << J.col(q).transpose() << " against "
          << difference.transpose();
    }
  }
}

const Eigen::Matrix3d kTurned =
    Eigen::AngleAxisd(0.35, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();

TEST(TossModel, DerivativesOfAFlipAroundTheLargestAxis) {
  // Moments 1 : 1.6 : 2.3 (a phone on a book), ω mostly about the intermediate axis (case A).
  expect_derivatives(
      kTurned,
      {{0.01, -0.02, 0.015}, {std::log(1 / 2.3), std::log(1.6 / 2.3)}, {0.5, 12.0, 2.5, 0.0}},
      true);
}

TEST(TossModel, DerivativesOfAFlipAroundTheSmallestAxis) {
  expect_derivatives(
      kTurned,
      {{-0.02, 0.01, 0.0}, {std::log(1 / 2.3), std::log(1.6 / 2.3)}, {2.5, 12.0, 0.4, 0.0}}, true);
}

TEST(TossModel, DerivativesOfARacquetAndOfAWobble) {
  // Two nearly equal moments (0.9, 1); then a spin about the largest axis wobbling 3°.
  expect_derivatives(
      kTurned, {{0.0, 0.0, 0.0}, {std::log(0.1), std::log(0.9)}, {0.4, 14.0, 0.8, 0.0}}, true);
  expect_derivatives(Eigen::Matrix3d::Identity(),
                     {{0.0, 0.0, 0.0}, {std::log(0.4), std::log(0.7)}, {0.3, 0.4, 10.0, 0.0}},
                     true);
}

TEST(TossModel, DerivativesWhereThePhaseWrapsAround) {
  // sn(u0) = 0 with cn(u0) < 0: u0 = 2K, the end of its range (−2K, 2K], so a step in the
  // intermediate component lands u0 near −2K on one side.
  expect_derivatives(Eigen::Matrix3d::Identity(),
                     {{0.0, 0.0, 0.0}, {std::log(0.4), std::log(0.7)}, {-2.5, 0.0, 12.0, 0.0}},
                     true);
}

TEST(TossModel, ASteadySpinHasNoClosedFormAndDifferencesTheMotion) {
  // ω0 along a principal axis: steady at θ, not within the steps.
  const Eigen::Matrix3d R0 = Eigen::Matrix3d::Identity();
  const Theta theta{{0.0, 0.0, 0.0}, {std::log(0.4), std::log(0.7)}, {0.0, 0.0, 10.0, 0.0}};
  const TossModel model(R0, theta.aa, theta.p, theta.w, theta.law, true);
  EXPECT_FALSE(model.closed_form());
  TossModel::Jacobian J;
  EXPECT_LT((model.omega(0.7, &J) - Eigen::Vector3d(0, 0, 10)).norm(), 1e-12);
  // d ω / d ω0_z at a steady spin about z is e_z exactly.
  EXPECT_LT((J.col(7) - Eigen::Vector3d::UnitZ()).norm(), 1e-6);
}

// Under drag (docs/physics.md §21), both laws: ω and every column, the rate's analytic one
// included, against DampedExactRotation's ω and its differences; a steady spin under drag too.
TEST(TossModel, DerivativesUnderDrag) {
  for (physics::DragLaw law : {physics::DragLaw::linear, physics::DragLaw::quadratic}) {
    expect_derivatives(kTurned,
                       {{0.01, -0.02, 0.015},
                        {std::log(1 / 2.3), std::log(1.6 / 2.3)},
                        {0.5, 12.0, 2.5, 0.2},
                        law},
                       true);
    expect_derivatives(
        kTurned, {{0.0, 0.0, 0.0}, {std::log(0.1), std::log(0.9)}, {2.5, 12.0, 0.4, 0.05}, law},
        true);
    expect_derivatives(
        Eigen::Matrix3d::Identity(),
        {{0.0, 0.0, 0.0}, {std::log(0.4), std::log(0.7)}, {0.0, 0.0, 10.0, 0.3}, law}, false);
  }
}

}  // namespace
}  // namespace bookspin::fit
