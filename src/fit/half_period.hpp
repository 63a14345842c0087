#pragma once
// Flips and half periods (docs/phone-lab.md, "Reading the result"): the sign changes of ω
// about the intermediate axis, measured or of a model, and their mean spacing, T/2; and the
// measured |L|'s decay.
#include <Eigen/Dense>
#include <optional>
#include <vector>

#include "physics/damped_exact.hpp"

namespace bookspin::fit {

/// Times of the sign changes of `values` (hysteresis at ±`band`), by linear interpolation.
std::vector<double> sign_changes(const std::vector<double>& t, const std::vector<double>& values,
                                 double band);

/// T/2 of a (damped) exact motion over a flight sampled at `tau`: the mean spacing of its flips
/// there, or its T/2 at the flight's middle where it flips fewer than twice (docs/physics.md
/// §21); nullopt for a steady motion or one the drag stops before a flip.
std::optional<double> motion_half_period(const physics::DampedExactRotation& motion,
                                         const Eigen::Matrix3d& axes,
                                         const std::vector<double>& tau);

/// −slope/intercept of the least-squares line through |L|(τ) (`tau` s, `L` any unit, equal
/// lengths, two or more): the fractional loss of |L| per second (TossFit::L_decay); 0 where the
/// line's intercept is not positive.
double L_decay(const std::vector<double>& tau, const std::vector<double>& L);

}  // namespace bookspin::fit
