// `bookspin sweep` (docs/physics.md §14): shards merged into the one-process result byte for
// byte, merge errors, a diverging point as a row, bad ranges as one-line errors.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "support/cli_runner.hpp"

namespace bookspin::cli {
namespace {

using namespace bookspin::test;

/// A small sweep: 7 points (7 does not divide into 3 shards evenly), short quaternion RK4 runs.
const std::string kSweep =
    "sweep " + scene_path("exact-unstable-x") +
    " --set 'model.kind=\"rigid-quaternion\"' --set 'model.integrator=\"rk4\"'"
    " --set time.frames=200 --vary 'initial.angular_velocity[1]=1e-4:1e-1:7:log'"
    " --measure first_flip,flip_period,energy_drift,orientation_error,diverged_at";

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::string shard(const std::filesystem::path& dir, int k, int n) {
  return (dir / ("exact-unstable-x-sweep.shard-" + std::to_string(k) + "-of-" + std::to_string(n) +
                 ".csv"))
      .string();
}

/// Writes the shards 0–2 of 3 of kSweep into `dir`.
void write_shards(const std::filesystem::path& dir) {
  for (int k = 0; k < 3; ++k) {
    const CliResult r =
        run_bookspin(kSweep + " -j 1 --shard " + std::to_string(k) + "/3 -o " + dir.string());
    ASSERT_EQ(r.status, 0) << r.output;
  }
}

TEST(SweepCommand, WritesOneRowPerPointWithTheVariedValuesThenTheMeasures) {
  const auto dir = fresh_dir("sweep_rows");
  const CliResult r = run_bookspin(kSweep + " -j 2 -o " + dir.string());
  ASSERT_EQ(r.status, 0) << r.output;
  const auto lines = lines_of(read_file(dir / "exact-unstable-x-sweep.csv"));
  ASSERT_EQ(lines.size(), 8u);
  EXPECT_EQ(lines[0],
            "initial.angular_velocity[1],first_flip,flip_period,energy_drift,orientation_error,"
            "diverged_at,first_flip_exact,flip_period_exact");
  EXPECT_EQ(lines[1].rfind("0.0001,", 0), 0u) << lines[1];
  EXPECT_EQ(lines[7].rfind("0.10000000000000001,", 0), 0u) << lines[7];
  EXPECT_TRUE(std::filesystem::file_size(dir / "exact-unstable-x-sweep.png") > 10000);
}

TEST(SweepCommand, MergedShardsAreByteIdenticalToOneProcess) {
  const auto one = fresh_dir("sweep_one");
  const auto parts = fresh_dir("sweep_parts");
  const auto merged = fresh_dir("sweep_merged");
  ASSERT_EQ(run_bookspin(kSweep + " -j 2 -o " + one.string()).status, 0);
  write_shards(parts);
  // Two points, two points, three points: every index once, in its shard.
  EXPECT_EQ(lines_of(read_file(shard(parts, 0, 3))).size(), 2u + 3u);
  EXPECT_EQ(lines_of(read_file(shard(parts, 2, 3))).size(), 2u + 2u);
  const CliResult r =
      run_bookspin("sweep --merge " + shard(parts, 2, 3) + " " + shard(parts, 0, 3) + " " +
                   shard(parts, 1, 3) + " -o " + merged.string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(read_file(merged / "exact-unstable-x-sweep.csv"),
            read_file(one / "exact-unstable-x-sweep.csv"));
  EXPECT_EQ(read_file(merged / "exact-unstable-x-sweep.png"),
            read_file(one / "exact-unstable-x-sweep.png"));
}

TEST(SweepCommand, MergeRejectsAMissingShardOrADuplicateNamingTheFile) {
  const auto parts = fresh_dir("sweep_merge_errors");
  const auto out = parts / "merged";
  write_shards(parts);
  CliResult r = run_bookspin("sweep --merge " + shard(parts, 0, 3) + " " + shard(parts, 2, 3) +
                             " -o " + out.string());
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find(shard(parts, 1, 3) + ": grid point 1 of 7 is missing"), std::string::npos)
      << r.output;
  r = run_bookspin("sweep --merge " + shard(parts, 0, 3) + " " + shard(parts, 1, 3) + " " +
                   shard(parts, 2, 3) + " " + shard(parts, 1, 3) + " -o " + out.string());
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("shard 1 of 3 is also given"), std::string::npos) << r.output;
  // A row copied into another shard is a duplicate grid point, named with its line.
  {
    const auto rows = lines_of(read_file(shard(parts, 0, 3)));
    std::ofstream(parts / "copy.csv") << rows[0] << '\n' << rows[1] << '\n';
    std::ofstream(shard(parts, 1, 3), std::ios::app) << rows[2] << '\n';
  }
  r = run_bookspin("sweep --merge " + shard(parts, 0, 3) + " " + shard(parts, 1, 3) + " " +
                   shard(parts, 2, 3) + " -o " + out.string());
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find(shard(parts, 1, 3) + ":5: grid_index '0' is not a point of shard 1"),
            std::string::npos)
      << r.output;
  // Mismatched headers.
  {
    auto rows = lines_of(read_file(shard(parts, 0, 3)));
    rows[1] += "x";
    std::ofstream edited(parts / "edited.csv");
    for (const auto& line : rows) edited << line << '\n';
  }
  r = run_bookspin("sweep --merge " + (parts / "edited.csv").string() + " -o " + out.string());
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("edited.csv:2: header differs"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(out / "exact-unstable-x-sweep.csv"));
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
}

TEST(SweepCommand, ADivergingPointIsARowNotACrash) {
  const auto dir = fresh_dir("sweep_diverge");
  const CliResult r = run_bookspin("sweep " + scene_path("fig10-matrix-no-normalization") +
                                   " --vary time.dt=0.01:2:2 --measure diverged_at,energy_drift,"
                                   "orientation_error -o " +
                                   dir.string());
  ASSERT_EQ(r.status, 0) << r.output;
  const auto lines = lines_of(read_file(dir / "fig10-matrix-no-normalization-sweep.csv"));
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[1].rfind("0.01,,", 0), 0u) << lines[1];  // ran to the end
  EXPECT_EQ(lines[2].rfind("2,", 0), 0u) << lines[2];
  EXPECT_NE(lines[2].substr(2, 1), ",") << lines[2];  // diverged_at holds a time
  EXPECT_EQ(lines[2].back(), ',') << lines[2];        // no orientation after divergence
}

TEST(SweepCommand, BadRangesAndValuesAreOneLineInputErrors) {
  const auto dir = fresh_dir("sweep_bad");
  const std::string base = "sweep " + scene_path("exact-unstable-x") + " -o " + dir.string();
  const std::pair<std::string, std::string> cases[] = {
      {" --vary time.dt=1:2 --measure first_flip", "--vary time.dt=1:2: expected KEY="},
      {" --vary time.dt=0:1:3:log --measure first_flip", "START and STOP greater than 0"},
      {" --vary time.dt=0.01:0.02:2 --measure flips", "unknown measure 'flips'"},
      {" --vary time.dt=0.01:0.02:2 --measure first_flip --shard 3/3", "--shard 3/3: expected K/N"},
      // The scene's own validation names the key.
      {" --vary time.dt=-1:0.02:2 --measure first_flip", "time.dt: must be"},
      {" --vary time.frames=10:20.5:2 --measure first_flip", "time.frames: expected an integer"},
      {" --vary book.spine=1:2:2 --measure first_flip", "book.spine"},
  };
  for (const auto& [args, expected] : cases) {
    const CliResult r = run_bookspin(base + args);
    EXPECT_EQ(r.status, 2) << args << "\n" << r.output;
    EXPECT_NE(r.output.find(expected), std::string::npos) << args << "\n" << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

TEST(SweepCommand, SigintStopsTheSweepWithNothingWritten) {
  // 400 runs of 1500 time units take many seconds; SIGINT after one ends it with 130.
  const auto dir = fresh_dir("sweep_interrupt");
  const std::string command =
      std::string("{ ") + BOOKSPIN_EXE + " sweep " + BOOKSPIN_SOURCE_DIR +
      "/sweeps/flip-time-vs-perturbation.toml --vary "
      "'initial.angular_velocity[1]=1e-6:1e-2:400:log'"
      " --measure first_flip -j 2 -o " +
      (dir / "out").string() +
      " & pid=$!; sleep 1; kill -INT $pid; wait $pid; echo status=$?; } 2>&1";
  std::string output;
  run_shell(command, output);
  EXPECT_NE(output.find("status=130"), std::string::npos) << output;
  EXPECT_NE(output.find("sweep interrupted; nothing written"), std::string::npos) << output;
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "flip-time-vs-perturbation-sweep.csv"));
}

TEST(SweepCommand, TheGalleryShowsASweepsPlotAndCsv) {
  const auto dir = fresh_dir("sweep_gallery");
  const std::string scene =
      std::string(BOOKSPIN_SOURCE_DIR) + "/sweeps/flip-time-vs-perturbation.toml";
  ASSERT_EQ(
      run_bookspin("sweep " + scene +
                   " --set time.frames=400 --vary 'initial.angular_velocity[1]=1e-4:1e-2:3:log'"
                   " --measure first_flip -o " +
                   dir.string())
          .status,
      0);
  const CliResult r = run_bookspin("gallery " + dir.string() + " " + scene);
  ASSERT_EQ(r.status, 0) << r.output;
  const std::string html = read_file(dir / "index.html");
  EXPECT_NE(html.find("src=\"flip-time-vs-perturbation-sweep.png\""), std::string::npos) << html;
  EXPECT_NE(html.find("href=\"flip-time-vs-perturbation-sweep.csv\""), std::string::npos) << html;
  EXPECT_EQ(html.find("not rendered yet"), std::string::npos) << html;
}

}  // namespace
}  // namespace bookspin::cli
