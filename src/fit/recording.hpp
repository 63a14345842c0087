#pragma once
// A gyroscope recording read into memory: a phyphox export (its folder, its `Raw Data.csv`, or
// a zip of the folder; every CSV dialect phyphox writes; the pauses of `meta/time.csv`) or a
// plain CSV `t,wx,wy,wz` (docs/phone-lab.md, "The recording").
#include <Eigen/Dense>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fit/rest.hpp"

namespace bookspin::fit {

/// One recording among those fitted as one body (pool_recordings; a recording alone is a pool
/// of one): its samples first … last of the pooled recording, at its own time + t_offset, and
/// its own gyroscope: the range it states, the still rest it was measured on and its bias. The
/// one place a recording's bias is held, from its rest to the fit's correction.
struct RecordingPart {
  std::string name;         ///< the recording's own name
  std::string source;       ///< its file
  double t_offset = 0.0;    ///< s added to its times
  double t_start = 0.0;     ///< s: its first sample's pooled time
  int first = 0, last = 0;  ///< its samples in the pooled recording (inclusive)
  /// rad/s, phone frame: the bias its samples carry as measured (its still rest's mean; 0
  /// without one), and its still rest (fit/rest.hpp, in its own times).
  Eigen::Vector3d bias = Eigen::Vector3d::Zero();
  Rest rest;
  /// rad/s: its gyroscope's stated range (GyroRecording::gyroscope_range).
  std::optional<double> gyroscope_range;
  /// rad/s, phone frame, set by the fit (fit/toss_fit.hpp): its own flights' correction of its
  /// bias (two or more flights; within Rest::bound() where it has a still rest), and with
  /// no rest the correction's standard error.
  Eigen::Vector3d bias_correction = Eigen::Vector3d::Zero();
  std::optional<Eigen::Vector3d> bias_fitted_sigma;
  /// rad/s, phone frame, set by the fit with no still rest: the bias its flights gave where it
  /// was consistent with zero (fit/toss_fit.hpp, bias_significant) and so not applied
  /// (bias_correction is then 0, bias_fitted_sigma its σ); nullopt where it was applied.
  std::optional<Eigen::Vector3d> bias_not_applied;
  /// rad/s, phone frame: the bias removed in flight, bias + bias_correction.
  Eigen::Vector3d bias_in_flight() const { return bias + bias_correction; }
};

/// One recording: the body-frame angular velocity as the gyroscope measured it, in the phone's
/// own axes (x to the right of the screen, y up the screen, z out of it).
struct GyroRecording {
  std::string name;    ///< the recording's name (folder, zip or file stem), file-safe
                       ///< (common/file_name.hpp: any alphabet, NFC)
  std::string source;  ///< the file the samples came from, for messages
  /// The file read (a CSV or a zip), made canonical (absolute, symlinks resolved): one file
  /// however it was spelled; empty for samples given as numbers.
  std::filesystem::path file;
  std::vector<double> t;               ///< seconds of experiment time, strictly increasing
  std::vector<Eigen::Vector3d> omega;  ///< rad/s, phone frame, as measured (bias included)
  /// Experiment times (s) at which the recording was paused: no flight spans one.
  std::vector<double> pauses;
  /// rad/s: the gyroscope's range as the export states it (phyphox's `meta/device.csv`, row
  /// "gyroscope Range": Android's Sensor.getMaximumRange(), in rad/s for a gyroscope); nullopt
  /// where nothing states it (phyphox on iOS, a plain CSV). fit/saturation.hpp uses it.
  std::optional<double> gyroscope_range;
  /// The recordings it is made of (pool_recordings: one or more), each with its bias; empty for
  /// a recording as read, which the finder and the fit do not take before it is pooled.
  std::vector<RecordingPart> parts;
};

/// Reads `path`: a phyphox export folder (holding `Raw Data.csv`, optionally `meta/time.csv` and
/// `meta/device.csv`), a `Raw Data.csv` (its folder's `meta/` read too), a `.zip` of such a
/// folder, or a plain CSV whose header is `t,wx,wy,wz` (rad/s). Throws InputError, one line
/// naming the file, row (1-based line) and column: no such file, not a gyroscope recording (the
/// header), a text or NaN cell, a row with too few cells, time not increasing, fewer than 10
/// samples, a stated range that is not a number.
GyroRecording read_recording(const std::filesystem::path& path);

/// The samples of CSV `text` (as read_recording(); `file` names it in messages, `name` is
/// the recording's). Throws InputError.
GyroRecording parse_gyro_csv(std::string_view text, const std::string& file,
                             const std::string& name);

/// A recording given as numbers rather than read (the Python module's (t, omega) arrays): t (N,
/// s, strictly increasing) and ω (N, rad/s, phone frame, bias included), no pauses, named
/// `name` (made file-safe) and `name` in messages. Throws InputError "NAME: t[I]: …" for a time
/// or ω that is not finite or a time that does not increase, and for unequal lengths or fewer
/// than 10 samples.
GyroRecording samples_recording(const std::string& name, std::vector<double> t,
                                std::vector<Eigen::Vector3d> omega);

/// s: the longest median step between samples a gyroscope recording of a hand toss may have (a
/// phone samples every 1–40 ms; 2 Hz is no recording of a flip).
inline constexpr double kMaxSampleStep = 0.5;

/// Why times `t` (s, increasing) are no gyroscope's: their median step over kMaxSampleStep,
/// naming the unit (ms, µs or ns) that puts it within 0.1–100 ms ("the samples lie 10.03 s
/// apart (the median step), … are the times in ms? …"); "" where they are plausible.
/// `stated`: the seconds in one unit of the times as written, where a header named their unit
/// (1e-3 for "t (ms)"): the likely unit is then judged on the numbers as written (µs under a
/// "t (ms)" header whose numbers are µs), and the message says what the header stated.
std::string time_unit_cause(const std::vector<double>& t, double stated = 1.0);

/// The PAUSE events' experiment times of a phyphox `meta/time.csv` `text`. Throws InputError.
std::vector<double> parse_time_csv(std::string_view text, const std::string& file);

/// rad/s: the gyroscope's range that a phyphox `meta/device.csv` `text` states (its
/// `"property","value"` rows, any of phyphox's separators; the row "gyroscope Range", as
/// phyphox for Android writes it); nullopt when no such row, or its value is empty or "null"
/// (no gyroscope). Throws InputError naming the file, line and key for a value that is not a
/// positive finite number.
std::optional<double> parse_device_csv(std::string_view text, const std::string& file);

}  // namespace bookspin::fit
