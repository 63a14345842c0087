// SIGINT, SIGTERM and SIGHUP at seeded random moments of every long command (render, sweep,
// fit, accuracy, flipcheck export, judge and league, explore, plot, simulate, export): whatever
// the moment, the stop contract holds (docs/outputs.md, "Signals"): exit status 128 + signal,
// the output folder as it was before, byte for byte, and no temporary left. signals_test.cpp
// signals at named stages; here the moment is drawn across the whole run, so a stage that polls
// no stop (a file formed after the last poll), or a window where a signal is lost or outputs are
// replaced, is met sooner or later. Each command runs once whole first: its outputs are the
// ones to keep, and its time sets the window, the signal coming within its first 80 % (from
// before the handlers are installed, where the default action ends it, 128 + signal and
// nothing written, to its last stages). A run that ends before its signal even so (a machine
// faster this time), or has begun to put its outputs in place by then (its work done: a
// loaded machine stretches the time from there to its exit), is counted, not judged; most must
// be signalled.
#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <fstream>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "fit/synthetic_recording.hpp"
#include "support/signal_runner.hpp"

namespace bookspin::cli {
namespace {

using namespace bookspin::test;
namespace fs = std::filesystem;

/// One command, run whole and then signalled. For a run of minutes, `window_s` is the window
/// instead, and the outputs kept are `first`'s or the caller's stand-ins.
struct LongCommand {
  LongCommand(std::string name_, std::vector<std::string> run_,
              std::vector<std::string> first_ = {}, double window = 0.0)
      : name(std::move(name_)), run(std::move(run_)), first(std::move(first_)), window_s(window) {}
  std::string name;
  std::vector<std::string> run;    ///< the run signalled (--force: it redoes its work)
  std::vector<std::string> first;  ///< makes the earlier outputs instead of `run` whole
  double window_s = 0.0;           ///< for a run of minutes: the signal comes within this
};

std::string signal_name(int signal) {
  return signal == SIGINT ? "SIGINT" : signal == SIGHUP ? "SIGHUP" : "SIGTERM";
}

std::string quoted_words(const std::vector<std::string>& words) {
  std::string line;
  for (const std::string& w : words) line += "'" + w + "' ";
  return line;
}

/// Signals `c.run` with each of SIGINT, SIGTERM and SIGHUP at seeded moments (`rounds` each)
/// and checks the contract against the folder `out` as the whole run (or `c.first`) left it.
void expect_every_moment_stops_cleanly(const LongCommand& c, const fs::path& out,
                                       std::mt19937_64& rng, int rounds) {
  double window = c.window_s;
  if (window > 0.0) {
    // The earlier outputs are the caller's stand-ins, or `first`'s.
    if (!c.first.empty()) {
      const CliResult first = run_bookspin(quoted_words(c.first));
      ASSERT_EQ(first.status, 0) << c.name << ": " << first.output;
    }
  } else if (!c.first.empty()) {
    const CliResult first = run_bookspin(quoted_words(c.first));
    ASSERT_EQ(first.status, 0) << c.name << ": " << first.output;
  } else {
    const auto start = std::chrono::steady_clock::now();
    const CliResult whole = run_bookspin(quoted_words(c.run));
    window = 0.8 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ASSERT_EQ(whole.status, 0) << c.name << ": " << whole.output;
    ASSERT_GT(window, 0.25) << c.name << ": make the run longer";
  }
  fs::create_directories(out);
  const auto before = snapshot(out);
  int signalled = 0, runs = 0;
  for (int signal : {SIGINT, SIGTERM, SIGHUP}) {
    for (int round = 0; round < rounds; ++round) {
      const double delay = std::uniform_real_distribution<double>(0.0, window)(rng);
      SCOPED_TRACE(c.name + ": " + signal_name(signal) + " after " + std::to_string(delay) +
                   " s of " + std::to_string(window / 0.8));
      const TimedRun run = signal_after(c.run, delay, signal, out);
      ++runs;
      // A run that ended first was quicker than the whole run measured (a machine whose load
      // fell meanwhile): the later moments are drawn within what it took.
      if (run.ended_first) {
        window = 0.8 * delay;
        continue;
      }
      ++signalled;
      EXPECT_EQ(run.status, 128 + signal) << run.err;
      EXPECT_EQ(temporaries(out), std::vector<std::string>{});
      EXPECT_EQ(snapshot(out), before) << "the earlier outputs changed";
    }
  }
  EXPECT_GE(3 * signalled, 2 * runs) << c.name << ": most runs ended before their signal";
}

void write_text(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
}

const std::string kFig09 = scene_path("fig09-matrix-unstable-x");

std::string flipcheck_scenario(const std::string& name) {
  return (fs::path(BOOKSPIN_SOURCE_DIR) / "scenes" / "flipcheck" / (name + ".toml")).string();
}

class RandomSignals : public ::testing::Test {
 protected:
  ScratchDir dir;
  fs::path out = dir.path() / "out";
  std::mt19937_64 rng{82};
};

TEST_F(RandomSignals, Render) {
  expect_every_moment_stops_cleanly(
      {"render",
       {"render", kFig09, "-o", out.string(), "--force", "--frames", "300", "--set",
        "render.preset=\"ultrafast\"", "--set", "render.width=320", "--set", "render.height=180"}},
      out, rng, 2);
}

TEST_F(RandomSignals, Sweep) {
  expect_every_moment_stops_cleanly(
      {"sweep",
       {"sweep", kFig09, "--vary", "time.dt=0.01:0.02:2", "--measure", "energy_drift", "-j", "2",
        "-o", out.string(), "--force", "--set", "time.frames=100000"}},
      out, rng, 2);
}

TEST_F(RandomSignals, PlotSimulateAndExport) {
  expect_every_moment_stops_cleanly({"plot",
                                     {"plot", kFig09, "-o", out.string(), "--force", "--set",
                                      "time.frames=100000", "--set", "time.steps_per_frame=100"}},
                                    out, rng, 1);
  expect_every_moment_stops_cleanly(
      {"simulate",
       {"simulate", kFig09, "--csv", (out / "fig09.csv").string(), "--set", "time.frames=100000",
        "--set", "time.steps_per_frame=100"}},
      out, rng, 1);
  expect_every_moment_stops_cleanly({"export",
                                     {"export", kFig09, "--gltf", "-o", out.string(), "--force",
                                      "--frames", "2000", "--set", "time.steps_per_frame=300"}},
                                    out, rng, 1);
}

TEST_F(RandomSignals, Accuracy) {
  // A full report takes minutes: stand-ins at the report's paths, which must keep their bytes,
  // and the signal within the first two seconds of 2·10⁷ steps a method.
  for (const char* name :
       {"-accuracy.csv", "-accuracy.png", "-work-precision.png", "-energy-vs-dt.png",
        "-turnovers.png", "-energy.png", "-energy.csv", "/accuracy-manifest.json"})
    write_text(out / (std::string("exact-unstable-x") + name), std::string("earlier ") + name);
  expect_every_moment_stops_cleanly({"accuracy",
                                     {"accuracy", scene_path("exact-unstable-x"), "-o",
                                      out.string(), "--flips", "100", "--dt", "0.001"},
                                     {},
                                     2.0},
                                    out, rng, 2);
}

// A stop once ignored: flipcheck export of the box at 20000 steps a frame ran on for seconds
// after SIGTERM, exited 0 and replaced its earlier outputs (its CSV was written after its last
// poll); the export now asks the stop while it writes.
TEST_F(RandomSignals, FlipcheckExportJudgeAndLeague) {
  const std::string box = flipcheck_scenario("mujoco-test-box");
  expect_every_moment_stops_cleanly({"flipcheck export",
                                     {"flipcheck", "export", box, "-o", out.string(), "--force",
                                      "--set", "time.steps_per_frame=5000"}},
                                    out, rng, 2);
  // The judge of that motion (2,500,001 rows, the exact motion at every row).
  const std::string motion = (out / "mujoco-test-box-exact.csv").string();
  const fs::path judged = dir.path() / "judged";
  expect_every_moment_stops_cleanly({"flipcheck judge",
                                     {"flipcheck", "judge", box, motion, "-o", judged.string(),
                                      "--force", "--set", "time.steps_per_frame=5000"}},
                                    judged, rng, 1);
  const fs::path league = dir.path() / "league";
  expect_every_moment_stops_cleanly({"flipcheck league",
                                     {"flipcheck", "league", box, "--methods", "all", "--force",
                                      "--set", "time.frames=10001", "-o", league.string()}},
                                    league, rng, 1);
}

// The stop contract per command, not per scenario: an export of every scenario of the kit
// stages them all and puts them in place only at its end, so a signal at any moment keeps every
// earlier file byte for byte. The earlier files are made different first (each JSON, CSV and
// manifest an "earlier" stand-in), so that a scenario finished before the signal and put in place
// shows: each scenario once placed its own files as it finished (8 files replaced 0.25 s in,
// 20 to 23 at 2 s). Planted back (a commit per scenario), this fails.
TEST_F(RandomSignals, FlipcheckExportOfManyScenariosKeepsEveryEarlierFile) {
  std::vector<std::string> run{"flipcheck", "export"};
  std::vector<std::string> names;
  for (const auto& entry :
       fs::directory_iterator(fs::path(BOOKSPIN_SOURCE_DIR) / "scenes" / "flipcheck"))
    if (entry.path().extension() == ".toml") {
      run.push_back(entry.path().string());
      names.push_back(entry.path().stem().string());
    }
  ASSERT_EQ(names.size(), 7u);
  run.insert(run.end(), {"-o", out.string(), "--force"});
  const auto start = std::chrono::steady_clock::now();
  const CliResult whole = run_bookspin(quoted_words(run));
  const double took =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_EQ(whole.status, 0) << whole.output;
  ASSERT_GT(took, 0.3) << "make the run longer";
  std::vector<std::string> files;
  for (const std::string& name : names)
    for (const std::string& file :
         {name + ".json", name + "-exact.csv", name + "/flipcheck-export-manifest.json"}) {
      ASSERT_TRUE(fs::is_regular_file(out / file)) << file;
      files.push_back(file);
    }
  const auto stand_ins = [&] {
    for (const std::string& file : files) write_text(out / file, "earlier " + file + "\n");
  };
  stand_ins();
  const auto before = snapshot(out);
  // Each run signalled at a seeded moment of the whole run's time, without waiting for its
  // outputs: either the stop came first (128 + signal, every earlier file as it was), or the run
  // had asked its last stop and put everything in place (exit 0, every file new): never some.
  std::uniform_real_distribution<double> moment(0.0, 0.9 * took);
  int stopped = 0, runs = 0;
  for (int signal : {SIGINT, SIGTERM, SIGHUP}) {
    for (int round = 0; round < 3; ++round) {
      const double delay = moment(rng);
      SCOPED_TRACE(signal_name(signal) + " after " + std::to_string(delay) + " s of " +
                   std::to_string(took));
      const TimedRun r = signal_after(run, delay, signal);
      ++runs;
      EXPECT_EQ(temporaries(out), std::vector<std::string>{});
      const auto now = snapshot(out);
      if (r.status == 128 + signal) {
        ++stopped;
        EXPECT_EQ(now, before) << "an earlier file was replaced by a stopped export";
        continue;
      }
      EXPECT_EQ(r.status, 0) << r.err;
      for (const std::string& file : files)
        EXPECT_NE(now.at(file), before.at(file)) << file << " not made by a whole export";
      stand_ins();
    }
  }
  EXPECT_GE(3 * stopped, 2 * runs) << "most runs ended before their signal";
}

TEST_F(RandomSignals, FitAndExplore) {
  fit::test::write_export(
      dir.path() / "toss",
      fit::test::make_recording(fit::test::phone_alone(), {{{1.0, 18.0, 1.2}, 1.3}}, 6),
      fit::test::Dialect::comma);
  write_text(dir.path() / "small.toml",
             "body.shape = \"phone\"\nrender.width = 320\nrender.height = 180\n");
  const std::string recording = (dir.path() / "toss").string();
  // The fit with its clips rendered.
  expect_every_moment_stops_cleanly({"fit",
                                     {"fit", recording, "--force", "--render", "--scene",
                                      (dir.path() / "small.toml").string(), "-o", out.string()}},
                                    out, rng, 1);
  write_text(dir.path() / "shell.html",
             "<!doctype html><title>explorer</title><!--BOOKSPIN_DATA-->\n");
  const std::string shell = (dir.path() / "shell.html").string();
  const fs::path page = dir.path() / "page";
  // Every scene of scenes/ on one page, their replays run.
  std::vector<std::string> explore{"explore"};
  for (const auto& entry : fs::directory_iterator(fs::path(BOOKSPIN_SOURCE_DIR) / "scenes"))
    if (entry.path().extension() == ".toml") explore.push_back(entry.path().string());
  explore.insert(explore.end(), {"--force", "--shell", shell, "-o", page.string()});
  expect_every_moment_stops_cleanly({"explore", explore}, page, rng, 1);
}

}  // namespace
}  // namespace bookspin::cli
