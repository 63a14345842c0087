#pragma once
// The σ of a toss's predicted half period (docs/phone-lab.md, "Prediction intervals"): what
// half_period_predicted rests on, propagated to it. A prediction from the first 0.2 s near the
// separatrix cannot be held to a fixed percentage: its interval says how far it may be off.
#include <Eigen/Dense>
#include <optional>

#include "fit/toss_parameters.hpp"
#include "fit/toss_solve.hpp"

namespace bookspin::fit {

/// What a prediction's σ is propagated from, besides the toss and the prediction's own fit.
struct PredictionInputs {
  physics::DragLaw drag = physics::DragLaw::none;
  /// σ of the moment ratios I1/I3, I2/I3 the prediction's body carries (BodyEstimate::
  /// ratio_sigma); nullopt or zeros for moments given.
  std::optional<Eigen::Vector3d> ratio_sigma;
  /// rad/s per phone axis: the σ of the bias removed from the toss (its rest's standard error
  /// plus kBiasDrift, or the flights' fitted σ; 0 where nothing bounds it).
  Eigen::Vector3d bias_sigma = Eigen::Vector3d::Zero();
};

/// rad/s per phone axis: the σ of the bias removed from `part`'s samples in flight: its still
/// rest's standard error plus kBiasDrift, or with no rest its flights' fitted σ, or 0.
Eigen::Vector3d bias_sigma(const RecordingPart& part);

/// s: one σ of `half` (the half period predicted from `fitted`, the toss `d`'s ω0 and drag rate
/// fitted on its first options.window s with the body held), in quadrature (each term the half
/// of the spread of T/2 between the input ± its σ, T/2 by motion_half_period over d.tau):
/// ω0's scatter over the window (the window's residual per component over √n, twice for the
/// correlation of a real gyroscope's residual from sample to sample, and the bias's σ), the
/// window's placement (T/2 predicted again from the window's first half, started from `start`:
/// the difference), and the body's σ (each ratio). nullopt where the prediction has no T/2 to
/// compare with (none at some input within its σ: the separatrix within reach).
std::optional<double> prediction_sigma(const TossData& d, const Parameters& fitted,
                                       const Parameters& start, const SolveOptions& options,
                                       const PredictionInputs& inputs, double half);

}  // namespace bookspin::fit
