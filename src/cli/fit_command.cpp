// `bookspin fit`: the phone-toss lab (docs/phone-lab.md): a gyroscope recording's free flights
// found and fitted with the exact motion.
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/interrupt.hpp"
#include "cli/subcommand.hpp"
#include "common/errors.hpp"
#include "fit/fit_options.hpp"
#include "fit/pool.hpp"
#include "fit/report.hpp"
#include "products/fit.hpp"

namespace bookspin::cli {
namespace {

struct FitOptions {
  std::vector<std::string> recordings;
  std::string out_dir = "out";
  std::string tosses;           ///< "a:b,c:d" (s)
  std::string moments;          ///< "I1,I2,I3"
  std::string drag = "linear";  ///< --drag: none | linear | quadratic
  bool render = false;          ///< --render: a clip of each toss
  std::string scene_file;       ///< --scene: the clips' body and render keys
  double slow_motion = 4.0;
  bool force = false;
  bool verify = false;
  bool verbose = false;  ///< --verbose: every dropped stretch a line
};

/// Fits OUT/<recording>-fit.csv, -fit-body.csv and a chart per toss (with --render a clip per
/// toss); prints what was kept, dropped and found.
int fit_command(const FitOptions& options) {
  products::FitJob job;
  job.out_dir = options.out_dir;
  // Each option read and judged as every door reads it (fit/fit_options.hpp).
  const fit::FitOptionNames names = fit::fit_option_names(fit::Reader::command_line);
  job.request.tosses = fit::parse_toss_ranges(options.tosses, names.tosses);
  if (!options.moments.empty())
    job.request.settings.moments = fit::parse_moments(options.moments, names.moments);
  job.request.settings.drag = fit::parse_drag_option(options.drag, names.drag);
  if (!options.render && !options.scene_file.empty())
    throw InputError("--scene: only with --render (it gives the clips' body and render keys)");
  // Read after the options are checked, as every input: a bad option is named first.
  // One recording or several, fitted as one body: a pool (of one).
  std::vector<fit::GyroRecording> recordings;
  for (const std::string& path : options.recordings)
    recordings.push_back(fit::read_recording(path));
  job.recording = fit::pool_recordings(recordings);
  if (options.render) {
    products::FitRender render;
    if (!options.scene_file.empty()) render.scene_file = options.scene_file;
    render.slow_motion = options.slow_motion;
    job.clips = products::fit_clips(render);
  }
  job.verbose = options.verbose;
  job.freshness = {options.force, options.verify, remake_note};
  job.stop_signal = stop_poll();
  std::vector<std::string> summary;
  const cache::Outcome outcome = products::make_fit(job, &summary);
  if (outcome == cache::Outcome::up_to_date)
    std::cout << "up to date: "
              << (options.recordings.size() == 1 ? options.recordings.front()
                                                 : job.recording.source)
              << std::endl;
  for (const std::string& line : summary) std::cout << line << '\n';
  return kExitOk;
}

}  // namespace

Subcommand add_fit(CLI::App& cli) {
  const auto stored = std::make_shared<FitOptions>();
  FitOptions& options = *stored;
  CLI::App* cmd = cli.add_subcommand(
      "fit",
      "Fit the exact motion to a phone toss's gyroscope recording (phyphox) into "
      "OUT/<recording>-fit.csv");
  cmd->add_option("RECORDING", options.recordings,
                  "A phyphox export (folder, Raw Data.csv or zip) or a t,wx,wy,wz CSV (rad/s); "
                  "several: recordings of one body fitted together (docs/phone-lab.md, \"A "
                  "class's recordings\"), into OUT/<first>-and-<N-1>-more-fit.csv")
      ->required();
  add_out_option(cmd, options.out_dir, "Output directory");
  cmd->add_option("--tosses", options.tosses,
                  "The flights by hand, START:END seconds, comma-separated (default: found)");
  cmd->add_option("--moments", options.moments,
                  "Principal moments I1,I2,I3 (any scale): fixed instead of fitted");
  cmd->add_option("--drag", options.drag,
                  "Air drag fitted per toss: none, linear (torque -c L) or quadratic "
                  "(-k|L| L); docs/phone-lab.md, \"Drag\"")
      ->capture_default_str();
  cmd->add_flag("--render", options.render,
                "Also a clip of each toss, OUT/<recording>-toss<N>.mp4: the body turning as the "
                "phone turned (its measured ω integrated) beside the fitted exact motion");
  cmd->add_option("--scene", options.scene_file,
                  "With --render: a scene file whose body and render.* keys the clips take "
                  "(default: the phone preset)");
  cmd->add_option("--slow-motion", options.slow_motion,
                  "With --render: the clips play the flight this many times slower")
      ->capture_default_str()
      ->check(CLI::Range(products::kMinSlowMotion, products::kMaxSlowMotion));
  cmd->add_flag("--verbose", options.verbose,
                "List every stretch of motion dropped, a line each (the summary counts those "
                "too slow for a flight in one line)");
  add_freshness_flags(cmd, options.force, options.verify, "OUT/<recording>/fit-manifest.json");
  return {cmd, [stored] { return fit_command(*stored); }};
}

}  // namespace bookspin::cli
