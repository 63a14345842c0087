#include "fit/prediction_sigma.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

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

HeldRate held_rate(const std::vector<TossData>& rest, const Parameters& fold, bool moments_fixed,
                   physics::DragLaw law, const std::vector<std::optional<double>>& sigmas) {
  if (rest.empty() || law == physics::DragLaw::none) return {};
  const std::optional<Covariances> cov =
      covariances(rest, fold, moments_fixed, std::vector<bool>(fold.e.size(), false), law);
  double weights = 0.0, sum = 0.0, plain = 0.0, sigma2 = 0.0;
  bool weighted = cov.has_value() && sigmas.size() == rest.size();
  for (std::size_t j = 0; j < rest.size(); ++j) {
    const double rate = std::max(fold.omega0.at(j)[3], 0.0);
    plain += rate / static_cast<double>(rest.size());
    const double c = weighted ? cov->omega0.at(j)(3, 3) : 0.0;
    if (!(c > 0) || !sigmas[j]) {
      weighted = false;
      continue;
    }
    weights += 1.0 / c, sum += rate / c, sigma2 += *sigmas[j] * *sigmas[j] / (c * c);
  }
  if (!weighted) return {plain, 0.0};
  return {sum / weights, std::sqrt(sigma2) / weights};
}

Eigen::Vector3d held_out_ratio_sigma(const Eigen::Vector3d& joint, double all, double seconds) {
  if (!(seconds > 0.0) || !(seconds < all)) return joint;
  return joint * std::sqrt(all / seconds);
}

Eigen::Vector3d bias_sigma(const RecordingPart& part) {
  if (part.rest.samples > 0) return part.rest.standard_error.array() + kBiasDrift;
  return part.bias_fitted_sigma.value_or(Eigen::Vector3d::Zero());
}

const char* PredictionSigma::largest() const {
  const double most = std::max({omega0, placement, body, rate});
  if (body == most) return "the body's σ";
  if (rate == most) return "the drag rate's σ";
  return placement == most ? "the window's placement" : "ω0's scatter";
}

std::optional<PredictionSigma> prediction_sigma(const TossData& d, const Parameters& fitted,
                                                const Parameters& start,
                                                const SolveOptions& options,
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
  PredictionSigma sigma;
  // Half the spread of T/2 between x − σ and x + σ; nullopt where either has no T/2.
  bool reached = true;
  const auto spread2 = [&](const std::optional<double>& lo, const std::optional<double>& hi) {
    if (!lo || !hi) return reached = false, 0.0;
    return 0.25 * (*hi - *lo) * (*hi - *lo);
  };
  double omega0_2 = 0.0, body_2 = 0.0;
  for (int c = 0; c < 3; ++c) {
    const double s = std::sqrt(4.0 * scatter2 / n + inputs.bias_sigma[c] * inputs.bias_sigma[c]);
    const Eigen::Vector3d step = s * Eigen::Vector3d::Unit(c);
    omega0_2 += spread2(half_of(moments, axes, w0 - step, drag, d.tau),
                        half_of(moments, axes, w0 + step, drag, d.tau));
  }
  if (inputs.ratio_sigma)
    for (int i = 0; i < 2; ++i) {
      const Eigen::Vector3d step = (*inputs.ratio_sigma)[i] * Eigen::Vector3d::Unit(i);
      if (!(step.norm() > 0)) continue;
      if (!(moments[i] > step[i])) return std::nullopt;  // a moment within σ of zero
      body_2 += spread2(half_of(moments - step, axes, w0, drag, d.tau),
                        half_of(moments + step, axes, w0, drag, d.tau));
    }
  if (inputs.rate_sigma > 0 && inputs.drag != physics::DragLaw::none) {
    const physics::Drag lo{drag.law, std::max(0.0, drag.rate - inputs.rate_sigma)};
    const physics::Drag hi{drag.law, drag.rate + inputs.rate_sigma};
    sigma.rate = std::sqrt(
        spread2(half_of(moments, axes, w0, lo, d.tau), half_of(moments, axes, w0, hi, d.tau)));
  }
  sigma.omega0 = std::sqrt(omega0_2);
  sigma.body = std::sqrt(body_2);
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
    sigma.placement = std::abs(*other - half);
  }
  if (!reached || !std::isfinite(sigma.total())) return std::nullopt;
  return sigma;
}

namespace {

/// A prediction withheld, with why (one phrase), and nothing computed.
Prediction withheld_because(const char* why) {
  Prediction prediction;
  prediction.withheld = why;
  return prediction;
}

}  // namespace

Prediction predict_half_period(const TossData& d, const Parameters& body,
                               const SolveOptions& options, const PredictionInputs& inputs) {
  char why[200];
  Parameters p = body;
  if (!solve({d}, p, options).usable) {
    std::snprintf(why, sizeof why, "its first %g s could not be fitted", options.window);
    return withheld_because(why);
  }
  const std::optional<double> half = half_of(p.moments(), p.axes(), omega0_of(p),
                                             physics::Drag{inputs.drag, p.omega0[0][3]}, d.tau);
  if (!half) {
    std::snprintf(why, sizeof why, "the motion predicted from its first %g s does not flip",
                  options.window);
    return withheld_because(why);
  }
  const std::optional<PredictionSigma> sigma = prediction_sigma(d, p, body, options, inputs, *half);
  if (!sigma) {
    std::snprintf(why, sizeof why,
                  "the separatrix within its inputs' σ from its first %g s: no interval holds it",
                  options.window);
    return withheld_because(why);
  }
  Prediction prediction;
  prediction.propagated_half = half;
  prediction.propagated_sigma = sigma->total();
  prediction.largest = sigma->largest();
  prediction.propagated_window = options.window;
  prediction.withheld = withheld_for_width(*half, sigma->total(), options.window, sigma->largest());
  if (prediction.withheld.empty()) {
    prediction.half = half;
    prediction.sigma = sigma->total();
    prediction.window = options.window;
  }
  return prediction;
}

std::string withheld_for_width(double half, double sigma, double window, const char* largest,
                               const std::string& how) {
  const double width = 2.0 * sigma / half;
  if (width <= kWidestInterval) return "";
  char why[300];
  std::snprintf(why, sizeof why,
                "interval ±%.0f %% (2σ/T, mostly %s%s) from its first %g s, over the ±%.0f %% "
                "shown",
                100.0 * width, largest, how.c_str(), window, 100.0 * kWidestInterval);
  return why;
}

}  // namespace bookspin::fit
