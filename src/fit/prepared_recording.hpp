#pragma once
// A recording made ready for the class's live fit (docs/phone-lab.md, "The live fit"): what a
// toss needs of its own, done once when it arrives: read and pooled alone, its flights found,
// and its own joint fit (its body, each flight's ω0 and drag rate, its bias correction), the
// start its flights take in every live fit after.
#include <Eigen/Dense>
#include <array>
#include <string>
#include <vector>

#include "fit/flights.hpp"
#include "fit/recording.hpp"
#include "fit/toss_fit.hpp"
#include "fit/toss_parameters.hpp"

namespace bookspin::fit {

/// One recording, prepared: a value, shared read-only by every live fit that takes it.
struct PreparedRecording {
  std::string name;    ///< GyroRecording::name (the file-safe stem)
  std::string source;  ///< the file, for messages
  RecordingPart part;  ///< its still rest and bias, as pool_recordings measures them alone
  /// Its flights in its own times (found as `bookspin fit FILE` finds them, not trimmed), and
  /// the stretches dropped.
  FlightSearch search;
  std::vector<TossData> data;  ///< one per flight, group 0, its rest's bias removed
  /// Its own joint fit (fit/joint_fit.hpp; no restarts, no error bars): each flight's ω0 and
  /// drag rate (ω0x, ω0y, ω0z, r) and its bias correction (rad/s); its body where `own_body`.
  std::vector<std::array<double, 4>> omega0;
  std::array<double, 3> bias_correction{0, 0, 0};
  bool own_body = false;  ///< false: its own fit failed (no flight, or it did not converge)
  Eigen::Matrix3d R0 = Eigen::Matrix3d::Identity();
  std::array<double, 2> log_ratios{0, 0};
};

/// `recording` (as read: read_recording) prepared. A recording with no flight is prepared with
/// none (the live fit fits the others; `bookspin fit` of it alone says why there is none); an
/// own fit that does not converge leaves each ω0 at its first sample's. Throws Interrupted when
/// settings.stop answers a signal.
PreparedRecording prepare_recording(const GyroRecording& recording,
                                    const FitSettings& settings = {});

/// The bytes `prepared` holds (its samples in flight and its values): what the class server
/// keeps per toss.
std::size_t prepared_bytes(const PreparedRecording& prepared);

}  // namespace bookspin::fit
