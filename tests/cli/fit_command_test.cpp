// `bookspin fit` run as a program: a synthetic phyphox export (tests/fit/synthetic_recording.hpp)
// fitted into its CSVs and charts, and bad input answered with one line and exit 2, nothing
// written.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "fit/synthetic_recording.hpp"
#include "support/cli_runner.hpp"

namespace bookspin::cli {
namespace {

namespace fs = std::filesystem;

std::string quoted(const fs::path& path) {
  std::string text = "'";
  text += path.string();
  text += '\'';
  return text;
}

/// The files the printed `bookspin explore WORDS -o …` command names once a shell expands its
/// words, each as its last 6 characters, space-separated ("" without such a line).
std::string explored_scenes(const std::string& output) {
  const std::string start = "bookspin explore ";
  const auto at = output.find(start);
  if (at == std::string::npos) return "";
  const auto end = output.find(" -o ", at);
  const std::string words = output.substr(at + start.size(), end - at - start.size());
  const bookspin::test::ScratchDir dir;
  std::ofstream(dir.path() / "expand.sh")
      << "for f in " << words << "; do printf '%s ' \"${f: -6}\"; done\n";
  std::string expanded;
  bookspin::test::run_shell("bash " + (dir.path() / "expand.sh").string(), expanded);
  return expanded.substr(0, expanded.find_last_not_of(' ') + 1);
}

TEST(FitCommand, FitsASyntheticExportIntoItsCsvsAndCharts) {
  const fs::path dir = bookspin::test::fresh_dir("cli/fit/good");
  const auto synthetic = fit::test::make_recording(
      fit::test::phone_on_book(), {{{0.5, 12.0, 0.4}, 1.2}, {{-0.3, 11.0, 0.7}, 1.2}}, 3);
  fit::test::write_export(dir / "toss", synthetic, fit::test::Dialect::tab);
  const auto result =
      bookspin::test::run_bookspin("fit " + quoted(dir / "toss") + " -o " + quoted(dir / "out"));
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_NE(result.output.find("kept toss 2"), std::string::npos) << result.output;
  for (const char* name : {"toss-fit.csv", "toss-fit-body.csv", "toss-toss1.png", "toss-toss2.png",
                           "toss-toss1.toml", "toss-toss2.toml", "toss-toss1-measured.csv",
                           "toss-toss2-measured.csv", "toss/fit-manifest.json"})
    EXPECT_TRUE(fs::exists(dir / "out" / name)) << name;
  // It says how to open the tosses in the explorer: one shell glob that names every toss scene.
  EXPECT_EQ(explored_scenes(result.output), "1.toml 2.toml") << result.output;
  const std::string csv = read_text_file(dir / "out" / "toss-fit.csv", "the CSV");
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "toss,t_start,t_end,omega0_x,omega0_y,omega0_z,half_period_measured,"
            "half_period_fitted,half_period_predicted,half_period_predicted_sigma,"
            "half_period_propagated_sigma,prediction_interval,predicted_from_"
            "tosses,predicted_from_seconds,predicted_window,not_predicted,"
            "residual_rms,L_decay,drag_rate,"
            "drag_rate_sigma,saturated,stable,poor_fit,flag");
  // Run again: up to date.
  const auto again =
      bookspin::test::run_bookspin("fit " + quoted(dir / "toss") + " -o " + quoted(dir / "out"));
  EXPECT_EQ(again.status, 0);
  EXPECT_NE(again.output.find("up to date"), std::string::npos) << again.output;
  EXPECT_EQ(explored_scenes(again.output), "1.toml 2.toml") << again.output;
}

// Moments given that no rigid body has (I1 + I2 < I3: 1 + 1.5 < 5) are bad input: one line
// naming the option and which way the triangle inequality is broken, exit 2, nothing written.
TEST(FitCommand, MomentsThatBreakTheTriangleInequalityAreRefusedWithNothingWritten) {
  const fs::path dir = bookspin::test::fresh_dir("cli/fit/triangle");
  const auto synthetic = fit::test::make_recording(
      fit::test::phone_on_book(), {{{0.5, 12.0, 0.4}, 1.2}, {{-0.3, 11.0, 0.7}, 1.2}}, 3);
  fit::test::write_export(dir / "toss", synthetic, fit::test::Dialect::tab);
  const auto result = bookspin::test::run_bookspin("fit " + quoted(dir / "toss") +
                                                   " --moments 5,1,1.5 -o " + quoted(dir / "out"));
  EXPECT_EQ(result.status, 2) << result.output;
  EXPECT_EQ(result.output,
            "bookspin: error: --moments: 1 + 1.5 < 5: no rigid body has these principal moments "
            "(the two smaller sum to at least the largest)\n");
  EXPECT_FALSE(fs::exists(dir / "out"));
}

// The same input gives the same bytes whatever the machine's load: six fits of the sample
// recording at once on two cores, each CSV byte for byte the same. (With Ceres on several
// threads, the order of its sums followed the load, and ten such runs differed by up to 3e-9
// relative in the axes and the residual.)
TEST(FitCommand, ConcurrentRunsWriteTheSameBytes) {
  const fs::path dir = bookspin::test::fresh_dir("cli/fit/concurrent");
  const fs::path recording =
      fs::path(BOOKSPIN_SOURCE_DIR) / "recordings" / "phone-on-book-synthetic";
  std::string script;
  constexpr int kRuns = 6;
  for (int i = 0; i < kRuns; ++i)
    script += std::string(BOOKSPIN_EXE) + " fit " + quoted(recording) + " --drag quadratic -o " +
              quoted(dir / ("out" + std::to_string(i))) + " > /dev/null 2>&1 &\n";
  script += "wait\n";
  std::ofstream(dir / "runs.sh") << script;
  std::string ignored;
  bookspin::test::run_shell("bash " + quoted(dir / "runs.sh"), ignored);
  for (const char* name :
       {"phone-on-book-synthetic-fit.csv", "phone-on-book-synthetic-fit-body.csv"}) {
    const std::string first = read_text_file(dir / "out0" / name, "the first run's CSV");
    for (int i = 1; i < kRuns; ++i)
      EXPECT_EQ(read_text_file(dir / ("out" + std::to_string(i)) / name, "a run's CSV"), first)
          << name << " of run " << i;
  }
}

/// Runs `bookspin fit FILE extra` on `text` written to FILE; expects exit 2, one line
/// holding `expected`, and no output folder.
void expect_bad(const std::string& name, const std::string& text, const std::string& expected,
                const std::string& extra = "") {
  const fs::path dir = bookspin::test::fresh_dir("cli/fit/bad-" + name);
  std::ofstream(dir / (name + ".csv")) << text;
  const auto result = bookspin::test::run_bookspin("fit " + quoted(dir / (name + ".csv")) + " -o " +
                                                   quoted(dir / "out") + " " + extra);
  EXPECT_EQ(result.status, 2) << result.output;
  EXPECT_EQ(std::count(result.output.begin(), result.output.end(), '\n'), 1) << result.output;
  EXPECT_NE(result.output.find(expected), std::string::npos) << result.output;
  EXPECT_FALSE(fs::exists(dir / "out")) << name;
}

std::string rest_rows(int n, double t0 = 0.0) {
  std::string text;
  for (int i = 0; i < n; ++i) text += std::to_string(t0 + 0.01 * i) + ",0.01,0.02,0.01\n";
  return text;
}

TEST(FitCommand, BadInputIsOneLineAndExitTwo) {
  expect_bad("accelerometer", "\"Time (s)\",\"Acceleration x (m/s^2)\",\"y\",\"z\"\n0,1,2,3\n",
             "accelerometer.csv:1: header: not a gyroscope recording");
  expect_bad("backwards", "t,wx,wy,wz\n" + rest_rows(20) + "0.05,1,2,3\n",
             "backwards.csv:22: t: time does not increase");
  expect_bad("nan", "t,wx,wy,wz\n" + rest_rows(5) + "0.5,nan,1,1\n" + rest_rows(10, 1.0),
             "nan.csv:7: wx: not a finite number");
  expect_bad("text", "t,wx,wy,wz\n" + rest_rows(5) + "0.5,1,x,1\n" + rest_rows(10, 1.0),
             "text.csv:7: wy: not a number");
  expect_bad("still", "t,wx,wy,wz\n" + rest_rows(300), "still.csv: no free flight found");
  expect_bad("short", "t,wx,wy,wz\n" + rest_rows(300), "--tosses 0.100:0.120: 3 samples",
             "--tosses 0.1:0.12");
  expect_bad("moments", "t,wx,wy,wz\n" + rest_rows(300), "--moments: expected I1,I2,I3",
             "--moments 1,2");
  expect_bad("scene", "t,wx,wy,wz\n" + rest_rows(300), "--scene: only with --render",
             "--scene x.toml");
  expect_bad("slow", "t,wx,wy,wz\n" + rest_rows(300), "--slow-motion: Value 0.5 not in range",
             "--render --slow-motion 0.5");
}

TEST(FitCommand, RenderMakesAClipPerTossAndABadSceneWritesNothing) {
  const fs::path dir = bookspin::test::fresh_dir("cli/fit/render");
  const auto synthetic = fit::test::make_recording(
      fit::test::phone_alone(), {{{1.0, 18.0, 1.2}, 1.3}, {{-1.2, 17.0, 1.5}, 1.2}}, 6);
  fit::test::write_export(dir / "toss", synthetic, fit::test::Dialect::comma);
  std::ofstream(dir / "bad.toml") << "body.shape = \"phone\"\nrender.fps = 0\n";
  const auto bad =
      bookspin::test::run_bookspin("fit " + quoted(dir / "toss") + " --render --scene " +
                                   quoted(dir / "bad.toml") + " -o " + quoted(dir / "out"));
  EXPECT_EQ(bad.status, 2) << bad.output;
  EXPECT_EQ(std::count(bad.output.begin(), bad.output.end(), '\n'), 1) << bad.output;
  EXPECT_NE(bad.output.find("bad.toml:2: render.fps"), std::string::npos) << bad.output;
  EXPECT_FALSE(fs::exists(dir / "out"));
  std::ofstream(dir / "small.toml") << "body.shape = \"phone\"\nrender.width = 160\n"
                                       "render.height = 90\nrender.fps = 10\nrender.msaa = 1\n";
  const auto made = bookspin::test::run_bookspin(
      "fit " + quoted(dir / "toss") + " --render --slow-motion 2 --scene " +
      quoted(dir / "small.toml") + " -o " + quoted(dir / "out"));
  ASSERT_EQ(made.status, 0) << made.output;
  EXPECT_NE(made.output.find("2 video(s)"), std::string::npos) << made.output;
  for (const char* name : {"toss-toss1.mp4", "toss-toss2.mp4"})
    EXPECT_TRUE(fs::exists(dir / "out" / name)) << name;
}

}  // namespace
}  // namespace bookspin::cli
