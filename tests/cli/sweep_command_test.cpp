// `bookspin sweep` (docs/physics.md §14): shards merged into the one-process result byte for
// byte, merge errors, a diverging point as a row, bad ranges as one-line errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <utility>
#include <vector>

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
            "diverged_at,first_flip_exact,flip_period_exact,refused");
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

// A point its engine refuses (scenes/README.md, "Engine limits") is its row's reason, not a
// dead sweep: MuJoCo over book.mass for a 1e-6 cube, whose moments m·(2e-12)/12 reach MuJoCo's
// 1e-15 at m = 6e-3, so exactly the two lightest of three points (worked out here from the
// grid) are refused, each naming the key and saying why; the third ran; the note says how
// many; shards merge to the same bytes, the reason's comma and all. When every point is
// refused the sweep is refused whole: exit 2, one line, nothing written.
TEST(SweepCommand, APointTheEngineRefusesIsItsRowsReasonNotADeadSweep) {
  const auto one = fresh_dir("sweep_refused_one");
  const auto scene = one.parent_path() / "refusing.toml";
  std::ofstream(scene) << "[model]\nkind = \"mujoco\"\n[book]\nsize = [1e-6, 1e-6, 1e-6]\n"
                          "[time]\nframes = 20\n";
  const std::string sweep = "sweep " + scene.string() + " --measure energy_drift,diverged_at";
  const std::string vary = " --vary book.mass=1e-4:1e-2:3:log";  // 1e-4, 1e-3, 1e-2
  CliResult r = run_bookspin(sweep + vary + " -j 2 -o " + one.string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("bookspin: note: the engine refused 2 of the 3 points (first: book.size: "
                          "MuJoCo needs every principal moment above its mjMINVAL (1e-15)"),
            std::string::npos)
      << r.output;
  const auto lines = lines_of(read_file(one / "refusing-sweep.csv"));
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[0], "book.mass,energy_drift,diverged_at,refused");
  for (int i = 0; i < 3; ++i) {
    const double mass = std::pow(10.0, -4.0 + i);
    const bool refused = mass * 2e-12 / 12 <= 1e-15;
    EXPECT_EQ(refused, i < 2);
    const std::string& line = lines[static_cast<std::size_t>(i) + 1];
    if (refused) {
      // ",,,book.size: … smallest is <I> (a larger or heavier body)": no measure, and the
      // moment printed is this point's, m·(2e-12)/12.
      const std::string head =
          ",,,book.size: MuJoCo needs every principal moment above its mjMINVAL (1e-15); this "
          "body's smallest is ";
      const std::string tail = " (a larger or heavier body)";
      const auto at = line.find(head);
      ASSERT_NE(at, std::string::npos) << line;
      ASSERT_GT(line.size(), at + head.size() + tail.size()) << line;
      EXPECT_EQ(line.substr(line.size() - tail.size()), tail) << line;
      const std::string moment =
          line.substr(at + head.size(), line.size() - at - head.size() - tail.size());
      EXPECT_NEAR(std::stod(moment) / (mass * 2e-12 / 12), 1.0, 1e-12) << moment;
    } else {
      EXPECT_EQ(line.back(), ',') << line;  // ran: refused empty
      EXPECT_NE(line.rfind("0.01,", 0), std::string::npos) << line;
      EXPECT_EQ(line.find(",,,"), std::string::npos) << line;  // energy_drift measured
    }
  }
  EXPECT_TRUE(std::filesystem::file_size(one / "refusing-sweep.png") > 10000);
  // Shards 0 and 1 of 2, merged: the same bytes.
  const auto parts = fresh_dir("sweep_refused_parts");
  for (int k = 0; k < 2; ++k) {
    r = run_bookspin(sweep + vary + " -j 1 --shard " + std::to_string(k) + "/2 -o " +
                     parts.string());
    ASSERT_EQ(r.status, 0) << r.output;
  }
  const auto part = [&](int k) {
    return (parts / ("refusing-sweep.shard-" + std::to_string(k) + "-of-2.csv")).string();
  };
  r = run_bookspin("sweep --merge " + part(1) + " " + part(0) + " -o " + (parts / "m").string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(read_file(parts / "m" / "refusing-sweep.csv"), read_file(one / "refusing-sweep.csv"));
  // Every point refused: the sweep is.
  const auto none = fresh_dir("sweep_refused_all");
  r = run_bookspin(sweep + " --vary book.mass=1e-4:1e-3:2:log -o " + none.string());
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("refusing.toml:4: book.size: MuJoCo needs every principal moment"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("(at every one of the 2 points)"), std::string::npos) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  EXPECT_TRUE(std::filesystem::is_empty(none)) << none;
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
  // A row copied into another shard is not a point of that shard, named with its line.
  {
    const auto rows = lines_of(read_file(shard(parts, 0, 3)));
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

/// `lines` joined with `eol` after each.
std::string joined(const std::vector<std::string>& lines, const std::string& eol = "\n") {
  std::string text;
  for (const auto& line : lines) text += line + eol;
  return text;
}

/// Merges shards 0, 1, 2 of `dir` into `dir`/merged and expects exit 2 with one line that
/// names `culprit` and says `why`, and no merged output.
void expect_refused(const std::filesystem::path& dir, const std::string& culprit,
                    const std::string& why) {
  const auto out = dir / "merged";
  const CliResult r = run_bookspin("sweep --merge " + shard(dir, 0, 3) + " " + shard(dir, 1, 3) +
                                   " " + shard(dir, 2, 3) + " -o " + out.string());
  EXPECT_EQ(r.status, 2) << why << "\n" << r.output;
  EXPECT_EQ(r.output.rfind("bookspin: error: " + culprit, 0), 0u) << why << "\n" << r.output;
  EXPECT_NE(r.output.find(why), std::string::npos) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  EXPECT_FALSE(std::filesystem::exists(out / "exact-unstable-x-sweep.csv"));
}

/// Replaces shard K of 3 in `dir` by `lines`.
void rewrite_shard(const std::filesystem::path& dir, int k, const std::vector<std::string>& lines) {
  std::ofstream(shard(dir, k, 3), std::ios::binary | std::ios::trunc) << joined(lines);
}

// A shard records its resolved scene (after --set), its build, grid and measures; --merge
// refuses a shard whose record differs from the first's, and a cell that is not a number.
TEST(SweepCommand, MergeRefusesShardsOfAnotherSceneSetBuildGridOrMeasures) {
  const auto dir = fresh_dir("sweep_merge_mixed");
  const auto redo_shard_1 = [&](const std::string& args) {
    const CliResult r = run_bookspin(args + " -j 1 --shard 1/3 -o " + dir.string());
    ASSERT_EQ(r.status, 0) << r.output;
  };
  write_shards(dir);
  const std::string good_1 = read_file(shard(dir, 1, 3));
  // Another --set.
  redo_shard_1(kSweep + " --set time.dt=0.02");
  expect_refused(dir, shard(dir, 1, 3), "the resolved scene differs");
  // The same scene name, edited: a book of mass 80 instead of 8.
  {
    const auto edited_dir = dir / "edited";
    std::filesystem::create_directories(edited_dir);
    std::string text = read_file(scene_path("exact-unstable-x"));
    const auto at = text.find("mass = 8.0");
    ASSERT_NE(at, std::string::npos);
    text.replace(at, 10, "mass = 80.0");
    std::ofstream(edited_dir / "exact-unstable-x.toml") << text;
    std::string edited_sweep = kSweep;
    edited_sweep.replace(edited_sweep.find(scene_path("exact-unstable-x")),
                         scene_path("exact-unstable-x").size(),
                         (edited_dir / "exact-unstable-x.toml").string());
    redo_shard_1(edited_sweep);
    expect_refused(dir, shard(dir, 1, 3), "the resolved scene differs");
  }
  // Another build of bookspin (its id edited in the shard line).
  {
    auto lines = lines_of(good_1);
    const auto at = lines[0].find(" build=");
    ASSERT_NE(at, std::string::npos) << lines[0];
    lines[0][at + 7] = lines[0][at + 7] == '0' ? '1' : '0';
    rewrite_shard(dir, 1, lines);
    expect_refused(dir, shard(dir, 1, 3), "made by another bookspin build");
  }
  // Other measures; another grid.
  {
    std::string other = kSweep;
    other.replace(other.find(",diverged_at"), 12, "");
    redo_shard_1(other);
    expect_refused(dir, shard(dir, 1, 3), "other measures");
    std::string grid = kSweep;
    grid.replace(grid.find("1e-1:7:log"), 10, "1e-2:7:log");
    redo_shard_1(grid);
    expect_refused(dir, shard(dir, 1, 3), "another grid");
  }
  // Not a number where a number belongs: a measure, and a varied value (never empty).
  const auto good = lines_of(good_1);
  auto cells_of_row = [](const std::string& row) {
    std::vector<std::string> cells;
    std::stringstream in(row);
    for (std::string cell; std::getline(in, cell, ',');) cells.push_back(cell);
    if (!row.empty() && row.back() == ',') cells.emplace_back();
    return cells;
  };
  auto join_cells = [](const std::vector<std::string>& cells) {
    std::string row;
    for (std::size_t i = 0; i < cells.size(); ++i) row += (i ? "," : "") + cells[i];
    return row;
  };
  for (const auto& [column, value] : std::vector<std::pair<int, std::string>>{
           {2, "abc"}, {2, "1.5x"}, {2, "nan"}, {2, "inf"}, {2, " 1"}, {1, ""}, {3, "1e999"}}) {
    auto lines = good;
    auto cells = cells_of_row(lines[2]);
    ASSERT_GT(cells.size(), 4u) << lines[2];
    cells[column] = value;
    lines[2] = join_cells(cells);
    rewrite_shard(dir, 1, lines);
    expect_refused(dir, shard(dir, 1, 3) + ":3: ", "'" + value + "' is not a number");
  }
  // A grid point twice in its own shard; an index equal to the point count (7 ≡ 1 mod 3).
  {
    auto lines = good;
    lines.push_back(lines[2]);
    rewrite_shard(dir, 1, lines);
    expect_refused(dir, shard(dir, 1, 3) + ":5: ",
                   "grid point 1 is duplicated (also at " + shard(dir, 1, 3) + ":3)");
    lines = good;
    auto cells = cells_of_row(lines[2]);
    cells[0] = "7";
    lines.push_back(join_cells(cells));
    rewrite_shard(dir, 1, lines);
    expect_refused(dir, shard(dir, 1, 3) + ":5: ", "grid_index '7' is not a point of shard 1");
  }
}

// Shards that went through CRLF line endings merge to the same bytes as one process.
TEST(SweepCommand, ShardsWithCrlfLineEndingsMergeToTheSameBytes) {
  const auto one = fresh_dir("sweep_crlf_one");
  const auto parts = fresh_dir("sweep_crlf_parts");
  ASSERT_EQ(run_bookspin(kSweep + " -j 2 -o " + one.string()).status, 0);
  write_shards(parts);
  for (int k = 0; k < 3; ++k) {
    const std::string crlf = joined(lines_of(read_file(shard(parts, k, 3))), "\r\n");
    std::ofstream(shard(parts, k, 3), std::ios::binary | std::ios::trunc) << crlf;
  }
  ASSERT_NE(read_file(shard(parts, 0, 3)).find("\r\n"), std::string::npos);
  const CliResult r =
      run_bookspin("sweep --merge " + shard(parts, 0, 3) + " " + shard(parts, 1, 3) + " " +
                   shard(parts, 2, 3) + " -o " + (parts / "merged").string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(read_file(parts / "merged" / "exact-unstable-x-sweep.csv"),
            read_file(one / "exact-unstable-x-sweep.csv"));
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
  EXPECT_NE(output.find("bookspin: interrupted; nothing written"), std::string::npos) << output;
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
