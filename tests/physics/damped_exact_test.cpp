// The damped exact motion (docs/physics.md §21) against an independent integration of the
// damped Euler equations, and the drag law's stretched time against its closed forms.
#include "physics/damped_exact.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "physics/book.hpp"
#include "physics/shape.hpp"

namespace bookspin::physics {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

struct Body3 {
  std::string name;
  Vector3d moments, omega0;
};

// Three bodies: the book near its intermediate axis (flips), and two others in each case.
std::vector<Body3> bodies() {
  const Vector3d book = Book{}.principal_moments();
  return {
      {"book x spin, tilted", book, Vector3d(0.114819, 0.004, 0.006)},
      {"body (2,1,3) case A", {2.0, 1.0, 3.0}, {0.3, -0.5, 0.7}},
      {"body (3,1,2) case B", {3.0, 1.0, 2.0}, {0.1, 0.9, 0.6}},
  };
}

/// The damped Euler equations in the body frame, written from the torque alone (not from the
/// stretched time): I ω̇ = (I ω) × ω − τ, τ = c I ω (linear) or (r/|L0|)|I ω| I ω (quadratic);
/// Ṙ = R [ω]×. One classical RK4 step of (ω, R).
struct State {
  Vector3d w;
  Matrix3d R;
};
State rk4(const State& y, double h, const Vector3d& I, const Drag& drag, double L0) {
  const auto f = [&](const State& s) {
    const Vector3d L = I.cwiseProduct(s.w);
    double c = drag.law == DragLaw::linear ? drag.rate : drag.rate * L.norm() / L0;
    if (drag.law == DragLaw::none) c = 0.0;
    const Vector3d w_dot = (L.cross(s.w) - c * L).cwiseQuotient(I);
    return State{w_dot, s.R * cross_matrix(s.w)};
  };
  const auto add = [](const State& a, double k, const State& b) {
    return State{a.w + k * b.w, a.R + k * b.R};
  };
  const State k1 = f(y), k2 = f(add(y, 0.5 * h, k1)), k3 = f(add(y, 0.5 * h, k2)),
              k4 = f(add(y, h, k3));
  return State{y.w + (h / 6.0) * (k1.w + 2.0 * k2.w + 2.0 * k3.w + k4.w),
               y.R + (h / 6.0) * (k1.R + 2.0 * k2.R + 2.0 * k3.R + k4.R)};
}

// ω and R of the closed form equal RK4's (steps h and h/2, Richardson-extrapolated) to 1e-10
// relative over two flip periods of the free motion, for both laws and three bodies, with rates
// that take 30–80 % of |L| away over the run.
TEST(DampedExact, EqualsAnIntegrationOfTheDampedEulerEquations) {
  for (const Body3& b : bodies()) {
    const ExactRotation free(b.moments, b.omega0);
    const double span = 2.0 * free.flip_period();
    for (DragLaw law : {DragLaw::linear, DragLaw::quadratic}) {
      for (double share : {0.3, 0.8}) {  // |L| lost over the span
        const double rate =
            law == DragLaw::linear ? -std::log(1.0 - share) / span : share / (1.0 - share) / span;
        const Drag drag{law, rate};
        const DampedExactRotation damped(b.moments, b.omega0, drag);
        const double L0 = b.moments.cwiseProduct(b.omega0).norm();
        const int steps = 20000;
        State coarse{b.omega0, Matrix3d::Identity()}, fine = coarse;
        const double h = span / steps;
        for (int i = 0; i < steps; ++i) {
          coarse = rk4(coarse, h, b.moments, drag, L0);
          fine = rk4(rk4(fine, 0.5 * h, b.moments, drag, L0), 0.5 * h, b.moments, drag, L0);
        }
        const Vector3d w_ref = fine.w + (fine.w - coarse.w) / 15.0;
        const Matrix3d R_ref = fine.R + (fine.R - coarse.R) / 15.0;
        const std::string what =
            b.name + ", " + std::string(to_string(law)) + ", rate " + std::to_string(rate);
        ASSERT_LE((fine.w - coarse.w).norm() / 15.0, 1e-11 * b.omega0.norm()) << what;
        EXPECT_LE((damped.omega_body(span) - w_ref).norm(), 1e-10 * b.omega0.norm()) << what;
        EXPECT_LE((damped.orientation(span) - R_ref).norm(), 1e-10) << what;
        // |L| as the law says, and its direction fixed.
        const double g =
            law == DragLaw::linear ? std::exp(-rate * span) : 1.0 / (1.0 + rate * span);
        EXPECT_NEAR(damped.angular_momentum_world(span).norm(), g * L0, 1e-13 * L0) << what;
        EXPECT_LE((damped.orientation(span) * damped.angular_momentum_body(span) -
                   damped.angular_momentum_world(span))
                      .norm(),
                  1e-12 * L0)
            << what;
        EXPECT_NEAR(g, 1.0 - share, 1e-12) << what;
      }
    }
  }
}

// Without drag, or with a zero rate, every value is the free motion's, bit for bit.
TEST(DampedExact, ZeroRateIsTheFreeMotionBitForBit) {
  for (const Body3& b : bodies()) {
    const ExactRotation free(b.moments, b.omega0);
    for (const Drag drag : {Drag{}, Drag{DragLaw::linear, 0.0}, Drag{DragLaw::quadratic, 0.0}}) {
      const DampedExactRotation damped(b.moments, b.omega0, drag);
      for (double t : {0.0, 0.37, 13.0, 1234.5}) {
        const Vector3d w = damped.omega_body(t), w_free = free.omega_body(t);
        for (int i = 0; i < 3; ++i) EXPECT_EQ(w[i], w_free[i]) << b.name;
        const Matrix3d R = damped.orientation(t), R_free = free.orientation(t);
        for (int i = 0; i < 9; ++i) EXPECT_EQ(R.data()[i], R_free.data()[i]) << b.name;
        EXPECT_EQ(damped.energy(t), free.energy());
        EXPECT_EQ(damped.flip_period_at(t), free.flip_period());
      }
    }
  }
}

// s(t) and its inverse, and the derivatives in the rate against central differences, across
// rates from 1e-12 (the series) to 3 (the closed forms), both laws.
TEST(DampedExact, StretchedTimeAndItsRateDerivatives) {
  for (DragLaw law : {DragLaw::linear, DragLaw::quadratic}) {
    for (double rate : {1e-12, 1e-6, 4e-4, 2e-3, 0.2, 3.0}) {
      for (double t : {0.01, 0.7, 1.3}) {
        const Drag drag{law, rate};
        const double s = stretched_time(drag, t);
        const double expected = law == DragLaw::linear ? (1.0 - std::exp(-rate * t)) / rate
                                                       : std::log(1.0 + rate * t) / rate;
        // The naive forms lose ~1e-16/(rate·t) to cancellation: compared loosely at small rates.
        EXPECT_NEAR(s, expected, std::max(1e-15, 2e-16 / (rate * t)) * t) << rate;
        EXPECT_NEAR(time_of_stretched(drag, s), t, 1e-14 * t) << rate;
        // Five-point central differences, step 2e-4: truncation ~h⁴ t⁵, rounding ~1e-16 t/h.
        const double h = 2e-4;
        const auto difference = [&](double (*f)(const Drag&, double)) {
          const auto at = [&](double k) { return f(Drag{law, rate + k * h}, t); };
          return (8.0 * (at(1) - at(-1)) - (at(2) - at(-2))) / (12.0 * h);
        };
        EXPECT_NEAR(stretched_time_rate_derivative(drag, t), difference(stretched_time),
                    1e-10 * t * t + 1e-12 * t)
            << to_string(law) << " rate " << rate << " t " << t;
        EXPECT_NEAR(drag_decay_rate_derivative(drag, t), difference(drag_decay), 1e-10 * t)
            << to_string(law) << " rate " << rate << " t " << t;
      }
    }
  }
  // The linear law never reaches s = 1/c; the next flip is then never.
  EXPECT_TRUE(std::isinf(time_of_stretched(Drag{DragLaw::linear, 2.0}, 0.5)));
}

// The flips slow down: the k-th sign change of ω about the intermediate axis comes at
// t(s_k), s_k the free motion's; the linear law allows only finitely many.
TEST(DampedExact, FlipsComeAtTheStretchedTimesOfTheFreeOnes) {
  const Body3 b = bodies()[0];
  const ExactRotation free(b.moments, b.omega0);
  const double half = free.flip_period();
  const Drag drag{DragLaw::linear, 0.2 / half};
  const DampedExactRotation damped(b.moments, b.omega0, drag);
  // Axis 2 of the book is body x. The first flip of the damped motion: bisection on ω_x.
  const auto sign_change_after = [&](double from) {
    double lo = from, hi = from;
    const double s0 = std::copysign(1.0, damped.omega_body(from)[0]);
    while (std::copysign(1.0, damped.omega_body(hi)[0]) == s0) hi += 0.01 * half;
    for (int i = 0; i < 80; ++i) {
      const double mid = 0.5 * (lo + hi);
      (std::copysign(1.0, damped.omega_body(mid)[0]) == s0 ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  };
  const double first = sign_change_after(0.0), second = sign_change_after(first + 0.01 * half);
  EXPECT_NEAR(second - first, damped.flip_period_at(first), 1e-9 * half);
  EXPECT_GT(second - first, half);  // slower than the free motion's
  // s never passes 1/c = 5 half periods: at most 5 flips ever.
  EXPECT_TRUE(std::isinf(damped.flip_period_at(time_of_stretched(drag, 4.9 * half))));
}

}  // namespace
}  // namespace bookspin::physics
