#pragma once
// A toss's flag (docs/phone-lab.md, "Flags"; "Saturation"): what its residual says that the
// measurement's noise cannot (a catch or throw inside the flight, a knock, a body that flexes),
// a recording beyond any gyroscope's range, or a flight the gyroscope's range clipped; and the
// gyroscope's noise at rest that the residual is judged against.
#include <Eigen/Dense>
#include <optional>
#include <string>
#include <vector>

#include "fit/flights.hpp"
#include "fit/recording.hpp"
#include "fit/saturation.hpp"
#include "fit/toss_parameters.hpp"

namespace bookspin::fit {

/// The gyroscope's scatter at rest (rad/s, per component, RMS): the samples outside every
/// flight within rest_omega/2 of their recording's bias (RecordingPart::bias); nullopt with
/// fewer than 20 such samples.
std::optional<double> rest_noise(const GyroRecording& recording, const FlightSearch& search);

/// The torque the measured samples need between each two neighbours, by Euler's equations
/// I ω̇ + ω × I ω = τ (docs/physics.md §8) at the step's midpoint: ω̇ = (ω_{i+1} − ω_i)/Δt,
/// ω = (ω_i + ω_{i+1})/2 (second order in Δt, and no pattern of samples hides from it), as
/// |τ| / (λ_max |ω|²): dimensionless, 0 for a free flight up to the noise and the body's error.
/// `tau` s (increasing), `omega` rad/s (phone frame), `inertia` the body's tensor in the phone
/// frame (any scale). n − 1 values for n samples; a step with ω = 0 or Δt ≤ 0 reads 0.
std::vector<double> step_torque(const std::vector<double>& tau,
                                const std::vector<Eigen::Vector3d>& omega,
                                const Eigen::Matrix3d& inertia);

/// The flag of toss `data` (its residual r_i = ω_fitted − ω_measured at each of data.tau; the
/// fitted body's tensor `inertia`, phone frame): a reading beyond any gyroscope's range, a
/// flight the range clipped to under a quarter of its samples, or what the residual looks like
/// against the flight's median 50 ms block and `noise` (rest_noise): a block's jump is named a
/// throw, a catch or a knock only where the samples there need a torque (step_torque over
/// kBlockFactor × the flight's median block; docs/phone-lab.md, "Flags"). Empty for a clean
/// toss. One line.
std::string toss_flag(const TossData& data, const std::vector<Eigen::Vector3d>& residual,
                      const Saturation& saturation, std::optional<double> noise,
                      const Eigen::Matrix3d& inertia);

/// What in the tosses' samples a fit that failed can blame, as a clause after "the fit did not
/// converge: " (docs/phone-lab.md, "Flags"): an axis whose |ω| passes any gyroscope's range
/// (±4000 °/s, 69.8 rad/s) while another's stays within it (one axis in °/s, or scaled), or every
/// axis beyond it (a recording in °/s); empty where nothing in the samples explains it.
std::string scale_cause(const std::vector<TossData>& data);

}  // namespace bookspin::fit
