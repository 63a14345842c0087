#include "fit/prediction_calibration.hpp"

#include <algorithm>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>

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

}  // namespace bookspin::fit
