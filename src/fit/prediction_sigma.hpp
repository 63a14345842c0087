#pragma once
// A toss's predicted half period and its σ (docs/phone-lab.md, "Prediction intervals"): T/2
// predicted from the toss's first window with the held-out body, and what it rests on propagated
// to it. A prediction near the separatrix cannot be held to a fixed percentage: its interval says
// how far it may be off, and one wider than ±kWidestInterval is withheld, with the reason.
#include <Eigen/Dense>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "fit/toss_parameters.hpp"
#include "fit/toss_solve.hpp"

namespace bookspin::fit {

/// The widest interval shown: a prediction whose 2σ/T exceeds this is withheld (docs/phone-lab.md,
/// "Prediction intervals").
inline constexpr double kWidestInterval = 0.25;

/// What a prediction's σ is propagated from, besides the toss and the prediction's own fit.
struct PredictionInputs {
  physics::DragLaw drag = physics::DragLaw::none;
  /// σ of the moment ratios I1/I3, I2/I3 the prediction's body carries (BodyEstimate::
  /// ratio_sigma); nullopt or zeros for moments given.
  std::optional<Eigen::Vector3d> ratio_sigma;
  /// rad/s per phone axis: the σ of the bias removed from the toss (its rest's standard error
  /// plus kBiasDrift, or the flights' fitted σ; 0 where nothing bounds it).
  Eigen::Vector3d bias_sigma = Eigen::Vector3d::Zero();
  /// 1/s: the σ of the drag rate the prediction holds (HeldRate::sigma); 0 under DragLaw::none
  /// or with none known.
  double rate_sigma = 0.0;
};

/// 1/s: the drag rate a prediction holds and its σ: the weighted mean of the other tosses'
/// rates (`rest`, fitted as `fold` without the toss predicted; each at least 0: air cannot speed
/// a body up), each weighted by the inverse of its variance in that fit ((JᵀJ)⁻¹, so that
/// nothing of the toss predicted weighs in), its σ from theirs (`sigmas`, the joint fit's, one
/// per toss of `rest`). Their plain mean and σ 0 where a variance or σ is missing; 0, 0 for no
/// tosses or DragLaw::none.
struct HeldRate {
  double rate = 0.0, sigma = 0.0;
};
HeldRate held_rate(const std::vector<TossData>& rest, const Parameters& fold, bool moments_fixed,
                   physics::DragLaw law, const std::vector<std::optional<double>>& sigmas);

/// The σ of the moment ratios of a body fitted on `seconds` of the `all` s of flight the joint
/// fit's σ `joint` rests on (docs/phone-lab.md, "Prediction intervals"): `joint` × √(all /
/// seconds), a least-squares σ falling as one over the root of the samples; `joint` itself where
/// `seconds` is not positive or not less than `all`.
Eigen::Vector3d held_out_ratio_sigma(const Eigen::Vector3d& joint, double all, double seconds);

/// rad/s per phone axis: the σ of the bias removed from `part`'s samples in flight: its still
/// rest's standard error plus kBiasDrift, or with no rest its flights' fitted σ, or 0.
Eigen::Vector3d bias_sigma(const RecordingPart& part);

/// s: one σ of a predicted half period, by term (each the half of the spread of T/2 between its
/// input ± its σ, added in quadrature where more than one input): ω0's scatter over the window
/// and the bias's σ, the window's placement, the body's σ (each ratio), the drag rate's σ.
struct PredictionSigma {
  double omega0 = 0.0, placement = 0.0, body = 0.0, rate = 0.0;
  double total() const {
    return std::sqrt(omega0 * omega0 + placement * placement + body * body + rate * rate);
  }
  /// "ω0's scatter", "the window's placement", "the body's σ" or "the drag rate's σ": the
  /// largest term.
  const char* largest() const;
};

/// One σ of `half` (s: the half period predicted from `fitted`, the toss `d`'s ω0 and drag rate
/// fitted on its first options.window s with the body held), by term: ω0's scatter over the
/// window (the window's residual per component over √n, twice for the correlation of a real
/// gyroscope's residual from sample to sample, and the bias's σ), the window's placement (T/2
/// predicted again from the window moved kWindowShift s later, started from `start`: the
/// difference), the body's σ (each ratio) and the held drag rate's σ (its lower end at 0: air
/// cannot speed a body up). T/2 by motion_half_period over d.tau. nullopt
/// where the prediction has no T/2 to compare with (none at some input within its σ: the
/// separatrix within reach).
std::optional<PredictionSigma> prediction_sigma(const TossData& d, const Parameters& fitted,
                                                const Parameters& start,
                                                const SolveOptions& options,
                                                const PredictionInputs& inputs, double half);

/// A toss's prediction as shown: T/2 and its σ (s) with the window its ω0 was fitted on, or none
/// and why.
struct Prediction {
  std::optional<double> half, sigma;
  std::optional<double> window;  ///< s: the first seconds of the toss it was predicted from
  std::string withheld;          ///< "" where shown: else why not (one phrase)
  /// T/2 and its propagated σ (s) wherever both could be computed, shown or withheld for its
  /// width: what the calibration by the other tosses takes (prediction_calibration.hpp); the
  /// largest term of the σ and the window (s) with them.
  std::optional<double> propagated_half, propagated_sigma;
  const char* largest = "";
  double propagated_window = 0.0;
};

/// The withholding rule on a σ (s) of T/2 `half` (s) from the first `window` s: "" where its
/// interval 2σ/T is within kWidestInterval, else why not ("interval ±63 % (2σ/T, mostly the
/// body's σ) from its first 0.2 s, over the ±25 % shown"); `how` (optional) says how σ was
/// calibrated, after "mostly …".
std::string withheld_for_width(double half, double sigma, double window, const char* largest,
                               const std::string& how = "");

/// Predicts toss `d`'s T/2 from `body` (the held-out body and drag rate, ω0 its start; options:
/// the body held, options.window the window) with its σ; withheld, with why, where its interval
/// 2σ/T is over kWidestInterval (its width and largest term said), where the separatrix is
/// within its inputs' σ, or where the window's fit gives no flip.
Prediction predict_half_period(const TossData& d, const Parameters& body,
                               const SolveOptions& options, const PredictionInputs& inputs);

}  // namespace bookspin::fit
