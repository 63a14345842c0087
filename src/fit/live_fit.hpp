#pragma once
// The class's live pooled fit (docs/phone-lab.md, "The live fit"): every prepared recording's
// flights with one body, in one joint solve warm-started from the last live fit (its body,
// each of its flights' ω0 and drag rate, each recording's bias correction; a new recording's
// from its own fit, prepared_recording.hpp). No growing stages, no restarts, no folds, no
// predictions, no trimmed ends: an estimate between two exact fits (fit_recording), which
// the class's projector marks as such.
#include <Eigen/Dense>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "fit/prepared_recording.hpp"
#include "fit/toss_fit.hpp"

namespace bookspin::fit {

/// One flight as the live fit fitted it.
struct LiveToss {
  std::string recording;              ///< its recording's name (PreparedRecording::name)
  int flight = 0;                     ///< 1..n within its recording
  int toss = 0;                       ///< 1..N in the set, the recordings in their canonical order
  double t_start = 0.0, t_end = 0.0;  ///< s, its recording's own time
  Eigen::Vector3d omega0 = Eigen::Vector3d::Zero();  ///< rad/s, phone frame, at t_start
  double drag_rate = 0.0;                            ///< 1/s (TossFit::drag_rate)
  /// TossFit's half periods (s): measured (sign changes about the fitted intermediate axis)
  /// and of the fitted motion; nullopt as there.
  std::optional<double> half_period_measured, half_period_fitted;
  double residual_rms = 0.0;  ///< rad/s
};

/// What a live fit ends at, and the start of the next.
struct LiveFit {
  Eigen::Vector3d ratios = Eigen::Vector3d::Ones();    ///< BodyEstimate::ratios
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();  ///< BodyEstimate::axes
  /// From the covariance alone (scaled by the residual variance and its correlation), not
  /// widened by folds as the exact fit's: smaller. nullopt where it cannot be computed.
  std::optional<Eigen::Vector3d> ratio_sigma, axis_sigma_deg;
  std::vector<LiveToss> tosses;  ///< in `toss` order
  int recordings = 0;
  /// Each recording's values as fitted, by name: the next live fit's start for it.
  struct Start {
    std::string name;
    std::vector<std::array<double, 4>> omega0;
    std::array<double, 3> e{0, 0, 0};
  };
  std::vector<Start> starts;
};

/// The live fit of `recordings` (one or more, each prepared once; any order: they are taken in
/// their canonical order, by name then source) from `start`, a previous live fit of some of
/// them: one solve of everything from its values, where it holds at least half of the flights
/// and the solve ends at a rigid body (rigid_bounds.hpp); else, and with no start, cold: the
/// exact fit's joint fit, grown over each flight from Euler's equations' body (joint_fit.hpp),
/// each flight's ω0 from its own fit. Throws
/// InputError for none, for one given twice (by source), when no recording has a flight, or
/// when the solve does not converge; Interrupted when settings.stop answers a signal.
LiveFit live_fit(const std::vector<const PreparedRecording*>& recordings, const LiveFit* start,
                 const FitSettings& settings = {});

}  // namespace bookspin::fit
