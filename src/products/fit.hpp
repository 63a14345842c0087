#pragma once
// The phone-toss lab's product (`bookspin fit`): a gyroscope recording's tosses fitted with the
// exact motion, as two CSVs and a chart per toss, with its manifest (docs/outputs.md, "The
// fit"; docs/phone-lab.md). The physics is the fit stage's, the chart the charts stage's.
#include <Eigen/Dense>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
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
  /// OUT/<recording>-toss<N>.toml, each toss as a scene (products/fit_scene.hpp), and
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
  std::filesystem::path recording;  ///< a phyphox export (folder, Raw Data.csv, zip) or t,wx,wy,wz
  std::filesystem::path out_dir;
  std::vector<std::pair<double, double>> tosses;     ///< --tosses by hand (s); empty: found
  std::optional<Eigen::Vector3d> moments;            ///< --moments: fixed
  physics::DragLaw drag = physics::DragLaw::linear;  ///< --drag (fit::FitSettings::drag)
  int width = 1400, height = 700;                    ///< each chart's pixels
  std::optional<FitRender> render;                   ///< --render: a clip of each toss
  /// Polled before each clip frame and while its encoders finish (clip::ClipRequest): a signal
  /// throws Interrupted, nothing put in place.
  StopPoll stop_signal;
  cache::Freshness freshness;
};

/// (recording, tosses, moments[, render]) => OUT/<recording>-fit.csv + -fit-body.csv +
/// -toss<N>.png + -toss<N>.toml + -toss<N>-measured.csv [+ -toss<N>.mp4] + manifest.
/// Reads the recording (fit::read_recording), finds its flights (or takes the given ones),
/// fits them (fit::fit_recording), draws each toss (charts::toss_image), makes each toss's
/// scene and measured ω (fit_scene.hpp; none, and a line in the summary saying why, where the
/// fitted moments make no body) and writes the files, unless the manifest says they are up to
/// date; with `render`, also renders each toss's clip (products/fit_clip.hpp) into a scratch
/// folder of the run and puts it in place with the rest, all or nothing. `summary`, when
/// given, receives fit::fit_summary's lines of a made fit.
/// Throws InputError (the recording, a toss, no flight; with `render` a bad scene file or
/// --slow-motion, and a fit whose every toss is stable without --moments: no moments to
/// show), OutputError, Interrupted (a signal while the clips are made), and what
/// clip::render_clip throws (render::RenderError, video::EncoderError): then nothing is put in
/// place and the earlier outputs and manifest stay.
cache::Outcome make_fit(const FitJob& job, std::vector<std::string>* summary = nullptr);

}  // namespace bookspin::products
