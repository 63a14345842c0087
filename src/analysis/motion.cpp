#include "analysis/motion.hpp"

#include <algorithm>
#include <cmath>

#include "physics/body.hpp"

namespace bookspin::analysis {

namespace {

int sign_of(double x) { return (x > 0.0) - (x < 0.0); }

}  // namespace

int intermediate_axis(const Eigen::Vector3d& moments) {
  return physics::principal_order(moments)[1];
}

double flip_signal(const physics::Diagnostics& diagnostics, const Eigen::Vector3d& moments) {
  return diagnostics.cos_axis_L[intermediate_axis(moments)];
}

void FlipDetector::observe(double t, double value) {
  const int s = sign_of(value);
  if (started_ && s != 0) {
    if (last_sign_ != 0 && s != last_sign_) {
      // Linear interpolation between the two samples around the zero (the earlier may be 0).
      const double t_flip =
          previous_t_ + (t - previous_t_) * (previous_value_ / (previous_value_ - value));
      if (count_++ == 0) first_ = t_flip;
      last_ = t_flip;
    }
  }
  if (s != 0) last_sign_ = s;
  previous_t_ = t;
  previous_value_ = value;
  started_ = true;
}

std::optional<double> FlipDetector::first_flip() const {
  if (count_ < 1) return std::nullopt;
  return first_;
}

std::optional<double> FlipDetector::flip_period() const {
  if (count_ < 2) return std::nullopt;
  return (last_ - first_) / (count_ - 1);
}

std::optional<double> exact_first_flip(const physics::ExactRotation& exact, int axis) {
  const double half = exact.flip_period();
  if (!std::isfinite(half) || half <= 0.0) return std::nullopt;
  const auto f = [&](double t) { return exact.omega_body(t)[axis]; };
  constexpr int kSamples = 64;
  const double h = half / kSamples;
  double t0 = 0.0;
  int reference = sign_of(f(0.0));  // 0 when it starts on a zero: the sign just after counts
  for (int j = 1; j <= 2 * kSamples + 1; ++j) {
    const double t1 = j * h;
    const int s = sign_of(f(t1));
    if (reference == 0) {
      reference = s;
    } else if (s == 0) {
      return t1;
    } else if (s != reference) {
      double a = t0, b = t1;
      for (int it = 0; it < 200 && b - a > 0.0; ++it) {
        const double m = 0.5 * (a + b);
        if (m <= a || m >= b) break;
        (sign_of(f(m)) == reference ? a : b) = m;
      }
      return 0.5 * (a + b);
    }
    t0 = t1;
  }
  return std::nullopt;
}

double rotation_angle_between(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  const double chord = (a - b).norm() / std::sqrt(8.0);
  return 2.0 * std::asin(std::min(1.0, chord));
}

}  // namespace bookspin::analysis
