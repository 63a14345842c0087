// The exact model's rows against an independent evaluation of the Jacobi solution
// (docs/physics.md §8, §10): its state at row n is the solution at t = n·dt.
#include "physics/exact_model.hpp"

#include <gtest/gtest.h>

#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>
#include <cmath>

#include "physics/shape.hpp"

namespace bookspin::physics {
namespace {

using Real = long double;

/// ω(t) of the free book written out from Landau & Lifshitz, Mechanics §37, in the frame
/// (e1, e2, e3) = (y, x, −z) of the body: moments sorted I1 < I2 < I3 by a rotation (det +1),
/// so that Euler's equations keep their form. Everything in long double: near the
/// separatrix k'² is small and the period depends on it logarithmically.
class LandauLifshitzOmega {
 public:
  LandauLifshitzOmega(const Eigen::Vector3d& moments, const Eigen::Vector3d& omega0) {
    I1 = moments.y(), I2 = moments.x(), I3 = moments.z();
    const Real w1 = omega0.y(), w2 = omega0.x(), w3 = -omega0.z();
    // 2E·I_j − L² = Σ_i I_i ω_i² (I_j − I_i): sums without the vanishing i = j term.
    const Real a1 = I2 * w2 * w2 * (I2 - I1) + I3 * w3 * w3 * (I3 - I1);  // L² − 2E·I1
    const Real a3 = I1 * w1 * w1 * (I3 - I1) + I2 * w2 * w2 * (I3 - I2);  // 2E·I3 − L²
    const Real d2 = I1 * w1 * w1 * (I1 - I2) + I3 * w3 * w3 * (I3 - I2);  // L² − 2E·I2
    around_largest = d2 > 0;
    if (around_largest) {  // ω1 ∝ cn, ω2 ∝ sn, ω3 ∝ dn
      k2 = (I2 - I1) * a3 / ((I3 - I2) * a1);
      kc2 = (I3 - I1) * d2 / ((I3 - I2) * a1);
      lambda = std::sqrt((I3 - I2) * a1 / (I1 * I2 * I3));
      A = {std::sqrt(a3 / (I1 * (I3 - I1))), std::sqrt(a3 / (I2 * (I3 - I2))),
           std::sqrt(a1 / (I3 * (I3 - I1)))};
      // Euler's equations need s1 = s2·s3; dn > 0 fixes s3, and u0 absorbs s1 = +1.
      s = {1.0L, w3 < 0 ? -1.0L : 1.0L, w3 < 0 ? -1.0L : 1.0L};
      u0 = boost::math::ellint_1(std::sqrt(k2), std::atan2(w2 / (s[1] * A[1]), w1 / A[0]));
    } else {  // ω1 ∝ dn, ω2 ∝ sn, ω3 ∝ cn
      k2 = (I3 - I2) * a1 / ((I2 - I1) * a3);
      kc2 = (I3 - I1) * -d2 / ((I2 - I1) * a3);
      lambda = std::sqrt((I2 - I1) * a3 / (I1 * I2 * I3));
      A = {std::sqrt(a3 / (I1 * (I3 - I1))), std::sqrt(a1 / (I2 * (I2 - I1))),
           std::sqrt(a1 / (I3 * (I3 - I1)))};
      s = {w1 < 0 ? -1.0L : 1.0L, w1 < 0 ? -1.0L : 1.0L, 1.0L};
      u0 = boost::math::ellint_1(std::sqrt(k2), std::atan2(w2 / (s[1] * A[1]), w3 / A[2]));
    }
    K = boost::math::ellint_1(std::sqrt(k2));
  }

  /// Body-frame ω (x, y, z) at time t.
  Eigen::Vector3d operator()(Real t) const {
    Real u = lambda * t + u0;
    u -= 4.0L * K * std::floor(u / (4.0L * K));  // one period: Boost is accurate there
    Real cn = 0, dn = 0;
    const Real k = std::sqrt(k2);
    const Real sn = boost::math::jacobi_elliptic(k, u, &cn, &dn);
    dn = std::sqrt(kc2 + k2 * cn * cn);  // dn² = k'² + k² cn², no cancellation near u = K
    const Real w1 = s[0] * A[0] * (around_largest ? cn : dn);
    const Real w2 = s[1] * A[1] * sn;
    const Real w3 = s[2] * A[2] * (around_largest ? dn : cn);
    return {static_cast<double>(w2), static_cast<double>(w1), static_cast<double>(-w3)};
  }

 private:
  Real I1, I2, I3, k2, kc2, lambda, u0, K;
  bool around_largest;
  std::array<Real, 3> A, s;
};

// The scene exact-unstable-x's motion, rows of 30 steps of 1/60 up to t = 2300: every row's
// ω matches the closed form at t = n·dt to 1e-12 of |ω|. A running sum of dt would put the
// state 1.7e-9 time units off the row's t by then.
TEST(ExactModel, OmegaAtEveryRowIsTheJacobiSolutionAtNTimesDt) {
  const physics::Book book;
  const physics::InitialState initial{Eigen::Vector3d(0.114819, 0.0, 0.0), 1e-3, 2012};
  const Eigen::Vector3d L0 = physics::initial_angular_momentum(book, initial);
  const Eigen::Vector3d moments = book.principal_moments();
  const LandauLifshitzOmega closed_form(moments, L0.cwiseQuotient(moments));
  physics::ExactModel sim(book);
  sim.reset(initial);
  const double dt = 1.0 / 60.0;
  const long steps_per_row = 30, rows = std::lround(2300.0 / dt) / steps_per_row;
  double worst = 0.0;
  long worst_row = 0;
  for (long row = 1; row <= rows; ++row) {
    for (long s = 0; s < steps_per_row; ++s) sim.step(dt);
    const long n = row * steps_per_row;
    const Eigen::Vector3d expected = closed_form(static_cast<Real>(n) * dt);
    const double error = (sim.diagnostics().omega_body - expected).norm() / expected.norm();
    if (error > worst) worst = error, worst_row = row;
    ASSERT_EQ(sim.diagnostics().t, n * dt) << "row " << row;
  }
  EXPECT_LT(worst, 1e-12) << "worst at t = " << worst_row * steps_per_row * dt;
}

// The closed form written above starts at ω0 and satisfies Euler's equations (checked by
// central differences), so the comparison above is against the true motion.
TEST(ExactModel, IndependentClosedFormSolvesEulerEquations) {
  const physics::Book book;
  const physics::InitialState initial{Eigen::Vector3d(0.114819, 0.0, 0.0), 1e-3, 2012};
  const Eigen::Vector3d I = book.principal_moments();
  const Eigen::Vector3d omega0 = physics::initial_angular_momentum(book, initial).cwiseQuotient(I);
  for (const Eigen::Vector3d& w0 :
       {omega0, Eigen::Vector3d(0.02, 0.3, 0.01), Eigen::Vector3d(0.02, 0.01, 0.3)}) {
    const LandauLifshitzOmega omega(I, w0);
    EXPECT_LT((omega(0.0L) - w0).norm(), 1e-15 * w0.norm());
    for (double t : {3.0, 170.0, 1234.5}) {
      const double h = 1e-3;
      const Eigen::Vector3d w = omega(t);
      const Eigen::Vector3d w_dot = (omega(t + h) - omega(t - h)) / (2.0 * h);
      const Eigen::Vector3d euler = I.cwiseInverse().cwiseProduct((I.cwiseProduct(w)).cross(w));
      EXPECT_LT((w_dot - euler).norm(), 1e-8 * w.norm()) << "t = " << t;
    }
  }
}

}  // namespace
}  // namespace bookspin::physics
