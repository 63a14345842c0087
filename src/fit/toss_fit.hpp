#pragma once
// The exact motion fitted to a recording's free flights (docs/phone-lab.md, "The fit"): the
// body's inertia in the phone frame up to scale (principal axes and two moment ratios), shared
// by every toss, and each toss's initial ω, by nonlinear least squares (Ceres) of the closed-form
// body-frame ω(t) of physics::ExactRotation (docs/physics.md §8) against the measured ω.
#include <Eigen/Dense>
#include <optional>
#include <string>
#include <vector>

#include "common/stop.hpp"
#include "fit/flights.hpp"
#include "fit/recording.hpp"
#include "physics/drag.hpp"

namespace bookspin::fit {

/// The body as the fit found it.
struct BodyEstimate {
  /// Principal moments over the largest, ascending: (I1/I3, I2/I3, 1).
  Eigen::Vector3d ratios = Eigen::Vector3d::Ones();
  /// Columns: the principal axes 1, 2, 3 (unit, phone frame, right-handed; each axis's sign
  /// is a convention: its largest phone component positive, the third then fixed by det +1).
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
  /// One standard deviation of each ratio (the third is exactly 1: σ 0) and of each axis's
  /// direction (degrees): the larger of the fit's covariance scaled by its residual variance
  /// and inflated for the residual's correlation from sample to sample, and the spread of the
  /// bodies fitted without each fold of tosses (a grouped jackknife over the tosses: what the
  /// model leaves out differs from toss to toss; docs/phone-lab.md, "Error bars"); nullopt
  /// where the covariance could not be computed (a fit that cannot tell them apart).
  std::optional<Eigen::Vector3d> ratio_sigma, axis_sigma_deg;
  bool moments_fixed = false;      ///< given by --moments: not fitted
  bool moments_determined = true;  ///< false: every toss stable, the moments poorly known
  std::vector<std::string> notes;  ///< what the reader should know (one line each)
};

/// One toss as fitted.
struct TossFit {
  Flight flight;
  Eigen::Vector3d omega0 = Eigen::Vector3d::Zero();  ///< rad/s, phone frame, at t_start
  std::optional<Eigen::Vector3d> omega0_sigma;       ///< rad/s, one standard deviation
  /// The air drag's rate r (1/s: the initial loss of |L| per second, docs/physics.md §21) under
  /// the fit's law, and its standard deviation; 0 and nullopt under --drag none.
  double drag_rate = 0.0;
  std::optional<double> drag_rate_sigma;
  /// Mean time between the measured ω's sign changes about the fitted intermediate axis (s);
  /// nullopt with fewer than two sign changes in the flight.
  std::optional<double> half_period_measured;
  /// The same mean over the flight's sample times for the fitted motion (s): its T/2 without
  /// drag; under drag the flips slow down (docs/physics.md §21), and this is their mean spacing
  /// within the flight. Where the fitted motion changes sign fewer than twice in the flight,
  /// its T/2 at the flight's middle; nullopt for a steady motion (no period).
  std::optional<double> half_period_fitted;
  /// The same for a prediction: the body fitted on the other tosses (or --moments), the drag
  /// rate the mean of theirs (0 without others), this toss's ω0 fitted on its first
  /// `predict_window` seconds alone; nothing after them is seen. nullopt with no other toss and
  /// no --moments, or where every other toss is stable (a body they cannot tell apart).
  /// nullopt (withheld, why in not_predicted) where its interval 2σ/T is over 25 % or the
  /// separatrix is within its inputs' σ (fit/prediction_sigma.hpp).
  std::optional<double> half_period_predicted;
  /// s: one σ of half_period_predicted: propagated from what it rests on (fit/
  /// prediction_sigma.hpp), widened by the calibration on the fit's other tosses (fit/
  /// prediction_calibration.hpp), at most 12.5 % of it; nullopt without a prediction, and for an
  /// uncalibrated one (too few other tosses to calibrate on: no interval is shown).
  std::optional<double> half_period_predicted_sigma;
  /// s: the σ propagated from the prediction's inputs alone, before the calibration; nullopt
  /// without a prediction.
  std::optional<double> half_period_propagated_sigma;
  /// How the prediction's interval is calibrated (calibration_words: "Student t on 5 other
  /// tosses", "uncalibrated: …"); "" without a prediction.
  std::string prediction_interval;
  /// s: the first seconds of the toss half_period_predicted was predicted from
  /// (FitSettings::predict_window); nullopt without a prediction.
  std::optional<double> predicted_window;
  /// Why there is no half_period_predicted (one phrase: "interval ±63 % (2σ/T, mostly the
  /// body's σ) from its first 0.2 s, over the ±25 % shown"); "" where there is one.
  std::string not_predicted;
  /// What half_period_predicted rests on: the number of other tosses the held-out body was
  /// fitted on and their flight time (s); 0 and 0 when it is the given --moments'. nullopt
  /// with no prediction. A body from too little flight (under 0.6 s in all) predicts poorly (a note
  /// says so).
  std::optional<int> predicted_from_tosses;
  std::optional<double> predicted_from_seconds;
  double residual_rms = 0.0;  ///< rad/s, RMS of |ω_measured − ω_fitted| over the flight
  /// residual_rms over the flight's mean measured |ω|: past kLargeResidualShare the summary
  /// says so first (fit_tables.hpp, fit_summary).
  double residual_share = 0.0;
  /// Fractional loss of the measured |L| (L = I ω with the fitted I) per second (1/s), from a
  /// straight line fitted to |L|(t): 0 for torque-free flight, > 0 under air drag.
  double L_decay = 0.0;
  bool stable = false;  ///< ω stays within 25° of the axis it circles: it cannot tell moments
  /// The residual is not the measurement's noise: somewhere in the flight (50 ms blocks) it is
  /// far above both the gyroscope's scatter at rest and the flight's typical residual, or it is
  /// over 5 % of |ω| throughout (docs/phone-lab.md, "Flags"); `flag` says what it looks like (a
  /// catch or throw inside the flight, a knock or the phone slipping, a body that flexes), one
  /// line, also in BodyEstimate::notes.
  bool poor_fit = false;
  std::string flag;
  /// Samples of the flight that read the gyroscope's range (fit/saturation.hpp): left out of
  /// the fit, or kept where fewer than 10 others would remain (the toss is then flagged, and
  /// its flag says so).
  int saturated = 0;
};

/// A note's remedy on the command line (BodyEstimate::notes); the page says it in its own terms
/// (fit_summary, Reader::page).
inline constexpr const char* kGiveMoments = "give --moments I1,I2,I3";

/// What the fit is given besides the flights.
struct FitSettings {
  /// Principal moments given by --moments (any scale, any order): fixed, not fitted.
  std::optional<Eigen::Vector3d> moments;
  double predict_window = 0.2;  ///< s, the start of a toss that half_period_predicted sees
  /// Each flight's ends trimmed by the fitted motion's residual and the flights fitted again
  /// (fit/flight_trim.hpp): fit_report asks it for the flights it finds (the command line and
  /// the page alike); flights given by hand are fitted as given.
  bool trim_ends = false;
  /// The air drag's law fitted with each toss (docs/physics.md §21; docs/phone-lab.md, "Drag":
  /// linear by default, chosen by measurement), its rate one more parameter per toss.
  physics::DragLaw drag = physics::DragLaw::linear;
  /// Polled at every iteration of every solve (a few milliseconds apart): a signal stops the fit
  /// with Interrupted (docs/outputs.md, "Signals"). Empty: never stops.
  StopPoll stop;
};

struct FitResult {
  /// The flights fitted and the stretches dropped.
  FlightSearch search;
  /// The recordings fitted as one (GyroRecording::parts, one or more), each with its bias
  /// (docs/phone-lab.md, "The bias"): its still rest's mean, corrected by its own flights
  /// (RecordingPart::bias_correction, with two or more tosses), or with no rest fitted from them.
  std::vector<RecordingPart> parts;
  physics::DragLaw drag = physics::DragLaw::linear;  ///< the law the rates are of
  BodyEstimate body;
  std::vector<TossFit> tosses;  ///< one per flight, in order
  /// rad/s: the range the gyroscope saturated at, found in the samples (fit/saturation.hpp),
  /// or nullopt.
  std::optional<double> saturation_range;
};

/// Fits `search`'s flights of `recording` (pooled: pool_recordings, one recording or more). A
/// recording with no still rest whose bias fitted from its flights is consistent with zero
/// (bias_significant false) is fitted again with it held at zero (RecordingPart::
/// bias_not_applied keeps it, bias_fitted_sigma its σ).
/// Throws InputError naming the recording when there is no flight ("no free flight found", with
/// why each stretch was dropped) or when the solver cannot fit them; Interrupted when
/// settings.stop answers a signal; std::logic_error for a recording not pooled.
FitResult fit_recording(const GyroRecording& recording, const FlightSearch& search,
                        const FitSettings& settings = {});

/// The fitted exact body-frame ω (rad/s, phone frame) of toss `toss` at time `t` (s, the
/// recording's time), its drag included (docs/physics.md §21).
Eigen::Vector3d fitted_omega(const FitResult& fit, int toss, double t);

/// The measured ω (rad/s, phone frame, bias removed) of toss `toss`'s samples, and their times.
void measured_omega(const GyroRecording& recording, const FitResult& fit, int toss,
                    std::vector<double>& t, std::vector<Eigen::Vector3d>& omega);

}  // namespace bookspin::fit
