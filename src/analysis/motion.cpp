#include "analysis/motion.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

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

double flip_signal(const physics::Simulator& simulator, const Eigen::Vector3d& moments) {
  return simulator.cos_axis_L(intermediate_axis(moments));
}

FlipDetector::FlipDetector(double margin) : margin_(margin) {
  // std::invalid_argument, as physics throws: this file is also compiled into the explorer's
  // WebAssembly, which has src/physics and nothing else (docs/architecture.md).
  if (!(margin >= 0.0 && margin < 1.0))
    throw std::invalid_argument("flip detector margin out of [0, 1)");
}

void FlipDetector::observe(double t, double value) {
  const int s = sign_of(value);
  if (started_ && s != 0 && last_sign_ != 0 && s != last_sign_ && s == -side_) {
    // A zero crossing away from the side: linear interpolation between the two samples
    // around it (the earlier may be 0). It becomes a flip once the margin is passed.
    crossing_ = previous_t_ + (t - previous_t_) * (previous_value_ / (previous_value_ - value));
  }
  if (s != 0) {
    if (side_ == 0) {
      side_ = s;  // the first non-zero sample: the side the run starts on
    } else if (s == -side_ && std::abs(value) > margin_) {
      if (count_++ == 0) first_ = crossing_;
      last_ = crossing_;
      side_ = s;
    }
    last_sign_ = s;
  }
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

double exact_flip_amplitude(const physics::ExactRotation& exact) {
  const Eigen::Vector3d& moments = exact.moments();
  const auto order = physics::principal_order(moments);
  const double I1 = moments[order[0]], I2 = moments[order[1]], I3 = moments[order[2]];
  const double L2 = exact.angular_momentum_norm() * exact.angular_momentum_norm();
  const double E2 = 2.0 * exact.energy();
  switch (exact.motion_case()) {
    case physics::ExactCase::steady:
      return 0.0;
    case physics::ExactCase::separatrix:
      return 1.0;
    case physics::ExactCase::around_largest:
      return std::sqrt(std::clamp((E2 * I3 - L2) * I2 / ((I3 - I2) * L2), 0.0, 1.0));
    case physics::ExactCase::around_smallest:
      return std::sqrt(std::clamp((L2 - E2 * I1) * I2 / ((I2 - I1) * L2), 0.0, 1.0));
  }
  return 0.0;
}

int exact_flip_count(const physics::ExactRotation& exact, int axis, double t_end) {
  if (exact_flip_amplitude(exact) <= FlipDetector::kMargin) return 0;
  return exact_flip_count(exact, exact_first_flip(exact, axis), t_end);
}

int exact_flip_count(const physics::ExactRotation& exact, std::optional<double> first,
                     double t_end) {
  if (exact_flip_amplitude(exact) <= FlipDetector::kMargin) return 0;
  if (!first || t_end < *first) return 0;
  return 1 + static_cast<int>(std::floor((t_end - *first) / exact.flip_period()));
}

double rotation_angle_between(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  const double chord = (a - b).norm() / std::sqrt(8.0);
  return 2.0 * std::asin(std::min(1.0, chord));
}

}  // namespace bookspin::analysis
