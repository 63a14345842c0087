#pragma once
// A recording's fit as one value (docs/phone-lab.md): the flights found (or given), the fit,
// its tables and summary lines, and each toss's chart data and scene values. Made by
// fit_report(), a pure stage (no file written, no picture drawn); presented by the fit product
// (products/fit.hpp: CSVs, charts, scenes, clips), the explorer's Phone-toss lab
// (web/fit_bindings.cpp) and the Python module (python/fit.cpp) alike.
#include <Eigen/Dense>
#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "common/stop.hpp"
#include "fit/fit_options.hpp"
#include "fit/fit_tables.hpp"
#include "fit/recording.hpp"
#include "fit/toss_fit.hpp"
#include "fit/toss_scene.hpp"
#include "physics/polhode.hpp"

namespace bookspin::fit {

/// What a fit is asked for besides the recording.
struct FitRequest {
  /// --tosses by hand, [t_start, t_end] s each (parse_toss_ranges, hand_flights); empty: found
  /// (find_flights).
  std::vector<std::pair<double, double>> tosses;
  FitSettings settings;                  ///< --moments, --drag
  Reader reader = Reader::command_line;  ///< whose terms the summary's remedies are in
};

/// How an error line names the flights by hand (parse_toss_ranges, hand_flights): the command
/// line's option, the explorer lab's field ("Flights by hand (s)") or Python's argument
/// (fit_option_names).
inline const char* tosses_name(Reader reader) { return fit_option_names(reader).tosses; }

/// What the finder's refusal ("no free flight found", throw_no_flight) offers, in the door's
/// terms: the flights named by hand.
inline const char* hand_flights_remedy(Reader reader) {
  return reader == Reader::page ? "name the flights in the \"Flights by hand (s)\" field "
                                  "(START:END, seconds)"
         : reader == Reader::python
             ? "name the flights by hand with tosses=[(START, END), ...] (seconds)"
             : "name the flights by hand with --tosses START:END[,START:END...] (seconds)";
}

/// One toss's chart as values (charts::toss_image draws it; docs/phone-lab.md, "Reading the
/// result").
struct TossChart {
  int toss = 0;  ///< 0-based
  /// The toss's own recording (RecordingPart::name: of several pooled, the one it was thrown
  /// in) and the seconds its own clock is behind the pooled one (RecordingPart::t_offset): every
  /// time below is on its own clock, as its recording's file has it.
  std::string recording;
  double t_offset = 0.0;
  /// The flight's samples: t (N, s, its own recording's time), the measured ω (N, rad/s, phone
  /// frame, bias removed: measured_omega) and the fitted ω at the same times (fitted_omega).
  std::vector<double> t;
  std::vector<Eigen::Vector3d> measured, fitted;
  /// The fitted ω every millisecond of the flight (s on its own clock, rad/s, phone frame): the
  /// chart's lines.
  std::vector<double> curve_t;
  std::vector<Eigen::Vector3d> curve;
  /// The fitted motion's flips (s): where its ω about the fitted intermediate axis changes sign
  /// between two of curve_t, linearly interpolated; none for a stable toss, whose wobble
  /// changes that sign without flipping.
  std::vector<double> flips;
  /// The momentum sphere (docs/physics.md §15) in the fitted principal frame (axes 1, 2, 3 by
  /// ascending moment): the moment ratios (I1/I3, I2/I3, 1), each axis's label ("2 · phone
  /// -x": the phone axis it lies nearest, signed), the fitted exact motion's L/|L| over one
  /// period of ω (721 points; over the flight when the motion has no period), and the measured
  /// L/|L| of each sample with ω ≠ 0 (L = I ω with the fitted ratios and axes).
  Eigen::Vector3d moments = Eigen::Vector3d::Ones();
  std::array<std::string, 3> axis_labels;
  std::vector<Eigen::Vector3d> orbit, measured_L;
  /// The polhode family and the separatrices of `moments` (physics::polhode_family), the
  /// sphere's background: the chart is drawn from these values alone.
  std::vector<physics::Polhode> polhodes;
};

/// One toss of the report.
struct TossReport {
  TossChart chart;
  std::optional<TossScene> scene;  ///< nullopt where the fitted moments make no body
  /// With a scene: its file's text (toss_scene_text) and its measured ω's CSV text
  /// (toss_measured_csv), as the fit product writes them; empty without.
  std::string scene_text, measured_csv;
};

/// The fit of one recording.
struct FitReport {
  std::string recording;  ///< GyroRecording::name: it names the outputs
  std::string source;     ///< the file the samples came from, for messages
  FitResult result;
  /// The two tables as the command writes them (csv_text): OUT/<recording>-fit.csv, a row a
  /// toss (fit_toss_csv), and OUT/<recording>-fit-body.csv, the body's row (fit_body_csv).
  std::string toss_csv, body_csv;
  /// fit_summary's lines, then kNoSceneLine where the fitted moments make no body
  std::vector<std::string> summary;
  std::vector<std::string> dropped;  ///< fit_dropped_lines: every stretch dropped, a line each
  std::vector<TossReport> tosses;    ///< one per toss, in order
  bool has_scenes = false;           ///< every toss has its scene (toss_book made a book)
};

/// The summary's last line where the fitted moments make no body (toss_book: the triangle
/// inequality broken, or a body too flat for a scene): why no toss has a scene to play, for the
/// command line and the page alike.
inline constexpr const char* kNoSceneLine =
    "no scene of the tosses: the fitted moments break the triangle inequality (I1 + I2 < I3, "
    "where every rigid body has I1 + I2 ≥ I3) or make a body too flat for a scene";

/// Toss `toss` (0-based) of `fit` of `recording` as its chart's values.
TossChart toss_chart(const GyroRecording& recording, const FitResult& fit, int toss);

/// Finds `recording`'s flights (or takes request.tosses), fits them (fit_recording) and makes
/// every value the doors present. `stop` is polled before the fit, at every iteration of its
/// solves (FitSettings::stop, unless the request has its own) and before each toss's values
/// (docs/outputs.md, "Signals"). `recording` is pooled (pool_recordings: one or more). Throws
/// InputError (a toss given by hand, or tosses by hand with a pooled recording, no flight, a fit
/// the solver cannot make: see hand_flights and fit_recording) and Interrupted.
FitReport fit_report(const GyroRecording& recording, const FitRequest& request,
                     const StopPoll& stop = {});

}  // namespace bookspin::fit
