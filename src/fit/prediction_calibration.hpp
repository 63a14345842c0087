#pragma once
// A predicted half period's interval calibrated by the fit's other tosses (docs/phone-lab.md,
// "Prediction intervals"): the σ propagated from a prediction's inputs (prediction_sigma.hpp)
// leaves out what the model cannot see (the motion's drift near the flip on real throws, the
// flight's ends, a phone's case); the other tosses' measured-minus-predicted half periods, each
// over its own propagated σ, say by how much it falls short on these data.
#include <string>
#include <vector>

#include "fit/prediction_sigma.hpp"
#include "fit/toss_fit.hpp"

namespace bookspin::fit {

/// The fewest other tosses (each with a measured and a predicted half period) an interval is
/// calibrated on; with fewer the prediction is shown uncalibrated, with no interval.
inline constexpr int kFewestToCalibrate = 2;
/// From this many other tosses on, the split-conformal quantile (distribution-free); below it,
/// the Student-t scale (normal scores assumed): ⌈0.95 (n + 1)⌉ ≤ n needs n ≥ 19.
inline constexpr int kConformalFrom = 19;
/// The coverage the calibrated ±2σ interval is set for.
inline constexpr double kCalibratedCoverage = 0.95;

/// How a prediction's σ is widened (never narrowed) to hold on the data.
struct PredictionCalibration {
  /// ≥ 1: the calibrated σ over the propagated σ.
  double factor = 1.0;
  /// The other tosses the scale rests on (each with a measured and a predicted half period).
  int tosses = 0;
  bool calibrated = false;  ///< false: fewer than kFewestToCalibrate others; no interval shown
  /// "conformal", "Student t" or "uncalibrated": how (fit_tables' prediction_interval column
  /// says it with the count).
  std::string method = "uncalibrated";
};

/// The calibration of one toss's prediction from `scores`: |measured − predicted| / σ_propagated
/// of each other toss of the fit (none of its own), by the toss's own prediction from the body of
/// the tosses without it. n ≥ kConformalFrom: the ⌈0.95 (n + 1)⌉-th smallest score over 2 (the
/// split-conformal interval, Vovk et al. 2005; in the leave-one-out form of Barber et al. 2021,
/// "Predictive inference with the jackknife+", Ann. Statist. 49(1)): the ±2σ interval then holds
/// the truth 95 % of the time for exchangeable tosses, whatever their scatter's shape. n from
/// kFewestToCalibrate to kConformalFrom − 1: scores taken as |N(0, c²)|, c² their mean square,
/// and 2σ = t_{n, 0.975} c σ_propagated (a new score over ĉ is Student-t with n degrees of
/// freedom). Either way the factor is at least 1. Fewer: uncalibrated, factor 1.
PredictionCalibration calibrate_prediction(const std::vector<double>& scores);

/// "conformal on 21 other tosses", "Student t on 5 other tosses", or "uncalibrated: 1 other toss
/// with a measured half period (2 needed)": the words the tables and the summary give.
std::string calibration_words(const PredictionCalibration& calibration);

/// Each prediction's interval calibrated by the fit's other tosses (calibrate_prediction on their
/// scores): its propagated σ widened by the scale the other tosses' scores |measured − predicted|
/// / σ call for, then withheld where over ±kWidestInterval; shown with no σ where too few others
/// have a measured and a predicted half period (uncalibrated, in words). `predictions` and
/// `tosses` one per toss, in order; each toss's predicted fields set or cleared in place.
void calibrate_predictions(const std::vector<Prediction>& predictions,
                           std::vector<TossFit>& tosses);

}  // namespace bookspin::fit
