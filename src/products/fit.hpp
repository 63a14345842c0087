#pragma once
// The phone-toss lab's product (`bookspin fit`): a gyroscope recording's tosses fitted with the
// exact motion, as two CSVs and a chart per toss, with its manifest (docs/outputs.md, "The
// fit"; docs/phone-lab.md). The physics is the fit stage's, the chart the charts stage's.
#include <Eigen/Dense>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "cache/freshness.hpp"
#include "common/csv_writer.hpp"
#include "common/stop.hpp"
#include "fit/fit.hpp"
#include "products/fit_clip.hpp"

namespace bookspin::products {

/// Every path a fit of one recording into OUT writes.
struct FitLayout {
  std::filesystem::path csv;                ///< OUT/<recording>-fit.csv: one row per toss
  std::filesystem::path body_csv;           ///< OUT/<recording>-fit-body.csv: the body's one row
  std::vector<std::filesystem::path> pngs;  ///< OUT/<recording>-toss<N>.png, N = 1, 2, ...
  std::filesystem::path manifest;           ///< OUT/<recording>/fit-manifest.json
  /// OUT/<recording>-toss<N>.toml, each toss as a scene (fit::toss_scene_text), and
  /// OUT/<recording>-toss<N>-measured.csv, the measured ω it names; empty where the fitted
  /// moments make no body (toss_book).
  std::vector<std::filesystem::path> scenes, measured;
  /// With --render: OUT/<recording>-toss<N>.<format>, toss by toss, each in render.formats'
  /// order (products/fit_clip.hpp); empty without.
  std::vector<std::filesystem::path> videos;
  std::vector<std::filesystem::path> outputs() const;
};

/// The layout of recording `name`'s fit of `tosses` tosses in `out_dir`, with the tosses'
/// scenes or without, and a video of each toss in each of `video_formats` (--render's
/// render.formats; none without). No I/O.
FitLayout fit_layout(const std::filesystem::path& out_dir, const std::string& name, int tosses,
                     bool scenes = true, const std::vector<std::string>& video_formats = {});

/// What `bookspin fit` asks for.
struct FitJob {
  /// The recording, read by the command (fit::read_recording: a phyphox export or
  /// t,wx,wy,wz) and pooled (fit::pool_recordings: one or more): its name names the outputs,
  /// its samples are what they depend on.
  fit::GyroRecording recording;
  std::filesystem::path out_dir;
  fit::FitRequest request;         ///< --tosses by hand (empty: found), --moments, --drag
  int width = 1280, height = 640;  ///< each chart's pixels
  /// --verbose: the summary lists every stretch the finder dropped (fit::fit_dropped_lines),
  /// after its counted line; the files are the same.
  bool verbose = false;
  /// --render: a clip of each toss, its scene made by the command (fit_clip_scene: a bad scene
  /// file or --slow-motion is refused before anything is made).
  std::optional<FitClips> clips;
  /// Polled before the fit, each toss's values and each clip frame, and while the clips'
  /// encoders finish (clip::ClipRequest): a signal throws Interrupted, nothing put in place.
  StopPoll stop_signal;
  cache::Freshness freshness;
};

/// (recording, tosses, moments[, clips]) => OUT/<recording>-fit.csv + -fit-body.csv +
/// -toss<N>.png + -toss<N>.toml + -toss<N>-measured.csv [+ -toss<N>.mp4] + manifest.
/// Unless the manifest says they are up to date: makes the fit's report (fit::fit_report: the
/// flights found or given, the fit, each toss's chart data and scene values), draws each toss
/// (charts::toss_image), writes its scene and measured ω (the report's, fit/toss_scene.hpp; none,
/// and a line in the summary saying why, where the fitted moments make no body) and the tables;
/// with `clips`, also renders each toss's clip (products/fit_clip.hpp) into a scratch folder of the
/// run; all of it put in place together or not at all. `summary`, when given, receives the
/// report's summary lines of a made fit and what was written.
/// Throws InputError (a toss, no flight; with `clips` a fit whose every toss is stable without
/// --moments: no moments to show), OutputError,
/// Interrupted (a signal), and what clip::render_clip throws (render::RenderError,
/// video::EncoderError): then nothing is put in place and the earlier outputs and manifest stay.
cache::Outcome make_fit(const FitJob& job, std::vector<std::string>* summary = nullptr);

}  // namespace bookspin::products
