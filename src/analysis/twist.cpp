#include "analysis/twist.hpp"

#include <array>
#include <cmath>
#include <numbers>

#include "physics/body.hpp"

namespace bookspin::analysis {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

/// Two unit vectors that make (a, b, c) a right-handed orthonormal frame.
void normal_pair(const Eigen::Vector3d& a, Eigen::Vector3d& b, Eigen::Vector3d& c) {
  const Eigen::Vector3d seed =
      std::abs(a.x()) < 0.6 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  b = (seed - seed.dot(a) * a).normalized();
  c = a.cross(b);
}

/// `angle` moved by whole turns to within π of `near`.
double unwrap_near(double angle, double near) {
  return angle + kTwoPi * std::round((near - angle) / kTwoPi);
}

/// Cubic Hermite interpolation on [t0, t1] of a function with values y and slopes d.
double hermite(double t0, double y0, double d0, double t1, double y1, double d1, double t) {
  const double h = t1 - t0, s = (t - t0) / h;
  const double s2 = s * s, s3 = s2 * s;
  return (2 * s3 - 3 * s2 + 1) * y0 + (s3 - 2 * s2 + s) * h * d0 + (-2 * s3 + 3 * s2) * y1 +
         (s3 - s2) * h * d1;
}

/// (1 − cos ϑ)·φ̇ about `pole` for the unit momentum direction m and ω (body frame): with
/// a·m = cos ϑ and φ̇ = ((a·m)(m·ω) − a·ω)/(1 − (a·m)²), one factor 1 − a·m cancels
/// (docs/physics.md §19), so the integrand stays finite at the pole.
double solid_angle_rate(const Eigen::Vector3d& pole, const Eigen::Vector3d& m,
                        const Eigen::Vector3d& omega) {
  const double c = pole.dot(m);
  return (c * m.dot(omega) - pole.dot(omega)) / (1.0 + c);
}

}  // namespace

double wrap_angle(double angle) {
  double wrapped = std::remainder(angle, kTwoPi);  // in [−π, π]
  if (wrapped <= -std::numbers::pi) wrapped += kTwoPi;
  return wrapped;
}

std::optional<Eigen::Vector3d> twist_pole(const physics::ExactRotation& exact) {
  const physics::ExactCase motion = exact.motion_case();
  if (motion != physics::ExactCase::around_largest && motion != physics::ExactCase::around_smallest)
    return std::nullopt;
  const std::array<int, 3> order = physics::principal_order(exact.moments());
  const int axis = motion == physics::ExactCase::around_largest ? order[2] : order[0];
  const double L_axis = exact.angular_momentum_body(0.0)[axis];
  Eigen::Vector3d pole = Eigen::Vector3d::Zero();
  pole[axis] = L_axis < 0.0 ? -1.0 : 1.0;
  return pole;
}

std::optional<double> polhode_solid_angle(const physics::ExactRotation& exact) {
  const auto pole = twist_pole(exact);
  const double T = exact.period();
  if (!pole || !std::isfinite(T)) return std::nullopt;
  const double L_norm = exact.angular_momentum_norm();
  auto rate = [&](double t) {
    return solid_angle_rate(*pole, exact.angular_momentum_body(t) / L_norm, exact.omega_body(t));
  };
  // Trapezoid sums over one period with n and 2n points: the 2n sum reuses the n points.
  int n = 64;
  double sum = 0.0;
  for (int j = 0; j < n; ++j) sum += rate(T * j / n);
  double previous = T * sum / n;
  for (; n < (1 << 22); n *= 2) {
    for (int j = 0; j < n; ++j) sum += rate(T * (2 * j + 1) / (2.0 * n));
    const double next = T * sum / (2 * n);
    if (std::abs(next - previous) <= 1e-13) return next;
    previous = next;
  }
  return previous;
}

std::optional<double> twist_exact(const physics::ExactRotation& exact) {
  const auto omega = polhode_solid_angle(exact);
  if (!omega) return std::nullopt;
  const double T = exact.period();
  return wrap_angle(2.0 * exact.energy() * T / exact.angular_momentum_norm() - *omega);
}

TwistMeter::TwistMeter(const Eigen::Vector3d& pole) : pole_(pole.normalized()) {
  normal_pair(pole_, b_, c_);
}

void TwistMeter::observe(double t, const Eigen::Matrix3d& R, const Eigen::Vector3d& omega_body,
                         const Eigen::Vector3d& L_world) {
  if (done_) return;
  if (!started_) {
    l_ = L_world.normalized();
    normal_pair(l_, g1_, g2_);
  }
  const Eigen::Vector3d m = R.transpose() * L_world.normalized();
  const double c = pole_.dot(m);
  if (!(c > 0.0)) {  // left the pole's hemisphere (or NaN): no period about the pole
    done_ = true;
    return;
  }
  const double m_omega = m.dot(omega_body);
  const double phi_dot = (c * m_omega - pole_.dot(omega_body)) / (1.0 - c * c);
  const Eigen::Vector3d u = R * pole_.cross(m).normalized();
  Sample s{t, std::atan2(m.dot(c_), m.dot(b_)), phi_dot, std::atan2(u.dot(g2_), u.dot(g1_)),
           m_omega + phi_dot * c};
  if (!started_) {
    started_ = true;
    first_ = previous_ = s;
    return;
  }
  s.phi = unwrap_near(s.phi, previous_.phi);
  s.theta = unwrap_near(s.theta, previous_.theta);
  const double target = first_.phi + (s.phi >= first_.phi ? kTwoPi : -kTwoPi);
  if (std::abs(s.phi - first_.phi) >= kTwoPi) {
    // φ(t*) = target between the two samples: bisection on the Hermite cubic, then θ(t*).
    double lo = previous_.t, hi = s.t;
    const bool rising = target > first_.phi;
    for (int i = 0; i < 200 && hi - lo > 1e-15 * std::abs(hi); ++i) {
      const double mid = 0.5 * (lo + hi);
      const double phi =
          hermite(previous_.t, previous_.phi, previous_.phi_dot, s.t, s.phi, s.phi_dot, mid);
      ((phi < target) == rising ? lo : hi) = mid;
    }
    const double t_end = 0.5 * (lo + hi);
    const double theta = hermite(previous_.t, previous_.theta, previous_.theta_dot, s.t, s.theta,
                                 s.theta_dot, t_end);
    twist_ = wrap_angle(theta - first_.theta);
    done_ = true;
    return;
  }
  previous_ = s;
}

}  // namespace bookspin::analysis
