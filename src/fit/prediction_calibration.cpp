#include "fit/prediction_calibration.hpp"

#include <algorithm>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <cstdio>

namespace bookspin::fit {

PredictionCalibration calibrate_prediction(const std::vector<double>& scores) {
  PredictionCalibration c;
  std::vector<double> s;
  for (double x : scores)
    if (std::isfinite(x)) s.push_back(std::abs(x));
  c.tosses = static_cast<int>(s.size());
  if (c.tosses < kFewestToCalibrate) return c;
  c.calibrated = true;
  const double n = static_cast<double>(c.tosses);
  double two_sigma = 0.0;  // in units of the propagated σ
  if (c.tosses >= kConformalFrom) {
    std::sort(s.begin(), s.end());
    const auto rank = static_cast<std::size_t>(std::ceil(kCalibratedCoverage * (n + 1.0)));
    two_sigma = s[std::min(rank, s.size()) - 1];
    c.method = "conformal";
  } else {
    double mean2 = 0.0;
    for (double x : s) mean2 += x * x / n;
    const boost::math::students_t t(n);
    two_sigma = boost::math::quantile(t, 0.5 + 0.5 * kCalibratedCoverage) * std::sqrt(mean2);
    c.method = "Student t";
  }
  c.factor = std::max(1.0, two_sigma / 2.0);
  return c;
}

std::string calibration_words(const PredictionCalibration& calibration) {
  const std::string n = std::to_string(calibration.tosses);
  const std::string others = calibration.tosses == 1 ? " other toss" : " other tosses";
  if (!calibration.calibrated)
    return "uncalibrated: " + n + others + " with a measured half period (" +
           std::to_string(kFewestToCalibrate) + " needed)";
  return calibration.method + " on " + n + others;
}

void calibrate_predictions(const std::vector<Prediction>& predictions,
                           std::vector<TossFit>& tosses) {
  std::vector<std::optional<double>> score(tosses.size());
  for (std::size_t j = 0; j < tosses.size(); ++j) {
    const Prediction& p = predictions[j];
    if (tosses[j].half_period_measured && p.propagated_half && p.propagated_sigma &&
        *p.propagated_sigma > 0)
      score[j] = (*tosses[j].half_period_measured - *p.propagated_half) / *p.propagated_sigma;
  }
  for (std::size_t k = 0; k < tosses.size(); ++k) {
    const Prediction& p = predictions[k];
    TossFit& toss = tosses[k];
    if (!p.propagated_half || !p.propagated_sigma || !toss.half_period_predicted) continue;
    std::vector<double> others;
    for (std::size_t j = 0; j < tosses.size(); ++j)
      if (j != k && score[j]) others.push_back(*score[j]);
    const PredictionCalibration c = calibrate_prediction(others);
    toss.prediction_interval = calibration_words(c);
    if (!c.calibrated) {
      toss.half_period_predicted_sigma.reset();
      continue;
    }
    const double sigma = *p.propagated_sigma * c.factor;
    char how[160];
    std::snprintf(how, sizeof how, ", widened ×%.2g by the %s", c.factor,
                  toss.prediction_interval.c_str());
    toss.not_predicted =
        withheld_for_width(*p.propagated_half, sigma, p.propagated_window, p.largest, how);
    if (toss.not_predicted.empty()) {
      toss.half_period_predicted_sigma = sigma;
      continue;
    }
    toss.half_period_predicted.reset();
    toss.half_period_predicted_sigma.reset();
    toss.predicted_window.reset();
    toss.predicted_from_tosses.reset();
    toss.predicted_from_seconds.reset();
  }
}

}  // namespace bookspin::fit
