#pragma once
// The free flights of a gyroscope recording (docs/phone-lab.md, "How the flights are found"):
// rest (the gyroscope's bias measured there), the throw (spikes), free flight (torque-free:
// Euler's equations hold, docs/physics.md §8), the catch (spikes).
#include <Eigen/Dense>
#include <string>
#include <utility>
#include <vector>

#include "fit/fit_options.hpp"  // parse_toss_ranges, check_toss_ranges
#include "fit/recording.hpp"
#include "fit/rest.hpp"

namespace bookspin::fit {

/// One free flight: samples first … last (inclusive) of the recording.
struct Flight {
  int first = 0, last = 0;
  double t_start = 0.0, t_end = 0.0;  ///< s, the first and last sample's time
};

/// A stretch of motion that was not kept, and why (one line).
struct DroppedStretch {
  double t_start = 0.0, t_end = 0.0;  ///< s
  std::string reason;
};

/// The start of a DroppedStretch's reason for motion too slow for a flight ("turning slower
/// than 2.000 rad/s"): the summary counts these (fit_summary).
inline constexpr const char* kTooSlowReason = "turning slower than ";

/// What the finder found. The bias it removed before judging is each recording's own
/// (RecordingPart::bias).
struct FlightSearch {
  std::vector<Flight> flights;
  std::vector<DroppedStretch> dropped;
};

/// The finder's thresholds.
struct FinderSettings {
  /// rad/s: moving at or above this (bias included); a still stretch turns slower
  /// (RestSettings::max_omega).
  double rest_omega = 0.5;
  double flight_omega = 2.0;  ///< rad/s: a free flight turns at least this fast throughout
  double min_flight = 0.3;    ///< s: a shorter flight is dropped (too short to fit)
};

/// ω̇ (rad/s², phone frame) at each sample: the slope of a quadratic fitted by least squares to
/// the samples within ±2 of it, or within ±5 ms of it where there are more (fewer at an end),
/// with their own times (jitter allowed).
std::vector<Eigen::Vector3d> omega_rate(const std::vector<double>& t,
                                        const std::vector<Eigen::Vector3d>& omega);

/// The symmetric inertia tensor (phone frame, up to scale: largest eigenvalue 1) that best
/// satisfies Euler's equations I ω̇ + ω × (I ω) = 0 (docs/physics.md §8) on the samples
/// `indices`, as the smallest right singular vector of the linear system in its six entries.
Eigen::Matrix3d euler_inertia(const std::vector<Eigen::Vector3d>& omega,
                              const std::vector<Eigen::Vector3d>& omega_dot,
                              const std::vector<int>& indices);

/// Where `recording` (its samples as measured, pooled or not) lay still, and what its still
/// samples say of its gyroscope's bias (fit/rest.hpp): its stretches by their scatter, within
/// its pauses and gaps, turning slower than settings.rest_omega.
Rest measure_rest(const GyroRecording& recording, const FinderSettings& settings = {});

/// Finds the free flights of `recording` (pooled: pool_recordings; each part's bias removed from
/// the omega it judges). No flight spans a pause or a gap (a step over five times the 90th
/// percentile of the steps and over 25 ms). Never throws for a recording with no flight (flights is
/// then empty, and dropped says why); std::logic_error for a recording not pooled.
FlightSearch find_flights(const GyroRecording& recording, const FinderSettings& settings = {});

/// The flights given by hand, [t_start, t_end] s each, of `recording` (pooled, as find_flights
/// takes it), in time order whatever order they are given in. Throws InputError naming `option`
/// when a range holds fewer than 10 samples, is reversed, spans a pause, overlaps another
/// (shares an instant with it) or is given twice, and first, as every door's ranges, for an end
/// that is not finite (check_toss_ranges).
FlightSearch hand_flights(const GyroRecording& recording,
                          const std::vector<std::pair<double, double>>& ranges,
                          const std::string& option = "--tosses");

/// Throws InputError "<source>: no free flight found", with why each of `search`'s stretches
/// was dropped ("(t0–t1 s: reason; …)"), then `remedy` where given ("…: name the flights by hand
/// with --tosses …": the door's words, report.hpp's hand_flights_remedy).
[[noreturn]] void throw_no_flight(const GyroRecording& recording, const FlightSearch& search,
                                  const std::string& remedy = "");

}  // namespace bookspin::fit
