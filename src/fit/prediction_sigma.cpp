#include "fit/prediction_sigma.hpp"

#include <algorithm>
#include <cmath>

#include "fit/half_period.hpp"
#include "physics/damped_exact.hpp"

namespace bookspin::fit {
namespace {

/// s: how much later the window is moved to measure its placement's weight.
constexpr double kWindowShift = 0.05;

/// T/2 over the toss's times of the motion from phone-frame `w0` with `moments`, `axes`.
std::optional<double> half_of(const Eigen::Vector3d& moments, const Eigen::Matrix3d& axes,
                              const Eigen::Vector3d& w0, const physics::Drag& drag,
                              const std::vector<double>& tau) {
  const physics::DampedExactRotation motion(moments, axes.transpose() * w0, drag,
                                            physics::ExactParts::omega_only);
  return motion_half_period(motion, axes, tau);
}

Eigen::Vector3d omega0_of(const Parameters& p) {
  return {p.omega0.at(0)[0], p.omega0.at(0)[1], p.omega0.at(0)[2]};
}

}  // namespace

Eigen::Vector3d bias_sigma(const RecordingPart& part) {
  if (part.rest.samples > 0) return part.rest.standard_error.array() + kBiasDrift;
  return part.bias_fitted_sigma.value_or(Eigen::Vector3d::Zero());
}

std::optional<double> prediction_sigma(const TossData& d, const Parameters& fitted,
                                       const Parameters& start, const SolveOptions& options,
                                       const PredictionInputs& inputs, double half) {
  const Eigen::Matrix3d axes = fitted.axes();
  const Eigen::Vector3d moments = fitted.moments();
  const Eigen::Vector3d w0 = omega0_of(fitted);
  const physics::Drag drag{inputs.drag, fitted.omega0.at(0)[3]};
  // The window's residual per component, and ω0's σ from it and the bias's.
  const physics::DampedExactRotation motion(moments, axes.transpose() * w0, drag,
                                            physics::ExactParts::omega_only);
  double sum2 = 0.0;
  int n = 0;
  for (std::size_t i = 0; i < d.tau.size() && d.tau[i] <= options.window; ++i, ++n)
    sum2 += (d.omega[i] - axes * motion.omega_body(d.tau[i])).squaredNorm();
  if (n < 2) return std::nullopt;
  const double scatter2 = sum2 / (3.0 * n);
  double variance = 0.0;
  // Half the spread of T/2 between x − σ and x + σ; nullopt where either has no T/2.
  bool reached = true;
  const auto spread = [&](const std::optional<double>& lo, const std::optional<double>& hi) {
    if (!lo || !hi) return reached = false, 0.0;
    return 0.5 * (*hi - *lo);
  };
  for (int c = 0; c < 3; ++c) {
    const double sigma =
        std::sqrt(4.0 * scatter2 / n + inputs.bias_sigma[c] * inputs.bias_sigma[c]);
    const Eigen::Vector3d step = sigma * Eigen::Vector3d::Unit(c);
    const double s = spread(half_of(moments, axes, w0 - step, drag, d.tau),
                            half_of(moments, axes, w0 + step, drag, d.tau));
    variance += s * s;
  }
  if (inputs.ratio_sigma)
    for (int i = 0; i < 2; ++i) {
      const Eigen::Vector3d step = (*inputs.ratio_sigma)[i] * Eigen::Vector3d::Unit(i);
      if (!(step.norm() > 0)) continue;
      if (!(moments[i] > step[i])) return std::nullopt;  // a moment within σ of zero
      const double s = spread(half_of(moments - step, axes, w0, drag, d.tau),
                              half_of(moments + step, axes, w0, drag, d.tau));
      variance += s * s;
    }
  // The window's placement: the same prediction from the window moved kWindowShift s later
  // (a real release is gradual: its first samples may still be the hand's).
  TossData later = d;
  const auto cut = std::lower_bound(later.tau.begin(), later.tau.end(), kWindowShift);
  const auto dropped = cut - later.tau.begin();
  later.tau.erase(later.tau.begin(), cut);
  later.omega.erase(later.omega.begin(), later.omega.begin() + dropped);
  SolveOptions moved = options;
  moved.window = options.window + kWindowShift;
  Parameters again = start;
  if (later.tau.size() >= 10 && solve({later}, again, moved).usable) {
    const std::optional<double> other =
        half_of(again.moments(), again.axes(), omega0_of(again),
                physics::Drag{inputs.drag, again.omega0.at(0)[3]}, d.tau);
    if (!other) return std::nullopt;
    variance += (*other - half) * (*other - half);
  }
  if (!reached || !std::isfinite(variance)) return std::nullopt;
  return std::sqrt(variance);
}

}  // namespace bookspin::fit
