#pragma once
// The flight ends' spread (docs/phone-lab.md, "Error bars"): how far each flight's ends may lie
// from where the finder put them, and how far the body and each drag rate move when the ends are
// moved in by it, added to their σ. What least squares cannot see: where the throw ends and the
// catch begins, which the finder only estimates.
#include <Eigen/Dense>
#include <vector>

#include "fit/fit_stages.hpp"
#include "fit/flights.hpp"
#include "fit/toss_fit.hpp"
#include "fit/toss_parameters.hpp"

namespace bookspin::fit {

/// s: the least a flight's end may lie off where it was put (the finder's torque window and the
/// trim's residual judge it to a few samples at 100 Hz: docs/phone-lab.md, "Error bars").
inline constexpr double kEndUncertainty = 0.02;
/// The most of a flight an end is moved in by to weigh its placement.
inline constexpr double kEndShare = 0.15;

/// How far each flight's ends may lie from where the finder put them (docs/phone-lab.md, "Error
/// bars"): per toss, s, the start's and the end's.
struct EndShifts {
  std::vector<double> start, end;
};

/// Each end's uncertainty, s: the larger of kEndUncertainty and how far the trim moved it from the
/// finder's end (`found`, the flights as the finder gave them, of which `flights` are trimmed
/// copies), at most kEndShare of its flight; empty where `found` is null (flights by hand).
EndShifts end_shifts(const std::vector<Flight>& flights, const FlightSearch* found);

/// The flight ends' placement added to the body's and each drag rate's σ (docs/phone-lab.md,
/// "Error bars"): the joint fit again with every flight's start moved in by its uncertainty
/// (`shifts`), and again with every end moved in; each value's spread σ² = Σ (θ_moved − θ)²
/// added in quadrature to its σ (the covariance's, inflated, or the jackknife's). What least
/// squares cannot see: where the throw ends and the catch begins, which the finder only
/// estimates. No term where a refit fails or a σ is missing. `data`, `rate_held` and `sigmas` one
/// per toss; `correction` rad/s, phone frame, one per recording (the samples carry it already);
/// widens body.ratio_sigma, body.axis_sigma_deg (°) and sigmas.rate in place.
void widen_by_ends(const std::vector<TossData>& data, const Parameters& p, const EndShifts& shifts,
                   const FitSettings& settings, const std::vector<bool>& rate_held,
                   const BiasFreedom& bias, const std::vector<Eigen::Vector3d>& correction,
                   BodyEstimate& body, TossSigmas& sigmas);

}  // namespace bookspin::fit
