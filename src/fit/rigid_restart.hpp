#pragma once
// The restart from rigid bodies (docs/phone-lab.md, "The fit"): a joint fit that ends at moments no
// rigid body has, or at a needle, fitted again from the moment ratios of a few rigid bodies, and
// the lowest cost of all kept.
#include <array>
#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

#include "fit/fit_stages.hpp"
#include "fit/recording.hpp"
#include "fit/rigid_bounds.hpp"
#include "fit/toss_fit.hpp"
#include "fit/toss_parameters.hpp"
#include "fit/toss_solve.hpp"

namespace bookspin::fit {

/// Moment ratios (I1/I3, I2/I3) a rigid body may have, the fit's other starts where the Euler
/// estimate's start ends past the triangle inequality or at a needle: a book's, a near-square
/// slab's, a box's.
inline constexpr std::array<std::array<double, 2>, 3> kRigidStarts{
    {{0.25, 0.8}, {0.5, 0.55}, {0.6, 0.85}}};

/// Fitted moments whose two smaller sum to less than the largest (docs/physics.md §11: no rigid
/// body has them), a needle's, or at the edge I2 = I3 (rigid_bounds.hpp's suspect_moments): where
/// a fit from a poor start ends (a recording thinned to a browser's rate did, the residual four
/// to ten times a book's).
bool suspect_body(const Parameters& p);

/// Fitted moments far past any rigid body a phone is tossed beside (rigid_bounds.hpp's
/// far_from_rigid: I1/I3 under kFarNeedle, or I1 + I2 under kFarTriangleShare I3).
bool fitted_no_rigid_body(const Parameters& p);

/// One joint fit's outcome: its unknowns, its solve (Solved::cost, (rad/s)²) and the tosses
/// whose drag rate it held at 0.
struct JointFitted {
  Parameters p;
  Solved solved;
  std::vector<bool> rate_held;
};

/// The fits `fit_from(i)` from each of `starts` starts (nullopt: a start passed over) beside
/// `fit`: the one of the lowest cost of them all replaces `fit` where its cost is lower than
/// `fit`'s, whatever the order of the starts (not the last that beats `fit`).
void keep_lowest(JointFitted& fit, std::size_t starts,
                 const std::function<std::optional<JointFitted>(std::size_t)>& fit_from);

/// A fit that ended at a suspect body (a local minimum its start led it to: a recording thinned
/// to a browser's ~55 Hz did; docs/phone-lab.md, "The fit") fitted again from each of
/// kRigidStarts, its axes and ω0 started as the Euler start's; the lowest cost replaces `p`,
/// `solved` and `rate_held` where it is lower (keep_lowest). A start that does not converge, runs
/// past the exact motion's time horizon, or ends far from any rigid body (fitted_no_rigid_body:
/// which needle, on a flat cost, hangs on round-off; the page and the command line parted so) is
/// passed over.
void refit_from_bodies(const std::vector<TossData>& data, const BiasFreedom& bias,
                       const FitSettings& settings, const GyroRecording& recording, Parameters& p,
                       Solved& solved, std::vector<bool>& rate_held);

}  // namespace bookspin::fit
