#include "fit/half_period.hpp"

#include <cmath>

namespace bookspin::fit {
namespace {

/// The mean spacing of the sign changes of the component along `axis` (phone frame) of
/// `omega(τ)` sampled at `tau` (s): the estimator half_period_measured uses, applied to a
/// model; nullopt with fewer than two sign changes.
template <typename OmegaAt>
std::optional<double> mean_flip_spacing(const std::vector<double>& tau, const Eigen::Vector3d& axis,
                                        OmegaAt omega) {
  std::vector<double> along(tau.size());
  double peak = 0.0;
  for (std::size_t i = 0; i < tau.size(); ++i) {
    along[i] = axis.dot(omega(tau[i]));
    peak = std::max(peak, std::abs(along[i]));
  }
  const std::vector<double> crossings = sign_changes(tau, along, 0.2 * peak);
  if (crossings.size() < 2) return std::nullopt;
  return (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
}

}  // namespace

std::vector<double> sign_changes(const std::vector<double>& t, const std::vector<double>& values,
                                 double band) {
  std::vector<double> crossings;
  int sign = 0;
  int last_index = -1;
  for (std::size_t i = 0; i < values.size(); ++i) {
    const int s = values[i] > band ? 1 : values[i] < -band ? -1 : 0;
    if (s == 0) continue;
    if (sign != 0 && s != sign) {
      // The crossing: the last zero of the line between the samples around it.
      std::size_t j = static_cast<std::size_t>(last_index);
      for (std::size_t k = j; k < i; ++k)
        if ((values[k] > 0) != (values[k + 1] > 0)) j = k;
      const double a = values[j], b = values[j + 1];
      crossings.push_back(t[j] + (t[j + 1] - t[j]) * a / (a - b));
    }
    sign = s;
    last_index = static_cast<int>(i);
  }
  return crossings;
}

std::optional<double> motion_half_period(const physics::DampedExactRotation& motion,
                                         const Eigen::Matrix3d& axes,
                                         const std::vector<double>& tau) {
  if (!std::isfinite(motion.free().flip_period())) return std::nullopt;
  if (!motion.drag().active()) return motion.free().flip_period();  // T/2 exactly
  const std::optional<double> spacing = mean_flip_spacing(
      tau, axes.col(1), [&](double t) { return Eigen::Vector3d(axes * motion.omega_body(t)); });
  if (spacing) return spacing;
  const double middle = 0.5 * (tau.front() + tau.back());
  const double half = motion.flip_period_at(middle);
  if (!std::isfinite(half)) return std::nullopt;
  return half;
}

/// −slope/intercept of the least-squares line through |L|(τ): the fractional loss of |L| per
/// second (TossFit::L_decay).
double L_decay(const std::vector<double>& tau, const std::vector<double>& L) {
  const double n = static_cast<double>(tau.size());
  double st = 0, sl = 0, stt = 0, stl = 0;
  for (std::size_t i = 0; i < tau.size(); ++i) {
    st += tau[i], sl += L[i], stt += tau[i] * tau[i], stl += tau[i] * L[i];
  }
  const double slope = (n * stl - st * sl) / (n * stt - st * st);
  const double intercept = (sl - slope * st) / n;
  return intercept > 0 ? -slope / intercept : 0.0;
}

}  // namespace bookspin::fit
