// SIGINT, SIGTERM and SIGHUP stop every command that writes (export, render in its encoders'
// finishing passes, sweep, accuracy, plot, simulate, explore, gallery, fit --render) within half
// a CPU second, with exit status 130, 143 or 129, the previous outputs and their manifest
// byte-identical and no temporary left (docs/outputs.md, "Signals"). Each signal comes at a named
// stage of the run (the command line's test hooks, src/cli/interrupt.hpp): for a long loop the
// test signals on the line of the stage polled just before the loop starts ("gif palette pass"
// before the GIF's second pass, "sweep point" before a point's steps, "accuracy runs" before a
// run's steps), so the time to exit measures how often the loop itself polls; a stage too short
// to catch in flight is held at its first poll until the signal has arrived.
#include <gtest/gtest.h>
#include <signal.h>

#include <algorithm>
#include <fstream>
#include <ostream>
#include <sstream>

#include "fit/synthetic_recording.hpp"
#include "support/signal_runner.hpp"

namespace bookspin::cli {
namespace {

using namespace bookspin::test;  // the shared runner (tests/support)

namespace fs = std::filesystem;

// From the signal to the exit, in the CPU seconds the program spends (its polls bound them
// whatever the machine's load; the wall-clock seconds grow with it: 1.15–1.36 s for the export's
// CSV on the 2-core machine at a load of 11, 2026-11-27). The loops poll every frame, packet or
// 64 physics steps (milliseconds); the rest is unwinding and removing the temporaries. Without
// the polls, seconds (the stage runs to its end) or never (exit 0). Half a CPU second leaves
// room for the unwinding; the wall clock is bounded only loosely, against a program that waits.
constexpr double kMaxCpuSecondsToExit = 0.5;
constexpr double kMaxSecondsToExit = 10.0;

constexpr const char* kReport = "BOOKSPIN_TEST_REPORT_STAGES";
constexpr const char* kHold = "BOOKSPIN_TEST_HOLD_AT";

std::vector<std::string> words(std::initializer_list<std::string> list) { return list; }

std::vector<std::string> operator+(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

std::string signal_name(int signal) {
  return signal == SIGINT ? "SIGINT" : signal == SIGHUP ? "SIGHUP" : "SIGTERM";
}

/// Runs `args` signalled by `signal` at `stage` (held there with kHold) and checks the contract:
/// status 128 + signal, out within kMaxCpuSecondsToExit (and kMaxSecondsToExit), `out` as `before`,
/// no temporary there.
void expect_stopped_cleanly(const std::vector<std::string>& args, const char* hook,
                            const std::string& stage, int signal, const fs::path& out,
                            const std::map<std::string, std::string>& before) {
  const SignalledRun run = signal_at_stage(args, hook, stage, signal);
  ASSERT_TRUE(run.reached) << "stage '" << stage << "' never came (status " << run.status << ")\n"
                           << run.err;
  std::cout << "[ timing   ] " << signal_name(signal) << " at " << stage << ": exit after "
            << run.to_exit_s << " s, " << run.cpu_to_exit_s << " CPU s\n";
  EXPECT_EQ(run.status, 128 + signal) << run.err;
  EXPECT_GE(run.cpu_to_exit_s, 0.0) << stage << ": its CPU time not read";
  EXPECT_LT(run.cpu_to_exit_s, kMaxCpuSecondsToExit) << stage;
  EXPECT_LT(run.to_exit_s, kMaxSecondsToExit) << stage;
  EXPECT_EQ(temporaries(out), std::vector<std::string>{});
  EXPECT_EQ(snapshot(out), before) << "the previous outputs changed";
}

const std::string kFig09 = scene_path("fig09-matrix-unstable-x");

// The league judges every method's motion, tens of milliseconds each (the exact motion at every
// row, 100,000 rows: the box run 200 times its scenario's 500 steps, so that the judging outlasts
// the signal's way in), and asks between them: a signal on the line of the first judgement stops
// it at the next, within the second, nothing written. Without the poll the judging runs on.
class LeagueSignal : public ::testing::TestWithParam<int> {};

TEST_P(LeagueSignal, StopsBetweenJudgementsAndWritesNothing) {
  const ScratchDir dir;
  const fs::path out = dir.path() / "out";
  fs::create_directories(out);
  const std::string scenario =
      (fs::path(BOOKSPIN_SOURCE_DIR) / "scenes" / "flipcheck" / "mujoco-test-box.toml").string();
  expect_stopped_cleanly(words({"flipcheck", "league", scenario, "--methods", "all", "--set",
                                "time.frames=10001", "-o", out.string()}),
                         kReport, "flipcheck judge", GetParam(), out, {});
}

INSTANTIATE_TEST_SUITE_P(Signals, LeagueSignal, ::testing::Values(SIGINT, SIGTERM, SIGHUP),
                         [](const auto& info) { return signal_name(info.param); });

// `flipcheck export` of the box at 20000 steps a frame (10^6 steps): the exact motion's rows
// and then its CSV, seconds of text, are each asked every 4096 rows. A signal while the CSV is
// spelled stops it within the second with 128 + signal, the previous export as it was (it ran on
// for 1.9 s, exited 0 and replaced both files, when only the exact motion's loop asked).
class FlipcheckExportSignal : public ::testing::TestWithParam<int> {};

TEST_P(FlipcheckExportSignal, StopsWhileTheExactMotionIsWrittenAndKeepsThePreviousFiles) {
  const ScratchDir dir;
  const fs::path out = dir.path() / "out";
  const std::string scenario =
      (fs::path(BOOKSPIN_SOURCE_DIR) / "scenes" / "flipcheck" / "mujoco-test-box.toml").string();
  const CliResult first = run_bookspin("flipcheck export " + scenario + " -o " + out.string());
  ASSERT_EQ(first.status, 0) << first.output;
  const auto before = snapshot(out);
  ASSERT_EQ(before.size(), 4u);  // the JSON, the CSV, the scenario's folder and its manifest
  for (const char* stage : {"flipcheck exact motion", "flipcheck export csv"})
    expect_stopped_cleanly(words({"flipcheck", "export", scenario, "--force", "--set",
                                  "time.steps_per_frame=20000", "-o", out.string()}),
                           kReport, stage, GetParam(), out, before);
}

INSTANTIATE_TEST_SUITE_P(Signals, FlipcheckExportSignal, ::testing::Values(SIGINT, SIGTERM, SIGHUP),
                         [](const auto& info) { return signal_name(info.param); });

// The export's frame loop polls every frame: a signal in a long export stops it before the
// file is written, and the previous .glb and its manifest stay. The second run is --force: an
// export is cached, and this one must reach its frames whatever the manifest says.
class ExportSignal : public ::testing::TestWithParam<int> {};

TEST_P(ExportSignal, StopsTheFrameLoopAndKeepsThePreviousGlb) {
  const ScratchDir dir;
  const fs::path out = dir.path() / "out";
  const std::vector<std::string> common = words({"export", kFig09, "--gltf", "-o", out.string()});
  const CliResult first =
      run_bookspin("export " + kFig09 + " --gltf -o " + out.string() + " --frames 10");
  ASSERT_EQ(first.status, 0) << first.output;
  const auto before = snapshot(out);
  ASSERT_EQ(before.size(), 3u);  // the .glb, and its manifest in the scene's folder
  // 20000 frames of 300 steps: seconds, even on a fast machine.
  expect_stopped_cleanly(
      common + words({"--force", "--frames", "20000", "--set", "time.steps_per_frame=300"}),
      kReport, "export frames", GetParam(), out, before);
}

INSTANTIATE_TEST_SUITE_P(Signals, ExportSignal, ::testing::Values(SIGINT, SIGTERM),
                         [](const auto& info) { return signal_name(info.param); });

// A render stopped while its encoders finish: the GIF's palette pass (long: signalled in
// flight), the WebM's and the MP4's flushes (held at their first packet).
struct FinishCase {
  std::string format;
  std::string stage;
  const char* hook;
  int signal;
  std::vector<std::string> settings;  ///< the interrupted run's own --set and options
  friend void PrintTo(const FinishCase& c, std::ostream* os) {
    *os << c.format << " at " << c.stage;
  }
};

class RenderFinishSignal : public ::testing::TestWithParam<FinishCase> {};

TEST_P(RenderFinishSignal, StopsTheEncoderAndKeepsThePreviousClip) {
  const FinishCase& c = GetParam();
  const ScratchDir dir;
  const fs::path out = dir.path() / "out";
  const std::vector<std::string> common =
      words({"render", kFig09, "-o", out.string(), "--format", c.format, "--jobs", "2", "--set",
             "render.preset=\"ultrafast\""});
  std::string first_args;
  for (const auto& w : common + words({"--frames", "12", "--set", "render.width=96", "--set",
                                       "render.height=64", "--set", "render.gif_width=64"}))
    first_args += "'" + w + "' ";
  const CliResult first = run_bookspin(first_args);
  ASSERT_EQ(first.status, 0) << first.output;
  const auto before = snapshot(out);
  std::stringstream formats(c.format);
  for (std::string format; std::getline(formats, format, ',');)
    ASSERT_TRUE(before.count("fig09-matrix-unstable-x." + format)) << format;
  ASSERT_TRUE(before.count("fig09-matrix-unstable-x/manifest.json"));
  expect_stopped_cleanly(common + c.settings, c.hook, c.stage, c.signal, out, before);
}

INSTANTIATE_TEST_SUITE_P(
    Signals, RenderFinishSignal,
    ::testing::Values(
        // 240 frames of 640 × 360, every one kept: a palette pass of 3.5 s here (2026-11-23).
        FinishCase{"gif", "gif palette pass", kReport, SIGINT,
                   words({"--frames", "240", "--no-png", "--set", "render.width=640", "--set",
                          "render.height=360", "--set", "render.gif_width=640", "--set",
                          "render.gif_fps=30", "--set", "render.panel=false"})},
        // Both formats: the MP4 is finished before the GIF's palette pass, and must not be
        // put in place when the GIF is stopped (one run's outputs go in together, or none).
        FinishCase{"mp4,gif", "gif palette pass", kReport, SIGTERM,
                   words({"--frames", "240", "--no-png", "--set", "render.width=640", "--set",
                          "render.height=360", "--set", "render.gif_width=640", "--set",
                          "render.gif_fps=30", "--set", "render.panel=false"})},
        FinishCase{
            "webm", "webm flush", kHold, SIGTERM,
            words({"--frames", "20", "--set", "render.width=96", "--set", "render.height=64"})},
        FinishCase{
            "mp4", "mp4 flush", kHold, SIGINT,
            words({"--frames", "20", "--set", "render.width=96", "--set", "render.height=64"})}),
    [](const auto& info) {
      std::string name = info.param.format;
      std::replace(name.begin(), name.end(), ',', '_');
      return name;
    });

// A sweep's running points are abandoned: their physics loops poll every 64 steps.
TEST(Signals, SweepAbandonsItsRunningPointsAndKeepsThePreviousSweep) {
  const ScratchDir dir;
  const fs::path out = dir.path() / "out";
  const std::string sweep = "sweep " + kFig09 +
                            " --vary time.dt=0.01:0.02:2 --measure energy_drift -j 2 -o " +
                            out.string();
  const CliResult first = run_bookspin(sweep + " --set time.frames=20");
  ASSERT_EQ(first.status, 0) << first.output;
  const auto before = snapshot(out);
  ASSERT_TRUE(before.count("fig09-matrix-unstable-x-sweep.csv"));
  ASSERT_TRUE(before.count("fig09-matrix-unstable-x/sweep-manifest.json"));
  // Two points of 100000 frames on two threads: each runs for seconds.
  expect_stopped_cleanly(
      words({"sweep", kFig09, "--vary", "time.dt=0.01:0.02:2", "--measure", "energy_drift", "-j",
             "2", "-o", out.string(), "--set", "time.frames=100000"}),
      kReport, "sweep point", SIGINT, out, before);
}

/// Writes `text` to `path`.
void write_text(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
}

// An accuracy run polls every 64 steps. A full report takes a quarter of a minute, so the
// previous outputs here are stand-ins at the report's paths, its manifest too: they must keep
// their bytes.
TEST(Signals, AccuracyStopsItsRunsAndKeepsThePreviousReport) {
  const ScratchDir dir;
  const fs::path out = dir.path() / "out";
  for (const char* name :
       {"-accuracy.csv", "-accuracy.png", "-work-precision.png", "-energy-vs-dt.png",
        "-turnovers.png", "-energy.png", "-energy.csv", "/accuracy-manifest.json"})
    write_text(out / (std::string("exact-unstable-x") + name), std::string("earlier ") + name);
  const auto before = snapshot(out);
  // 100 flips at dt = 0.001: 2·10⁷ steps a method.
  expect_stopped_cleanly(words({"accuracy", scene_path("exact-unstable-x"), "-o", out.string(),
                                "--flips", "100", "--dt", "0.001"}),
                         kReport, "accuracy runs", SIGTERM, out, before);
}

/// A shell as web/build.sh writes it, reduced to its data marker.
fs::path fake_shell(const fs::path& dir) {
  const fs::path shell = dir / "shell.html";
  write_text(shell, "<!doctype html><title>explorer</title><!--BOOKSPIN_DATA-->\n");
  return shell;
}

// The explorer page and the gallery are made in a fraction of a second: each is held at a
// stage until the signal arrives, and the earlier page and its manifest stay.
TEST(Signals, ExploreKeepsThePreviousPageAndManifest) {
  const ScratchDir dir;
  const fs::path out = dir.path() / "out";
  const std::string shell = fake_shell(dir.path()).string();
  const CliResult first =
      run_bookspin("explore " + kFig09 + " --shell " + shell + " -o " + out.string());
  ASSERT_EQ(first.status, 0) << first.output;
  const auto before = snapshot(out);
  ASSERT_TRUE(before.count("explorer.html"));
  ASSERT_TRUE(before.count("explorer-manifest.json"));
  for (const char* stage : {"explore scenes", "explore write"}) {
    expect_stopped_cleanly(words({"explore", kFig09, scene_path("exact-unstable-x"), "--shell",
                                  shell, "-o", out.string()}),
                           kHold, stage, SIGTERM, out, before);
  }
}

TEST(Signals, GalleryKeepsThePreviousPageAndManifest) {
  const ScratchDir dir;
  const fs::path out = dir.path() / "out";
  const CliResult first = run_bookspin("gallery " + out.string() + " " + kFig09);
  ASSERT_EQ(first.status, 0) << first.output;
  const auto before = snapshot(out);
  ASSERT_TRUE(before.count("index.html"));
  ASSERT_TRUE(before.count("gallery-manifest.json"));
  for (const char* stage : {"gallery scenes", "gallery write"}) {
    expect_stopped_cleanly(
        words({"gallery", out.string(), kFig09, scene_path("exact-unstable-x"), "--force"}), kHold,
        stage, SIGINT, out, before);
  }
}

// plot and simulate poll every frame of their run: a long one stopped by any of the three
// signals (SIGHUP: the terminal closed) keeps the earlier PNG and its manifest, or the earlier
// CSV, byte for byte, and leaves no temporary. Signalled at the loop's first poll, so the
// time to exit measures how often the loop polls (without the polls: tens of seconds, exit 0).
class PlotSimulateSignal : public ::testing::TestWithParam<int> {};

TEST_P(PlotSimulateSignal, StopsTheRunAndKeepsTheEarlierOutput) {
  const ScratchDir dir;
  const fs::path out = dir.path() / "out";
  const CliResult first =
      run_bookspin("plot " + kFig09 + " --set time.frames=20 -o " + out.string());
  ASSERT_EQ(first.status, 0) << first.output;
  const auto before = snapshot(out);
  ASSERT_TRUE(before.count("fig09-matrix-unstable-x-plot.png"));
  ASSERT_TRUE(before.count("fig09-matrix-unstable-x/plot-manifest.json"));
  // 100000 frames of 300 steps: minutes, even on a fast machine.
  const std::vector<std::string> long_run =
      words({"--set", "time.frames=100000", "--set", "time.steps_per_frame=300"});
  expect_stopped_cleanly(words({"plot", kFig09, "-o", out.string(), "--force"}) + long_run, kReport,
                         "plot frames", GetParam(), out, before);
  // Signalled once the sheet is drawn (held there), before its PNG goes in place: drawing a long
  // run's sheet takes seconds on a loaded machine, and without this poll the run went on, exit 0.
  expect_stopped_cleanly(
      words({"plot", kFig09, "-o", out.string(), "--force", "--set", "time.frames=2000"}), kHold,
      "plot files", GetParam(), out, before);

  const fs::path csv = out / "fig09.csv";
  const CliResult simulated =
      run_bookspin("simulate " + kFig09 + " --set time.frames=5 --csv " + csv.string());
  ASSERT_EQ(simulated.status, 0) << simulated.output;
  const auto with_csv = snapshot(out);
  ASSERT_TRUE(with_csv.count("fig09.csv"));
  expect_stopped_cleanly(words({"simulate", kFig09, "--csv", csv.string()}) + long_run, kReport,
                         "simulate rows", GetParam(), out, with_csv);
}

INSTANTIATE_TEST_SUITE_P(Signals, PlotSimulateSignal, ::testing::Values(SIGINT, SIGTERM, SIGHUP),
                         [](const auto& info) { return signal_name(info.param); });

// fit --render polls every frame of each toss's clip: a signal there keeps the earlier fit's
// CSVs, charts and manifest byte for byte, and the run's scratch folder and staged files go.
TEST(Signals, FitRenderKeepsThePreviousFit) {
  const ScratchDir dir;
  const fs::path out = dir.path() / "out";
  fit::test::write_export(
      dir.path() / "toss",
      fit::test::make_recording(fit::test::phone_alone(), {{{1.0, 18.0, 1.2}, 1.3}}, 6),
      fit::test::Dialect::comma);
  write_text(dir.path() / "small.toml",
             "body.shape = \"phone\"\nrender.width = 96\nrender.height = 64\n");
  const std::string recording = (dir.path() / "toss").string();
  const CliResult first = run_bookspin("fit " + recording + " -o " + out.string());
  ASSERT_EQ(first.status, 0) << first.output;
  const auto before = snapshot(out);
  ASSERT_TRUE(before.count("toss-fit.csv"));
  expect_stopped_cleanly(words({"fit", recording, "--render", "--scene",
                                (dir.path() / "small.toml").string(), "-o", out.string()}),
                         kHold, "render frames", SIGINT, out, before);
}

// The plain fit polls between its stages (the flights, each toss's chart, before the files go
// in place): a signal keeps the earlier fit's CSVs, charts and manifest byte for byte. --force:
// the second run must reach its work whatever the manifest says.
class FitSignal : public ::testing::TestWithParam<std::string> {};

TEST_P(FitSignal, KeepsThePreviousFit) {
  const ScratchDir dir;
  const fs::path out = dir.path() / "out";
  fit::test::write_export(
      dir.path() / "toss",
      fit::test::make_recording(fit::test::phone_alone(), {{{1.0, 18.0, 1.2}, 1.3}}, 6),
      fit::test::Dialect::comma);
  const std::string recording = (dir.path() / "toss").string();
  const CliResult first = run_bookspin("fit " + recording + " -o " + out.string());
  ASSERT_EQ(first.status, 0) << first.output;
  const auto before = snapshot(out);
  ASSERT_TRUE(before.count("toss-fit.csv"));
  for (const int signal : {SIGINT, SIGTERM})
    expect_stopped_cleanly(words({"fit", recording, "--force", "-o", out.string()}), kHold,
                           GetParam(), signal, out, before);
}

INSTANTIATE_TEST_SUITE_P(Signals, FitSignal,
                         ::testing::Values("fit flights", "fit charts", "fit files"),
                         [](const auto& info) {
                           std::string name = info.param;
                           name.erase(0, 4);
                           return name;
                         });

}  // namespace
}  // namespace bookspin::cli
