#include "fit/rigid_restart.hpp"

#include <cmath>
#include <utility>

#include "common/errors.hpp"
#include "fit/joint_fit.hpp"
#include "physics/exact_solution.hpp"

namespace bookspin::fit {

bool suspect_body(const Parameters& p) { return suspect_moments(p.moments()); }

bool fitted_no_rigid_body(const Parameters& p) { return far_from_rigid(p.moments()); }

void keep_lowest(JointFitted& fit, std::size_t starts,
                 const std::function<std::optional<JointFitted>(std::size_t)>& fit_from) {
  for (std::size_t i = 0; i < starts; ++i)
    if (std::optional<JointFitted> again = fit_from(i);
        again && again->solved.cost < fit.solved.cost)
      fit = std::move(*again);
}

void refit_from_bodies(const std::vector<TossData>& data, const BiasFreedom& bias,
                       const FitSettings& settings, const GyroRecording& recording, Parameters& p,
                       Solved& solved, std::vector<bool>& rate_held) {
  Parameters first = start(data, settings);  // the Euler start's axes and ω0, once
  first.e.assign(recording.parts.size(), {0.0, 0.0, 0.0});
  JointFitted fit{p, solved, rate_held};
  keep_lowest(fit, kRigidStarts.size(), [&](std::size_t i) -> std::optional<JointFitted> {
    JointFitted again{first, {}, {}};
    again.p.log_ratios = {std::log(kRigidStarts[i][0]), std::log(kRigidStarts[i][1])};
    try {
      again.solved = joint_fit(data, again.p, bias, settings, recording.source, again.rate_held);
    } catch (const InputError&) {
      return std::nullopt;
    } catch (const physics::ExactHorizonError&) {
      return std::nullopt;  // a start whose fit runs past the motion's time horizon: passed over
    }
    // A start whose fit ends far from any rigid body has found none: passed over. Where such a
    // fit ends (which needle) follows the solver's round-off on a flat cost, and a lower cost
    // there decided the body (12-29-59 thinned: a needle 0.0067 : 0.011 in the page, none in the
    // command line; docs/phone-lab.md, "The fit"). One at an edge (I2 = I3) is kept: from there
    // the fit of the trimmed flights found the body again.
    if (fitted_no_rigid_body(again.p)) return std::nullopt;
    return again;
  });
  p = std::move(fit.p);
  solved = fit.solved;
  rate_held = std::move(fit.rate_held);
}

}  // namespace bookspin::fit
