// The exact torque-free solution (docs/physics.md §8) and its simulator.
#include "physics/exact_solution.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "physics/exact_model.hpp"
#include "physics/shape.hpp"

namespace bookspin::physics {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

Vector3d book_moments() { return Book{}.principal_moments(); }

/// ω0 of a pure x spin (the original program's L = (1, 0, 0) start) after adding dL to L.
Vector3d perturbed_x_spin(const Vector3d& dL) {
  const Vector3d I = book_moments();
  return (I.cwiseProduct(Vector3d(0.114819, 0.0, 0.0)) + dL).cwiseQuotient(I);
}

struct Scenario {
  std::string name;
  Vector3d moments;
  Vector3d omega0;
};

// Book (I_y < I_x < I_z) and two other bodies, one sorted by an odd permutation of the
// axes and one by an even one, each in both cases.
std::vector<Scenario> scenarios() {
  return {
      {"book near z", book_moments(), {0.02, 0.01, 0.3}},
      {"book near y", book_moments(), {0.02, 0.3, 0.01}},
      {"book x spin, dL along +z", book_moments(), perturbed_x_spin({0.0, 0.0, 1e-3})},
      {"book x spin, dL along +y", book_moments(), perturbed_x_spin({0.0, 1e-3, 0.0})},
      {"book x spin, dL (1,-1,1)e-3", book_moments(), perturbed_x_spin({1e-3, -1e-3, 1e-3})},
      {"book x spin, dL (-1,1,-1)e-3", book_moments(), perturbed_x_spin({-1e-3, 1e-3, -1e-3})},
      {"body (2,1,3) case A", {2.0, 1.0, 3.0}, {0.3, -0.5, 0.7}},
      {"body (2,1,3) case B", {2.0, 1.0, 3.0}, {-0.6, 0.9, 0.2}},
      {"body (3,1,2) case A", {3.0, 1.0, 2.0}, {0.8, 0.2, -0.3}},
      {"body (3,1,2) case B", {3.0, 1.0, 2.0}, {0.1, 0.9, 0.6}},
      {"axisymmetric (1,1,2)", {1.0, 1.0, 2.0}, {0.3, -0.5, 0.7}},
      {"axisymmetric (1,2,2)", {1.0, 2.0, 2.0}, {0.3, -0.5, 0.7}},
  };
}

/// The case from the sign of L² − 2E·I_mid, computed here independently of ExactRotation.
ExactCase expected_case(const Scenario& s) {
  Vector3d sorted = s.moments;
  std::sort(sorted.data(), sorted.data() + 3);
  const Vector3d L = s.moments.cwiseProduct(s.omega0);
  const double two_E = s.omega0.dot(L);
  const double criterion = L.squaredNorm() - two_E * sorted[1];
  return criterion > 0 ? ExactCase::around_largest : ExactCase::around_smallest;
}

std::vector<double> random_times(double t_max, int count) {
  std::mt19937_64 engine(2024);
  std::uniform_real_distribution<double> uniform(0.0, t_max);
  std::vector<double> times(count);
  for (double& t : times) t = uniform(engine);
  return times;
}

Matrix3d skew(const Vector3d& w) { return cross_matrix(w); }

/// Classical RK4 for Ṙ = R [ω_body(t)]× from R(0) = I with step h, driven by the exact
/// ω_body(t); returns R after each of the (increasing) step counts in `checkpoints`.
std::vector<Matrix3d> integrate_orientation(const ExactRotation& exact, double h,
                                            const std::vector<long>& checkpoints) {
  std::vector<Matrix3d> out;
  Matrix3d R = Matrix3d::Identity();
  Vector3d w_start = exact.omega_body(0.0);
  long step = 0;
  for (long target : checkpoints) {
    for (; step < target; ++step) {
      const double t = step * h;
      const Vector3d w_mid = exact.omega_body(t + 0.5 * h);
      const Vector3d w_end = exact.omega_body(t + h);
      const Matrix3d k1 = R * skew(w_start);
      const Matrix3d k2 = (R + 0.5 * h * k1) * skew(w_mid);
      const Matrix3d k3 = (R + 0.5 * h * k2) * skew(w_mid);
      const Matrix3d k4 = (R + h * k3) * skew(w_end);
      R += (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
      w_start = w_end;
    }
    out.push_back(R);
  }
  return out;
}

TEST(ExactSolution, CaseFollowsTheEnergyMomentumCriterion) {
  int case_a = 0, case_b = 0;
  for (const Scenario& s : scenarios()) {
    const ExactRotation exact(s.moments, s.omega0);
    EXPECT_EQ(exact.motion_case(), expected_case(s)) << s.name;
    (exact.motion_case() == ExactCase::around_largest ? case_a : case_b)++;
  }
  EXPECT_GE(case_a, 4);
  EXPECT_GE(case_b, 4);
}

TEST(ExactSolution, StartsAtOmega0) {
  for (const Scenario& s : scenarios()) {
    const ExactRotation exact(s.moments, s.omega0);
    EXPECT_LE((exact.omega_body(0.0) - s.omega0).norm(), 1e-14 * s.omega0.norm()) << s.name;
    EXPECT_LE((exact.orientation(0.0) - Matrix3d::Identity()).norm(), 1e-14) << s.name;
  }
}

// I ω̇ = (Iω) × ω, with ω̇ from the Jacobi derivative identities, at 50 random times in
// [0, 10 T]; and that ω̇ really is the derivative of ω(t) (fourth-order central difference).
TEST(ExactSolution, SatisfiesEulerEquations) {
  double worst = 0.0;
  for (const Scenario& s : scenarios()) {
    const ExactRotation exact(s.moments, s.omega0);
    const Vector3d& I = s.moments;
    for (double t : random_times(10.0 * exact.period(), 50)) {
      const Vector3d w = exact.omega_body(t), w_dot = exact.omega_dot_body(t);
      const double scale = I.cwiseProduct(w).norm() * w.norm();
      const double residual = (I.cwiseProduct(w_dot) - I.cwiseProduct(w).cross(w)).norm() / scale;
      worst = std::max(worst, residual);
      EXPECT_LE(residual, 1e-12) << s.name << " t = " << t;
      const double h = 1e-4 * exact.period();
      const Vector3d difference = (8.0 * (exact.omega_body(t + h) - exact.omega_body(t - h)) -
                                   (exact.omega_body(t + 2 * h) - exact.omega_body(t - 2 * h))) /
                                  (12.0 * h);
      EXPECT_LE((difference - w_dot).norm(), 1e-9 * exact.lambda() * s.omega0.norm()) << s.name;
    }
  }
  std::printf("[ measured ] max relative Euler residual: %.3g\n", worst);
}

TEST(ExactSolution, ConservesEnergyAndAngularMomentum) {
  for (const Scenario& s : scenarios()) {
    const ExactRotation exact(s.moments, s.omega0);
    for (double t : random_times(10.0 * exact.period(), 50)) {
      const Vector3d w = exact.omega_body(t);
      const Vector3d L_body = s.moments.cwiseProduct(w);
      EXPECT_NEAR(0.5 * w.dot(L_body) / exact.energy(), 1.0, 1e-13) << s.name;
      EXPECT_NEAR(L_body.norm() / exact.angular_momentum_norm(), 1.0, 1e-13) << s.name;
    }
  }
}

// state()'s E and |R(t) I ω(t)| against the invariants from ω0, on 1,000 random bodies (moments
// 0.1 to 3, ω0 in the unit cube, 20 times each up to t = 200), in units of DBL_EPSILON times
// the invariant: within 4 (measured 2.5 and 3.8, the same before and after the per-motion
// constants of docs/physics.md §8, "How the code evaluates ω(t)").
TEST(ExactSolution, StateConservesEnergyAndMomentumWithinFourUlpsOnRandomBodies) {
  std::mt19937_64 engine(2026);
  std::uniform_real_distribution<double> moment(0.1, 3.0), rate(-1.0, 1.0), time(0.0, 200.0);
  const double eps = std::numeric_limits<double>::epsilon();
  double worst_E = 0.0, worst_L = 0.0;
  for (int body = 0; body < 1000; ++body) {
    const Vector3d moments(moment(engine), moment(engine), moment(engine));
    const Vector3d omega0(rate(engine), rate(engine), rate(engine));
    const ExactRotation exact(moments, omega0);
    for (int n = 0; n < 20; ++n) {
      const ExactState s = exact.state(time(engine));
      const double E_ulps = std::abs(s.E - exact.energy()) / (eps * exact.energy());
      const double L_ulps = std::abs(s.L.norm() - exact.angular_momentum_norm()) /
                            (eps * exact.angular_momentum_norm());
      EXPECT_LE(E_ulps, 4.0) << "body " << body << " t = " << s.t;
      EXPECT_LE(L_ulps, 4.0) << "body " << body << " t = " << s.t;
      worst_E = std::max(worst_E, E_ulps);
      worst_L = std::max(worst_L, L_ulps);
    }
  }
  std::printf("[ measured ] worst E %.2f ulps, worst |L| %.2f ulps\n", worst_E, worst_L);
}

// state() (the Landen chain and R_J from per-motion constants) against the BoostReference
// (Boost's jacobi_elliptic and ellint_rj, as evaluated before), on 1,000 random
// bodies, the scenarios above and bodies within 1e-2…1e-12 of the separatrix, t up to 200:
// ω to 2 ulps of its size, E to 3, L to 4; R(t) to 4 ulps of 1 + |ψ| (one ulp of a ψ of a
// few hundred radians turns q by more than one of its own).
TEST(ExactSolution, StateEqualsBoostsEvaluationToAFewUlps) {
  std::mt19937_64 engine(7);
  std::uniform_real_distribution<double> moment(0.1, 3.0), rate(-1.0, 1.0), time(0.0, 200.0),
      exponent(-12.0, -2.0);
  std::vector<Scenario> bodies = scenarios();
  for (int body = 0; body < 1000; ++body)
    bodies.push_back({"random " + std::to_string(body),
                      {moment(engine), moment(engine), moment(engine)},
                      {rate(engine), rate(engine), rate(engine)}});
  for (int body = 0; body < 100; ++body)
    bodies.push_back({"near the separatrix " + std::to_string(body),
                      {2.0, 1.0, 3.0},
                      {std::pow(10.0, exponent(engine)), 1.0, std::pow(10.0, exponent(engine))}});
  const double eps = std::numeric_limits<double>::epsilon();
  double worst[4] = {0.0, 0.0, 0.0, 0.0};  // ω, E, L, q in those units
  for (const Scenario& b : bodies) {
    const ExactRotation exact(b.moments, b.omega0);
    const ExactRotation::BoostReference boost = exact.boost_reference();
    for (int n = 0; n < 20; ++n) {
      const double t = time(engine);
      const ExactState fast = exact.state(t), reference = boost.state(t);
      const double w = reference.omega_body.norm(),
                   turn = 1.0 + std::abs(exact.precession_angle(t));
      const double ulps[4] = {(fast.omega_body - reference.omega_body).norm() / (eps * w),
                              std::abs(fast.E - reference.E) / (eps * reference.E),
                              (fast.L - reference.L).norm() / (eps * reference.L.norm()),
                              std::max((fast.q - reference.q).norm(),
                                       (fast.omega_world - reference.omega_world).norm() / w) /
                                  (eps * turn)};
      EXPECT_LE(ulps[0], 2.0) << b.name << " t = " << t;
      // E summed in long double here (so that an ω component rounded to 0 keeps its share of E,
      // docs/physics.md §8, "How far in time"), in doubles by the reference: 1.2 ulps from the
      // invariant, up to 2.5 from the reference's own rounding.
      EXPECT_LE(ulps[1], 3.0) << b.name << " t = " << t;
      EXPECT_LE(ulps[2], 4.0) << b.name << " t = " << t;
      EXPECT_LE(ulps[3], 4.0) << b.name << " t = " << t;
      for (int i = 0; i < 4; ++i) worst[i] = std::max(worst[i], ulps[i]);
    }
  }
  std::printf("[ measured ] worst ulps against Boost: ω %.2f, E %.2f, L %.2f, q %.2f\n", worst[0],
              worst[1], worst[2], worst[3]);
}

TEST(ExactSolution, OrientationIsARotationCarryingBodyMomentumToWorldMomentum) {
  for (const Scenario& s : scenarios()) {
    const ExactRotation exact(s.moments, s.omega0);
    const Vector3d L = exact.angular_momentum_world();
    for (double t : random_times(10.0 * exact.period(), 50)) {
      const Matrix3d R = exact.orientation(t);
      EXPECT_LE(orthogonality_error(R), 1e-13) << s.name;
      EXPECT_NEAR(R.determinant(), 1.0, 1e-13) << s.name;
      EXPECT_LE((R * exact.angular_momentum_body(t) - L).norm(), 1e-12 * L.norm()) << s.name;
    }
  }
}

// ω(t) has period T, so R(t + T) = R(T)·R(t): a check of the whole-period accumulation of ψ
// far from t = 0. The tolerance grows with t because t itself is a double (ε·t of phase).
TEST(ExactSolution, OrientationAdvancesByTheSameRotationEachPeriod) {
  for (const Scenario& s : scenarios()) {
    const ExactRotation exact(s.moments, s.omega0);
    const double T = exact.period();
    const Matrix3d R_T = exact.orientation(T);
    for (double t : {0.37 * T, 100.37 * T, 1000.9 * T}) {
      const Matrix3d lhs = exact.orientation(t + T), rhs = R_T * exact.orientation(t);
      EXPECT_LE((lhs - rhs).norm(), 1e-13 * (1.0 + t / T)) << s.name << " t = " << t;
    }
  }
}

// The "own error below 1e-10" demonstration (docs/physics.md §8): R(t) against RK4 with steps of
// h and h/2 driven by the exact ω(t), Richardson-extrapolated, over three flip periods.
TEST(ExactSolution, OrientationMatchesFineIntegration) {
  const std::vector<Scenario> all = scenarios();
  double worst = 0.0, worst_reference = 0.0;
  for (int index : {0, 1, 2, 3, 6, 9}) {
    const Scenario& s = all[index];
    const ExactRotation exact(s.moments, s.omega0);
    const double span = 3.0 * exact.flip_period();
    const long steps = 30000;  // coarse run (a multiple of 30); the fine run takes twice as many
    const double h = span / steps;
    std::vector<long> coarse, fine;
    for (long c = 1; c <= 30; ++c) {
      coarse.push_back(c * steps / 30);
      fine.push_back(2 * c * steps / 30);
    }
    const auto R_coarse = integrate_orientation(exact, h, coarse);
    const auto R_fine = integrate_orientation(exact, 0.5 * h, fine);
    for (std::size_t c = 0; c < coarse.size(); ++c) {
      const Matrix3d reference = R_fine[c] + (R_fine[c] - R_coarse[c]) / 15.0;
      const double reference_error = (R_fine[c] - R_coarse[c]).norm() / 15.0;
      const double error = (exact.orientation(coarse[c] * h) - reference).norm();
      worst = std::max(worst, error);
      worst_reference = std::max(worst_reference, reference_error);
      EXPECT_LE(reference_error, 1e-11) << s.name;
      EXPECT_LE(error, 1e-10) << s.name << " t = " << coarse[c] * h;
    }
  }
  std::printf("[ measured ] max |R_exact - R_reference|_F: %.3g (reference error estimate %.3g)\n",
              worst, worst_reference);
}

/// Times of the sign changes of ω_x in [0, t_end], each refined by TOMS 748 to round-off.
std::vector<double> omega_x_zeros(const ExactRotation& exact, double t_end, double scan) {
  auto omega_x = [&](double t) { return exact.omega_body(t).x(); };
  std::vector<double> zeros;
  for (double a = 0.0; a < t_end; a += scan) {
    const double b = a + scan;
    if (omega_x(a) * omega_x(b) >= 0.0) continue;
    boost::uintmax_t iterations = 100;
    const auto bracket = boost::math::tools::toms748_solve(
        omega_x, a, b, boost::math::tools::eps_tolerance<double>(50), iterations);
    zeros.push_back(0.5 * (bracket.first + bracket.second));
  }
  return zeros;
}

/// 2K(k)/λ from docs/physics.md §8 for the book (I1 = I_y, I2 = I_x, I3 = I_z), written out
/// here independently of ExactRotation.
double book_flip_period_formula(const Vector3d& omega0) {
  const Vector3d I = book_moments();
  const double I1 = I.y(), I2 = I.x(), I3 = I.z();
  const double L2 = I.cwiseProduct(omega0).squaredNorm(),
               two_E = omega0.dot(I.cwiseProduct(omega0));
  double k2, lambda;
  if (L2 > two_E * I2) {
    lambda = std::sqrt((I3 - I2) * (L2 - two_E * I1) / (I1 * I2 * I3));
    k2 = (I2 - I1) * (two_E * I3 - L2) / ((I3 - I2) * (L2 - two_E * I1));
  } else {
    lambda = std::sqrt((I2 - I1) * (two_E * I3 - L2) / (I1 * I2 * I3));
    k2 = (I3 - I2) * (L2 - two_E * I1) / ((I2 - I1) * (two_E * I3 - L2));
  }
  return 2.0 * boost::math::ellint_1(std::sqrt(k2)) / lambda;
}

TEST(ExactSolution, FlipPeriodIsTheTimeBetweenSignChangesOfOmegaX) {
  double worst = 0.0;
  for (const Vector3d& dL :
       {Vector3d(0, 0, 1e-3), Vector3d(0, 1e-3, 0), Vector3d(0, 0, -1e-3), Vector3d(0, -1e-3, 0)}) {
    const ExactRotation exact(book_moments(), perturbed_x_spin(dL));
    const double flip = exact.flip_period();
    EXPECT_DOUBLE_EQ(flip, 0.5 * exact.period());
    EXPECT_NEAR(flip / book_flip_period_formula(perturbed_x_spin(dL)), 1.0, 1e-9);
    const std::vector<double> zeros = omega_x_zeros(exact, 4.5 * flip, flip / 64.0);
    ASSERT_GE(zeros.size(), 4u);
    for (std::size_t i = 1; i < zeros.size(); ++i) {
      const double relative = std::abs((zeros[i] - zeros[i - 1]) / flip - 1.0);
      worst = std::max(worst, relative);
      EXPECT_LE(relative, 1e-10);
    }
  }
  std::printf("[ measured ] max |zero spacing / flip_period - 1|: %.3g\n", worst);
}

TEST(ExactSolution, PrincipalAxisSpinIsSteady) {
  const Vector3d I = book_moments();
  for (int axis = 0; axis < 3; ++axis) {
    const Vector3d w0 = 0.2 * Vector3d::Unit(axis);
    const ExactRotation exact(I, w0);
    EXPECT_EQ(exact.motion_case(), ExactCase::steady);
    EXPECT_TRUE(std::isinf(exact.period()));
    EXPECT_TRUE(std::isinf(exact.flip_period()));
    const double t = 17.3;
    EXPECT_EQ(exact.omega_body(t), w0);
    const Matrix3d expected = Eigen::AngleAxisd(0.2 * t, Vector3d::Unit(axis)).toRotationMatrix();
    EXPECT_LE((exact.orientation(t) - expected).norm(), 1e-15);
  }
  const ExactRotation at_rest(I, Vector3d::Zero());
  EXPECT_EQ(at_rest.orientation(5.0), Matrix3d::Identity());
  // A sphere, and ω in the plane of two equal moments, rotate steadily about ω.
  const ExactRotation sphere(Vector3d(2, 2, 2), Vector3d(0.1, 0.2, 0.3));
  const ExactRotation plane(Vector3d(1, 1, 2), Vector3d(0.1, 0.2, 0.0));
  EXPECT_EQ(sphere.motion_case(), ExactCase::steady);
  EXPECT_EQ(plane.motion_case(), ExactCase::steady);
}

// ω in the plane of two equal moments is an eigenvector of I whatever the order of the
// moments along x, y, z: ω stays ω0 (docs/physics.md §8, steady).
TEST(ExactSolution, SymmetricBodyInUnsortedOrderSpinsSteadilyInItsEqualPlane) {
  const struct {
    Vector3d moments, omega0;
  } cases[] = {
      {{2, 1, 2}, {0.3, 0.0, 0.7}},  {{2, 2, 1}, {-0.4, 0.6, 0.0}}, {{1, 2, 1}, {0.5, 0.0, -0.2}},
      {{3, 3, 5}, {0.2, -0.1, 0.0}}, {{5, 3, 3}, {0.0, 0.25, 0.5}}, {{3, 5, 3}, {0.1, 0.0, 0.9}},
  };
  for (const auto& c : cases) {
    const ExactRotation exact(c.moments, c.omega0);
    EXPECT_EQ(exact.motion_case(), ExactCase::steady) << c.moments.transpose();
    for (double t : {0.0, 1.5, 40.0}) {
      EXPECT_EQ(exact.omega_body(t), c.omega0) << c.moments.transpose() << " t " << t;
      const Matrix3d expected =
          Eigen::AngleAxisd(c.omega0.norm() * t, c.omega0.normalized()).toRotationMatrix();
      EXPECT_LE((exact.orientation(t) - expected).norm(), 1e-13) << c.moments.transpose();
    }
  }
}

// Axisymmetric body I1 = I2: ω precesses about axis 3 at Ω = (I3 − I1) ω3 / I1 (Landau §33).
TEST(ExactSolution, AxisymmetricBodyPrecessesAtTheKnownRate) {
  const double I1 = 1.0, I3 = 2.5, w3 = 0.7;
  const Vector3d w0(0.3, 0.0, w3);
  const ExactRotation exact(Vector3d(I1, I1, I3), w0);
  const double rate = (I3 - I1) * w3 / I1;
  EXPECT_NEAR(exact.modulus(), 0.0, 1e-15);
  for (double t : {0.5, 3.0, 40.0}) {
    const Vector3d expected(0.3 * std::cos(rate * t), 0.3 * std::sin(rate * t), w3);
    EXPECT_LE((exact.omega_body(t) - expected).norm(), 1e-14) << t;
  }
}

// I = (1, 5, 9), ω1 = 3 ω3 gives L² = 2E·I2 exactly: k = 1, ω tends to the intermediate axis.
TEST(ExactSolution, SeparatrixApproachesTheIntermediateAxis) {
  const Vector3d I(1.0, 5.0, 9.0), w0(0.75, 0.1, 0.25);
  const ExactRotation exact(I, w0);
  ASSERT_EQ(exact.motion_case(), ExactCase::separatrix);
  EXPECT_TRUE(std::isinf(exact.period()));
  EXPECT_LE((exact.omega_body(0.0) - w0).norm(), 1e-15);
  const Vector3d late = exact.omega_body(60.0 / exact.lambda());
  EXPECT_NEAR(std::abs(late.y()), std::sqrt(2.0 * exact.energy() / I.y()), 1e-12);
  for (double t : {0.5, 2.0, 7.0, 20.0}) {
    const Vector3d w = exact.omega_body(t), w_dot = exact.omega_dot_body(t);
    EXPECT_LE((I.cwiseProduct(w_dot) - I.cwiseProduct(w).cross(w)).norm(), 1e-14);
  }
  const double h = 1e-3;
  const std::vector<long> checkpoints{5000, 10000, 20000};
  const auto coarse = integrate_orientation(exact, h, checkpoints);
  const auto fine = integrate_orientation(exact, 0.5 * h, {10000, 20000, 40000});
  for (std::size_t c = 0; c < checkpoints.size(); ++c) {
    const Matrix3d reference = fine[c] + (fine[c] - coarse[c]) / 15.0;
    EXPECT_LE((exact.orientation(checkpoints[c] * h) - reference).norm(), 1e-10);
  }
}

// On the separatrix cn and dn take their signs from ω0 each: every sign pattern of a
// separatrix start, moments in any order, gives ω(0) = ω0 and satisfies Euler's equations.
// I = (1, 4, 6): L² = 2E·I2 when I1(I2 − I1)ω1² = I3(I3 − I2)ω3², i.e. ω1 = ±2ω3.
TEST(ExactSolution, SeparatrixStartOfEverySignGivesOmegaZero) {
  const Vector3d sorted(1.0, 4.0, 6.0);
  const std::array<std::array<int, 3>, 5> orders{
      {{0, 1, 2}, {2, 0, 1}, {1, 2, 0}, {1, 0, 2}, {0, 2, 1}}};
  int separatrices = 0;
  for (const auto& order : orders)
    for (double s1 : {1.0, -1.0})
      for (double s3 : {1.0, -1.0})
        for (double w2 : {0.0, 0.5, -0.5}) {
          const Vector3d w_sorted(2.0 * s1, w2, 1.0 * s3);
          Vector3d moments, w0;  // body axis order[i] carries sorted axis i
          for (int i = 0; i < 3; ++i) {
            moments[order[i]] = sorted[i];
            w0[order[i]] = w_sorted[i];
          }
          const ExactRotation exact(moments, w0);
          if (exact.motion_case() != ExactCase::separatrix) {
            ADD_FAILURE() << "not on the separatrix: " << w0.transpose();
            continue;
          }
          ++separatrices;
          EXPECT_LE((exact.omega_body(0.0) - w0).norm(), 1e-14 * w0.norm())
              << "moments " << moments.transpose() << " omega0 " << w0.transpose();
          for (double t : {0.3, 2.0}) {
            const Vector3d w = exact.omega_body(t), w_dot = exact.omega_dot_body(t);
            EXPECT_LE((moments.cwiseProduct(w_dot) - moments.cwiseProduct(w).cross(w)).norm(),
                      1e-13);
          }
        }
  EXPECT_EQ(separatrices, 60);
}

TEST(ExactSolution, RejectsInvalidInput) {
  EXPECT_THROW(ExactRotation(Vector3d(1, 0, 2), Vector3d(1, 1, 1)), std::invalid_argument);
  EXPECT_THROW(ExactRotation(Vector3d(1, -2, 2), Vector3d(1, 1, 1)), std::invalid_argument);
  EXPECT_THROW(ExactRotation(Vector3d(1, 2, 3), Vector3d(NAN, 1, 1)), std::invalid_argument);
}

TEST(ExactModel, StartsFromTheJiggledMomentumAndPlacesCornersByR) {
  const Book book;
  const InitialState initial{Vector3d(0.114819, 0.0, 0.0), 1e-3, 7};
  auto sim = make_exact_simulator(book);
  sim->reset(initial);
  const Vector3d I = book.principal_moments();
  const Vector3d L0 = I.cwiseProduct(initial.omega0_body) + jiggle_delta_L(7, 1e-3);
  const ExactRotation exact(I, L0.cwiseQuotient(I));
  EXPECT_LE((sim->diagnostics().omega_body - exact.omega0_body()).norm(), 1e-15);
  EXPECT_LE((sim->diagnostics().L - L0).norm(), 1e-15);
  EXPECT_LE((sim->corners() - book.body_corners()).norm(), 1e-14);
  for (int s = 0; s < 250; ++s) sim->step(0.4);
  EXPECT_LE((sim->corners() - exact.orientation(100.0) * book.body_corners()).norm(), 1e-12);
  EXPECT_TRUE(sim->finite());
}

TEST(ExactModel, DiagnosticsAreConsistentAndCosXLFlipsWithOmegaX) {
  const Book book;
  ExactModel sim(book);
  sim.reset({Vector3d(0.114819, 0.0, 0.0), 1e-3, 3});
  const ExactRotation& exact = sim.rotation();
  const double flip = exact.flip_period(), dt = 0.1;
  const Diagnostics start = sim.diagnostics();
  const std::vector<double> zeros = omega_x_zeros(exact, 3.0 * flip, flip / 64.0);
  std::vector<double> sign_changes;
  double previous_cos = start.cos_axis_L.x();
  while (sim.time() < 3.0 * flip) {
    sim.step(dt);
    const Diagnostics d = sim.diagnostics();
    EXPECT_NEAR(d.energy_total / start.energy_total, 1.0, 1e-13);
    EXPECT_EQ(d.energy_potential, 0.0);
    EXPECT_LE(d.strain_max, 1e-13);
    EXPECT_LE(d.orthogonality_error, 1e-13);
    EXPECT_EQ(d.quaternion_norm, 1.0);
    // cos(R e_x, L) = (Rᵀ L)_x / |L| = I_x ω_x / |L|.
    EXPECT_NEAR(d.cos_axis_L.x(), book.principal_moments().x() * d.omega_body.x() / d.L.norm(),
                1e-12);
    if (d.cos_axis_L.x() * previous_cos < 0.0) sign_changes.push_back(d.t);
    previous_cos = d.cos_axis_L.x();
  }
  ASSERT_EQ(sign_changes.size(), zeros.size());
  ASSERT_GE(zeros.size(), 2u);
  for (std::size_t i = 0; i < zeros.size(); ++i) {
    EXPECT_GE(sign_changes[i] - zeros[i], -1e-9);
    EXPECT_LT(sign_changes[i] - zeros[i], dt + 1e-9);
    if (i > 0) {
      EXPECT_NEAR(zeros[i] - zeros[i - 1], flip, 1e-9 * flip);
    }
  }
}

}  // namespace
}  // namespace bookspin::physics

namespace bookspin::physics {
namespace {

// Built for ω alone (the fit's many trial bodies), the motion is the same ω(t) and flip period,
// and asking it for an orientation is a bug it reports.
TEST(ExactSolutionOmegaOnly, SameOmegaNoOrientation) {
  const Eigen::Vector3d moments(1.0, 2.0, 3.0), w0(0.1, 2.0, 0.2);
  const ExactRotation full(moments, w0);
  const ExactRotation omega_only(moments, w0, ExactParts::omega_only);
  for (double t : {0.0, 0.7, 3.1, 12.5})
    EXPECT_EQ(omega_only.omega_body(t), full.omega_body(t)) << t;
  EXPECT_EQ(omega_only.flip_period(), full.flip_period());
  EXPECT_THROW(omega_only.orientation(1.0), std::logic_error);
}

// The closed form ω = A (cn u, sn u, dn u)ᵀ, u = λt + u0, that the fit differentiates: with
// Boost's Jacobi functions evaluated here it is omega_body() (unsorted moments, both cases),
// each column along one body axis; a steady motion has none.
TEST(ExactSolutionOmegaForm, ReproducesOmegaWithJacobiFunctions) {
  const Eigen::Vector3d moments(2.0, 3.0, 1.0);  // unsorted: the sorting rotation is not I
  for (const Eigen::Vector3d& w0 : {Eigen::Vector3d(0.3, 0.2, 2.0), Eigen::Vector3d(2.0, 0.2, 0.3),
                                    Eigen::Vector3d(-0.4, -1.5, 0.6)}) {
    const ExactRotation exact(moments, w0, ExactParts::omega_only);
    const ExactOmegaForm form = exact.omega_form();
    EXPECT_NEAR(form.kc2, 1.0 - form.k * form.k, 1e-12);
    EXPECT_NEAR(4.0 * form.K / form.lambda, exact.period(), 1e-12 * exact.period());
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ((form.A.col(c).array() != 0.0).count(), 1) << "column " << c;
    for (double t : {0.0, 0.4, 1.7, 9.3}) {
      double cn = 0, dn = 0;
      const double sn = boost::math::jacobi_elliptic(form.k, form.lambda * t + form.u0, &cn, &dn);
      EXPECT_LT((form.A * Eigen::Vector3d(cn, sn, dn) - exact.omega_body(t)).norm(),
                1e-10 * w0.norm())
          << "t " << t << " w0 " << w0.transpose();
    }
  }
  EXPECT_THROW(ExactRotation(moments, Eigen::Vector3d(0.0, 0.0, 2.0)).omega_form(),
               std::logic_error);
}

/// ψ(t) by adaptive Gauss–Kronrod quadrature (long double) of its rate, docs/physics.md §8,
/// ψ̇ = |L| Σ_{i≠r} I_i ω_i² / Σ_{i≠r} I_i² ω_i², from ω(t) alone (the way ψ was tabulated before
/// its closed form): r is the axis ω circles, the smallest in case B, else the largest. Summed
/// over pieces of a twentieth of the flip period (1 time unit on the separatrix), each
/// integrated adaptively.
long double quadrature_psi(const ExactRotation& exact, double t) {
  const Vector3d& I = exact.moments();
  int r = 0;
  for (int i = 0; i < 3; ++i)
    if (exact.motion_case() == ExactCase::around_smallest ? I[i] < I[r] : I[i] > I[r]) r = i;
  auto rate = [&](long double tau) {
    const Vector3d w = exact.omega_body(static_cast<double>(tau));
    long double num = 0.0L, den = 0.0L;
    for (int i = 0; i < 3; ++i) {
      if (i == r) continue;
      num += static_cast<long double>(I[i]) * w[i] * w[i];
      den += static_cast<long double>(I[i]) * I[i] * w[i] * w[i];
    }
    return exact.angular_momentum_norm() * num / den;
  };
  const double flip = exact.flip_period();
  const double piece = std::isfinite(flip) ? 0.05 * flip : 1.0;
  const int pieces = std::max(1, static_cast<int>(std::ceil(t / piece)));
  long double psi = 0.0L;
  using Quadrature = boost::math::quadrature::gauss_kronrod<long double, 31>;
  for (int p = 0; p < pieces; ++p)
    psi += Quadrature::integrate(rate, t * p / pieces, t * (p + 1) / pieces, 8, 1e-15L);
  return psi;
}

// The precession angle's closed form (Carlson's R_J, docs/physics.md §8) equals the
// quadrature of its rate that it replaced, in both cases, for a symmetric body, near the
// separatrix from both sides (k'² down to ~1e-15) and on it. An error δψ turns R(t) by δψ about L,
// ‖δR‖_F = 2√2 |sin(δψ/2)| ≈ 1.41 δψ (R·L_b = L holds separately): so |δψ| ≤ 5e-11 (1 + |ψ|/100)
// keeps the orientation within 1e-9 of the table-based one over the times tried.
TEST(ExactSolutionPrecession, ClosedFormEqualsQuadratureOfItsRate) {
  std::vector<Scenario> all = scenarios();
  const Vector3d I = book_moments();
  for (double e : {1e-5, 1e-8}) {
    all.push_back({"book x spin, dL +z " + std::to_string(e), I, perturbed_x_spin({0.0, 0.0, e})});
    all.push_back({"book x spin, dL +y " + std::to_string(e), I, perturbed_x_spin({0.0, e, 0.0})});
  }
  // k² rounds to 1: the separatrix's form, with ω_y = 0 (u0 infinite: ω stays on axis x).
  all.push_back({"book x spin, dL +z 1e-11", I, perturbed_x_spin({0.0, 0.0, 1e-11})});
  all.push_back({"(2,1,3) near the separatrix, case A", {2.0, 1.0, 3.0}, {1.0, 1e-7, 2e-7}});
  all.push_back({"(2,1,3) near the separatrix, case B", {2.0, 1.0, 3.0}, {1.0, 2e-7, 1e-7}});
  all.push_back({"separatrix (1,5,9)", {1.0, 5.0, 9.0}, {0.75, 0.1, 0.25}});
  all.push_back({"separatrix (1,5,9), ω2 < 0", {1.0, 5.0, 9.0}, {0.75, -0.1, -0.25}});
  int separatrices = 0, near = 0;
  for (const Scenario& s : all) {
    const ExactRotation exact(s.moments, s.omega0);
    separatrices += exact.motion_case() == ExactCase::separatrix;
    near += exact.motion_case() != ExactCase::separatrix && exact.modulus() > 1.0 - 1e-9;
    const double flip = exact.flip_period();
    std::vector<double> times{0.3, 1.7, 9.0, 41.3};
    if (std::isfinite(flip))
      for (double f : {0.25, 0.5, 0.999, 1.0, 1.5, 2.0, 3.37}) times.push_back(f * flip);
    for (double t : times) {
      const double closed = exact.precession_angle(t);
      const long double reference = quadrature_psi(exact, t);
      EXPECT_LE(std::abs(closed - reference), 5e-11 * (1.0 + std::abs(closed) / 100.0))
          << s.name << " t = " << t << " ψ = " << closed;
    }
  }
  EXPECT_EQ(separatrices, 3);
  EXPECT_GE(near, 4);
}

// ψ(t) against mpmath (40 digits: sn by mpmath's ellipfun, ψ by mpmath's quad of the rate
// above, tests/physics/exact_mpmath_reference.py), in both cases, near the separatrix and for
// a symmetric body. Within 1e-12 relative.
TEST(ExactSolutionPrecession, MatchesMpmath) {
  struct Reference {
    const char* name;
    Vector3d moments, omega0;
    std::array<double, 4> psi;  // at the times below
  };
  const std::array<double, 4> times{0.7, 13.1, 104.4, 1234.5};
  const std::vector<Reference> references{
      {"(2, 1, 3) ω0 (0.3, -0.5, 0.7)",
       {2, 1, 3},
       {0.3, -0.5, 0.7},
       {0.9547761543192106283104, 18.98759527322734927457, 153.6889651245655679466,
        1824.700342331433174836}},
      {"(2, 1, 3) ω0 (-0.6, 0.9, 0.2)",
       {2, 1, 3},
       {-0.6, 0.9, 0.2},
       {0.5473104066292216638563, 9.230996808229354761721, 72.3548948800327512906,
        853.7249048608729654396}},
      {"(3, 1, 2) ω0 (0.1, 0.9, 0.6)",
       {3, 1, 2},
       {0.1, 0.9, 0.6},
       {0.5326067376712979766081, 8.722862663157115575133, 68.1127333414625922294,
        806.1796430967546543911}},
      {"(2, 1, 3) ω0 (1e-3, 1, 2e-3)",
       {2, 1, 3},
       {1e-3, 1, 2e-3},
       {0.2363366074901513520383, 5.43273763544137311427, 44.0412691492408742283,
        521.8022462758622096327}},
      {"(2, 1, 3) ω0 (2e-3, 1, 1e-3)",
       {2, 1, 3},
       {2e-3, 1, 1e-3},
       {0.2846859488354704413556, 5.410177520796278398907, 44.09453167984787124052,
        521.7370183022679838299}},
      {"(1, 1, 2) ω0 (0.3, -0.5, 0.7)",
       {1, 1, 2},
       {0.3, -0.5, 0.7},
       {1.061602562167217018665, 19.86713366341506134931, 158.3304392717963667838,
        1872.211947136327727917}},
  };
  double worst = 0.0;
  for (const Reference& r : references) {
    const ExactRotation exact(r.moments, r.omega0);
    for (std::size_t i = 0; i < times.size(); ++i) {
      EXPECT_NEAR(exact.precession_angle(times[i]), r.psi[i], 1e-12 * std::abs(r.psi[i]))
          << r.name << " t = " << times[i];
      worst = std::max(worst, std::abs(exact.precession_angle(times[i]) / r.psi[i] - 1.0));
    }
  }
  std::printf("[ measured ] psi against mpmath: largest relative difference %.2g\n", worst);
}

// ψ where u = λt + u0 is near a quarter period K (|sn u| near 1), after two half periods:
// u = 4.5 K … 6.7 K, 10⁻⁶ K either side of 5K and at it, for k' = 2e-3 and far from the
// separatrix. There S(u) comes from the base point nearest K (docs/physics.md §8, "S from a base
// point"). Against mpmath at 40 digits (tests/physics/exact_mpmath_reference.py --quarter, ψ at
// the double t it prints): within 4 ulps of |ψ|. Closer to the separatrix the comparison is
// limited by k's own rounding in long double (k' = 3e-6: 1.1e-13 relative, before and after alike),
// so NearTheQuarterPeriodEqualsBoostsEvaluation holds those rows against Boost's evaluation.
TEST(ExactSolutionPrecession, MatchesMpmathNearTheQuarterPeriod) {
  struct Reference {
    const char* name;
    Vector3d moments, omega0;
    std::vector<std::array<double, 2>> rows;  // {t, ψ(t)}
  };
  const std::vector<Reference> references{
      {"(2, 1, 3) ω0 (1, 1e-3, 2e-3)",
       {2, 1, 3},
       {1, 1e-3, 2e-3},
       {{42.49702258562066, 46.68523655440161494124},
        {47.41263972369309, 51.60158571568515279311},
        {48.272872722855766, 52.46182330495867964025},
        {48.51865357975939, 52.70760531347905468972},
        {48.629254965366016, 52.81820721118299535987},
        {48.64153171916835, 52.83048402176574998826},
        {48.6415440082112, 52.83049631086543668},
        {48.64155629725404, 52.83050859996511626627},
        {48.76443443666301, 52.95338730825181867028},
        {54.78606543080173, 58.97575606732925131272},
        {69.532916845019, 75.81629250011804012435}}},
      {"(2, 1, 3) ω0 (0.3, -0.5, 0.7)",
       {2, 1, 3},
       {0.3, -0.5, 0.7},
       {{9.65673453957137, 14.26233761028560682211},
        {10.582411485926754, 15.36879827672410354975},
        {10.744404951538947, 15.55073530117389745157},
        {10.790688798856715, 15.60259784723743219378},
        {10.811516530149712, 15.62593095455547212308},
        {10.813828408323234, 15.62852087775938677303},
        {10.8138307225156, 15.62852347027463624373},
        {10.813833036707965, 15.62852606278988372443},
        {10.836972646174486, 15.6544490933118402937},
        {11.97092690545983, 16.99470933026366574421},
        {14.747957744525982, 21.68095027249119904213}}},
  };
  const double eps = std::numeric_limits<double>::epsilon();
  double worst = 0.0;
  for (const Reference& r : references) {
    const ExactRotation exact(r.moments, r.omega0);
    for (const auto& [t, psi] : r.rows) {
      const double ulps = std::abs(exact.precession_angle(t) - psi) / (eps * std::abs(psi));
      EXPECT_LE(ulps, 4.0) << r.name << " t = " << t;
      worst = std::max(worst, ulps);
    }
  }
  std::printf("[ measured ] worst psi near the quarter period: %.2f ulps of |psi|\n", worst);
}

// ψ where u = λt + u0 is near a quarter period K (|sn u| near 1), where S(u) comes from the
// base point nearest K (docs/physics.md §8, "S from a base point") and before the duplication
// of R_J took log₄(1/cn²) steps, against Boost's evaluation of the same motion (the same stored
// k; against mpmath, k' ≈ 3e-6 is limited by k's own rounding: §8): u = K·f for f across two
// half periods after the first (every 1/64, between base points too), 10⁻¹⁵…10⁻³ of K either
// side of 3K, 4K and 5K and at them, k' from 1e-2 to ~1e-8 in both cases and the book's
// jiggled x spin; within 4 ulps of 1 + |ψ|.
TEST(ExactSolutionPrecession, NearTheQuarterPeriodEqualsBoostsEvaluation) {
  std::vector<Scenario> motions;
  for (double small : {1e-2, 1e-4, 1e-6, 1e-8}) {
    motions.push_back(
        {"case A, small " + std::to_string(small), {2.0, 1.0, 3.0}, {small, 1.0, 3.0 * small}});
    motions.push_back(
        {"case B, small " + std::to_string(small), {2.0, 1.0, 3.0}, {3.0 * small, 1.0, small}});
  }
  motions.push_back({"book x spin, jiggle", book_moments(), perturbed_x_spin({1e-6, 1e-6, 1e-6})});
  std::vector<double> fractions;
  for (int i = 2 * 64; i <= 6 * 64; ++i) fractions.push_back(i / 64.0);
  for (double whole : {3.0, 4.0, 5.0})
    for (int p = 3; p <= 15; p += 2)
      for (double side : {-1.0, 1.0}) fractions.push_back(whole + side * std::pow(10.0, -p));
  const double eps = std::numeric_limits<double>::epsilon();
  double worst = 0.0;
  for (const Scenario& m : motions) {
    const ExactRotation exact(m.moments, m.omega0);
    const ExactRotation::BoostReference boost = exact.boost_reference();
    const ExactOmegaForm form = exact.omega_form();
    for (double f : fractions) {
      const double t = (f * form.K - form.u0) / form.lambda;  // u0 < 2K: t > 0
      const double psi = boost.precession_angle(t);
      const double ulps = std::abs(exact.precession_angle(t) - psi) / (eps * (1.0 + std::abs(psi)));
      EXPECT_LE(ulps, 4.0) << m.name << " u = " << f << " K";
      worst = std::max(worst, ulps);
    }
  }
  std::printf(
      "[ measured ] worst psi near the quarter period against Boost: %.2f ulps of 1 + |psi|\n",
      worst);
}

// The model's t = n·dt by steps or by advance(dt, n) in one evaluation lands on the same state.
TEST(ExactModel, AdvanceInOneEvaluationEqualsSteps) {
  InitialState initial;
  initial.omega0_body = {0.114819, 0.0, 0.0};
  initial.jiggle = 1e-3;
  initial.seed = 2012;
  ExactModel full(Book{});
  full.reset(initial);
  ExactModel jump(Book{});
  jump.reset(initial);
  const double dt = 1.0 / 60.0;
  for (int i = 0; i < 6000; ++i) full.step(dt);
  jump.advance(dt, 6000);
  EXPECT_EQ(jump.time(), full.time());
  EXPECT_EQ(jump.orientation(), full.orientation());
  EXPECT_EQ(jump.diagnostics().omega_body, full.diagnostics().omega_body);
}

}  // namespace
}  // namespace bookspin::physics
