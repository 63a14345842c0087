#pragma once
// The bodies fitted without each fold of tosses (docs/phone-lab.md, "Error bars" and "Prediction
// intervals"): what each toss's prediction rests on, and the grouped jackknife that widens the
// body's σ by their spread.
#include <cstddef>
#include <optional>
#include <vector>

#include "fit/fit_stages.hpp"
#include "fit/toss_fit.hpp"
#include "fit/toss_parameters.hpp"

namespace bookspin::fit {

/// The bodies the predictions use, each fitted without some of the tosses: the tosses are dealt
/// into at most five folds (toss k into fold k mod folds) and each fold's body is fitted on the
/// tosses of the other folds, so that with up to five tosses it is the body of all the others,
/// and with more the fits stay five, not one per toss. With --moments and one toss, the moments
/// given (the axes are fitted with ω0 on the toss's first predict_window s, toss_values). None
/// where a fold's fit fails: no prediction then. The same bodies give the moments' jackknife
/// spread (widen_by_folds).
struct Folds {
  std::size_t count = 1;
  std::vector<std::optional<Parameters>> body;
};

/// The folds of `data` and their bodies, fitted from the joint fit `joint` with each recording's
/// bias `correction` (rad/s) as the joint fit left it.
Folds fold_bodies(const std::vector<TossData>& data, const Parameters& joint,
                  const BiasFreedom& bias, const std::vector<Eigen::Vector3d>& correction,
                  const FitSettings& settings);

/// The grouped jackknife over the folds: σ² = (G − 1)/G Σ (θ_g − θ̄)², each axis's turn from the
/// joint axes; the body's σ the larger of it and the covariance's (docs/phone-lab.md, "Error
/// bars").
void widen_by_folds(const Folds& folds, bool fixed, BodyEstimate& body);

}  // namespace bookspin::fit
