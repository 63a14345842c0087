#pragma once
// Where the phone lay still, and the gyroscope's bias measured there (docs/phone-lab.md, "The
// bias"): the stretches whose scatter is the gyroscope's noise, found by their scatter (the
// recording's quietest stretches), not by a slow |ω|: a phone held in the hand turns slowly
// too, and its hand's motion is not the gyroscope's bias.
#include <Eigen/Dense>
#include <utility>
#include <vector>

namespace bookspin::fit {

/// The still stretches of a recording and what they say about the gyroscope's bias.
struct Rest {
  /// rad/s, phone frame: the mean ω over the still samples (the bias); 0 with none.
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  /// rad/s, phone frame: each axis's scatter there (the samples' standard deviation).
  Eigen::Vector3d sigma = Eigen::Vector3d::Zero();
  /// rad/s, phone frame: the standard error of `mean`, σ/√n_eff with n_eff = n (1 − ρ)/(1 + ρ),
  /// ρ ≥ 0 the samples' correlation from one to the next (an AR(1) noise's effective count).
  Eigen::Vector3d standard_error = Eigen::Vector3d::Zero();
  int samples = 0;  ///< still samples (0: no still stretch)
  /// s: each still stretch's first and last sample's time, in time order.
  std::vector<std::pair<double, double>> stretches;

  /// rad/s per axis: how far the bias in flight may lie from `mean`: 3 standard errors plus
  /// kBiasDrift plus kHandTurn (zero with no still sample).
  Eigen::Vector3d bound() const;
};

/// What counts as still.
struct RestSettings {
  double window = 0.3;        ///< s: a still stretch is at least this long
  double max_omega = 0.5;     ///< rad/s: every still sample turns slower than this (bias included)
  double max_scatter = 0.03;  ///< rad/s: no still window scatters more on any axis
  /// A window is still when its scatter (the largest axis's standard deviation) is at most this
  /// many times the quietest window's, and at most max_scatter; never less than min_scatter.
  double floor_factor = 3.0;
  double min_scatter = 0.005;  ///< rad/s
};

/// rad/s: the bias's allowance for drifting between the still stretch and a flight (the
/// largest change of a still stretch's mean between its halves on the development recordings,
/// rounded up: docs/phone-lab.md, "The bias").
inline constexpr double kBiasDrift = 0.002;

/// rad/s: how fast a hand holding the phone "still" may turn it, which the rest alone cannot
/// tell from the gyroscope's bias; the flights tell them apart within it (docs/phone-lab.md,
/// "The bias": a hand's slow turn, 0.015 rad/s measured against rests that turn 0–0.02 rad/s).
inline constexpr double kHandTurn = 0.015;

/// The still stretches of samples `omega` (rad/s, phone frame, as measured) at times `t` (s,
/// increasing) within `segments` (index ranges [begin, end) with no
/// pause or gap inside; no window spans two): each sample covered by a window of `window` s or
/// longer all of whose samples turn slower than max_omega and whose scatter is still by
/// `settings`. Never throws.
Rest find_rest(const std::vector<double>& t, const std::vector<Eigen::Vector3d>& omega,
               const std::vector<std::pair<int, int>>& segments, const RestSettings& settings = {});

/// The χ² of a bias `bias` fitted with standard errors `sigma` (rad/s, per axis) against zero:
/// Σ (bias_i/σ_i)²; infinite where a σ is not positive.
double bias_chi_square(const Eigen::Vector3d& bias, const Eigen::Vector3d& sigma);

/// χ² for 3 degrees of freedom at 1 %: a fitted bias below it is consistent with zero.
inline constexpr double kBiasChiSquare = 11.34;

/// Whether `bias` differs from zero significantly: bias_chi_square above kBiasChiSquare.
bool bias_significant(const Eigen::Vector3d& bias, const Eigen::Vector3d& sigma);

}  // namespace bookspin::fit
