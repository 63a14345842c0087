#pragma once
// The joint fit of every toss from one start (docs/phone-lab.md, "The fit"): the body, each toss's
// ω0 and drag rate and each recording's bias correction by least squares (toss_solve.hpp), grown
// over each toss from a rough start; and which bias corrections it frees (fit_stages.hpp).
#include <string>
#include <vector>

#include "fit/fit_stages.hpp"
#include "fit/recording.hpp"
#include "fit/toss_fit.hpp"
#include "fit/toss_parameters.hpp"
#include "fit/toss_solve.hpp"

namespace bookspin::fit {

/// Which of the recordings `parts` the joint fit of `data` frees a bias correction for (two or
/// more of its tosses), bounded by its still rest's bound where it has one; those `held` (by
/// part) held at zero.
BiasFreedom bias_freedom(const std::vector<RecordingPart>& parts, const std::vector<TossData>& data,
                         const std::vector<bool>& held);

/// The joint fit of every toss from `p`'s start: grown over each toss (0.3, 0.6, then all of
/// it), so that a rough start does not lock onto a wrong phase, the drag rates joining at the
/// last stage; free bias corrections (no rest) held at 0 until then (freed on each flight's start
/// they traded 2 rad/s for a wrong body), bounded ones until the body settles (a bounded solve
/// from a body far off leaves them at the bound's wall); then any toss whose drag
/// rate came out below 0 fitted again with it held at 0 (air cannot speed a body up,
/// docs/phone-lab.md, "Drag": held, not bounded, since a bound that a rate meets from its start
/// at 0 stalled Ceres's bounded steps far from the fit). Throws InputError when a stage fails.
Solved joint_fit(const std::vector<TossData>& data, Parameters& p, const BiasFreedom& bias,
                 const FitSettings& settings, const std::string& source,
                 std::vector<bool>& rate_held);

}  // namespace bookspin::fit
