// No NaN or infinity leaves bookspin (docs/outputs.md, "Numbers"): a body at rest gets empty
// cosine cells, the extremes the scene limits allow stay finite in every model, and options
// that would make a non-finite number are bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "support/catalogue.hpp"
#include "support/cli_runner.hpp"

namespace bookspin::cli {
namespace {

using namespace bookspin::test;  // the shared runner (tests/support)
namespace fs = std::filesystem;

constexpr const char* kAtRest = " --set 'initial.angular_velocity=[0,0,0]' --set initial.jiggle=0";

std::vector<std::vector<std::string>> cells_of(const std::string& csv) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(csv);
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells;
    std::size_t start = 0;
    for (std::size_t comma; (comma = line.find(',', start)) != std::string::npos; start = comma + 1)
      cells.push_back(line.substr(start, comma - start));
    cells.push_back(line.substr(start));
    rows.push_back(cells);
  }
  return rows;
}

/// Every cell of every row after the header is a finite number (but the accuracy CSV's
/// `model` and `integrator` names), or empty where `may_be_empty(column name)`; returns how
/// many cells were empty.
int expect_finite_cells(const std::string& csv, bool (*may_be_empty)(const std::string&)) {
  const auto rows = cells_of(csv);
  int empty = 0;
  EXPECT_GE(rows.size(), 2u) << csv;
  for (std::size_t r = 1; r < rows.size(); ++r) {
    EXPECT_EQ(rows[r].size(), rows[0].size()) << "row " << r;
    for (std::size_t c = 0; c < rows[r].size() && c < rows[0].size(); ++c) {
      const std::string& cell = rows[r][c];
      if (rows[0][c] == "model" || rows[0][c] == "integrator") continue;
      if (cell.empty()) {
        EXPECT_TRUE(may_be_empty(rows[0][c])) << rows[0][c] << " empty in row " << r;
        ++empty;
        continue;
      }
      char* end = nullptr;
      const double value = std::strtod(cell.c_str(), &end);
      EXPECT_TRUE(*end == '\0' && std::isfinite(value))
          << rows[0][c] << " = '" << cell << "' in row " << r;
    }
  }
  return empty;
}

bool is_cosine_column(const std::string& name) {
  return name.rfind("cos_", 0) == 0 && name.size() > 2 && name.substr(name.size() - 2) == "_L";
}

bool never_empty(const std::string&) { return false; }

TEST(FiniteOutputs, ABodyAtRestLeavesTheCosineCellsEmptyInEveryModel) {
  const auto dir = fresh_dir("finite_at_rest");
  for (const char* kind : {"particle", "rigid-matrix", "rigid-quaternion", "exact"}) {
    SCOPED_TRACE(kind);
    const auto csv = dir / (std::string(kind) + ".csv");
    const CliResult r = run_bookspin("simulate " + scene_path("fig09-matrix-unstable-x") + kAtRest +
                                     " --set 'model.kind=\"" + kind +
                                     "\"' --set 'model.integrator=\"euler\"' --set time.frames=4"
                                     " --csv " +
                                     quoted(csv));
    ASSERT_EQ(r.status, 0) << r.output;
    const std::string text = read_file(csv);
    // 4 rows × 6 cosine columns, every other cell a finite number (L = 0, ω = 0).
    EXPECT_EQ(expect_finite_cells(text, is_cosine_column), 24) << text;
    const auto rows = cells_of(text);
    EXPECT_EQ(rows[1][5] + rows[1][6] + rows[1][7], "000");  // L_x, L_y, L_z
  }
}

TEST(FiniteOutputs, ARenderAndAComparisonAtRestWriteEmptyCosineCells) {
  const auto dir = fresh_dir("finite_render_at_rest");
  const CliResult single =
      run_bookspin("render " + scene_path("fig05-particle-unstable-x") + kAtRest +
                   " --set time.frames=2 --no-png -o " + quoted(dir));
  ASSERT_EQ(single.status, 0) << single.output;
  EXPECT_EQ(expect_finite_cells(read_file(dir / "fig05-particle-unstable-x" / "diagnostics.csv"),
                                is_cosine_column),
            12);
  const CliResult compare = run_bookspin("render " + scene_path("compare-methods-x") + kAtRest +
                                         " --set time.frames=2 --no-png -o " + quoted(dir));
  ASSERT_EQ(compare.status, 0) << compare.output;
  int tiles = 0;
  for (const auto& entry : fs::directory_iterator(dir / "compare-methods-x")) {
    if (entry.path().extension() != ".csv") continue;
    ++tiles;
    EXPECT_EQ(expect_finite_cells(read_file(entry.path()), is_cosine_column), 12) << entry.path();
  }
  EXPECT_GE(tiles, 2);
}

TEST(FiniteOutputs, TheLargestAndSmallestBodiesAndSpinsStayFiniteInEveryModel) {
  const auto dir = fresh_dir("finite_extremes");
  const std::vector<std::string> extremes{
      " --set book.mass=1e12 --set 'book.size=[1e6,1e6,1e6]' "
      "--set 'initial.angular_velocity=[1e6,-1e6,1e6]'",
      " --set book.mass=1e-12 --set 'book.size=[1e-6,1e-6,1e-6]' --set initial.jiggle=1e6",
      " --set book.mass=1e12 --set 'book.size=[1e6,1e-6,1e-6]' "
      "--set 'initial.angular_velocity=[1e-9,0,0]'"};
  for (const char* kind : {"particle", "rigid-matrix", "rigid-quaternion", "exact"}) {
    for (const std::string& extreme : extremes) {
      SCOPED_TRACE(std::string(kind) + extreme);
      const auto csv = dir / "out.csv";
      const CliResult r = run_bookspin("simulate " + scene_path("fig09-matrix-unstable-x") +
                                       extreme + " --set 'model.kind=\"" + kind +
                                       "\"' --set 'model.integrator=\"euler\"'"
                                       " --set time.frames=10 --csv " +
                                       quoted(csv));
      ASSERT_EQ(r.status, 0) << r.output;  // a divergence keeps the finite rows and warns
      expect_finite_cells(read_file(csv), never_empty);
    }
  }
}

TEST(FiniteOutputs, ASweepFromRestWritesFiniteMeasures) {
  const auto dir = fresh_dir("finite_sweep_at_rest");
  const CliResult r = run_bookspin(
      "sweep " + scene_path("fig09-matrix-unstable-x") + kAtRest +
      " --set time.frames=20 --vary initial.jiggle=0:0.001:2"
      " --measure first_flip,flip_period,energy_drift,orientation_error,diverged_at -j 1 -o " +
      quoted(dir));
  ASSERT_EQ(r.status, 0) << r.output;
  const std::string csv = read_file(dir / "fig09-matrix-unstable-x-sweep.csv");
  expect_finite_cells(csv, [](const std::string& name) { return name != "initial.jiggle"; });
  EXPECT_EQ(cells_of(csv)[1][3], "0") << csv;  // energy_drift at rest: E = E0 = 0
}

struct BadOption {
  std::string args;      ///< after `accuracy SCENE`
  std::string expected;  ///< the whole line after "bookspin: error: "
};

TEST(FiniteOutputs, AccuracyRefusesNonFiniteAndOutOfRangeOptions) {
  const auto dir = fresh_dir("finite_accuracy_options");
  const std::vector<BadOption> cases{
      {"--dt nan", "--dt: Value nan not a finite number in (0, 1000]"},
      {"--dt inf", "--dt: Value inf not a finite number in (0, 1000]"},
      {"--dt 0", "--dt: Value 0 not a finite number in (0, 1000]"},
      {"--dt 1e4", "--dt: Value 1e4 not a finite number in (0, 1000]"},
      {"--dt 0.1 --dt=-inf", "--dt: Value -inf not a finite number in (0, 1000]"},
      {"--flips nan", "--flips: Value nan not a finite number in [1, 1000]"},
      {"--flips inf", "--flips: Value inf not a finite number in [1, 1000]"},
      {"--flips 0.5", "--flips: Value 0.5 not a finite number in [1, 1000]"},
      {"--dt 1e-300",
       "--dt 1e-300: 2.20946e+303 steps for 10 flip periods of 220.946 time units (expected 1 "
       "to 1e+08)"},
      {"--flips 1 --dt 500",
       "--dt 500: 0.441893 steps for 1 flip periods of 220.946 time units (expected 1 to "
       "1e+08)"},
      {"--methods bogus",
       "--methods bogus: \"bogus\" is not a model (all, engines, rigid, particle, "
       "rigid-matrix, rigid-quaternion, mujoco, bullet, ode, or KIND:INTEGRATOR)"},
      {"--methods exact",
       "--methods exact: the exact model is the reference every row is "
       "measured against"},
      {"--methods engines,rigid-matrix:step",
       "--methods engines,rigid-matrix:step: \"step\" is not an integrator of rigid-matrix"},
      {"--methods engines,",
       "--methods engines,: an empty item (expected e.g. "
       "engines,rigid-quaternion:rk4)"},
      {"--set initial.jiggle=0",
       "exact-unstable-x: the motion never flips (its L starts on a principal axis or on the "
       "separatrix), so there is no flip period to measure the runs over: initial.jiggle or "
       "initial.angular_velocity off the axis gives one"},
      // A cube never flips, jiggled or not: the message names that cause, not the jiggle.
      {"--set book.size=[1,1,1]",
       "exact-unstable-x: the body's three principal moments are equal (a cube or a sphere: "
       "every axis is principal), so it never flips, whatever its spin or jiggle: no flip "
       "period to measure the runs over"}};
  for (const BadOption& c : cases) {
    SCOPED_TRACE(c.args);
    const fs::path out = dir / "out";
    const SplitResult r = run_bookspin_split("accuracy " + scene_path("exact-unstable-x") + " " +
                                             c.args + " -o " + quoted(out));
    EXPECT_EQ(r.status, 2);
    const std::string line = r.err.substr(0, r.err.find(" (see bookspin --help)"));
    EXPECT_EQ(line, "bookspin: error: " + c.expected + (line == r.err ? "\n" : "")) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(out));
  }
}

TEST(FiniteOutputs, AccuracyLeavesTheCellsOfADivergedRunEmpty) {
  const auto dir = fresh_dir("finite_accuracy_diverged");
  const CliResult r = run_bookspin("accuracy " + scene_path("exact-unstable-x") +
                                   " --flips 1 --dt 0.5 -o " + quoted(dir));
  ASSERT_EQ(r.status, 0) << r.output;
  const std::string csv = read_file(dir / "exact-unstable-x-accuracy.csv");
  // The particle models blow up at dt = 0.5 (no orientation to compare); most rigid ones see
  // fewer than two flips in one flip period (no flip period to measure).
  const int empty = expect_finite_cells(csv, [](const std::string& name) {
    return name == "orientation_error_rad" || name == "flip_period" ||
           name == "flip_period_error" || name == "first_flip" || name == "first_flip_error";
  });
  EXPECT_GE(empty, 3) << csv;
  for (const auto& row : cells_of(csv)) {
    if (row.size() == 12 && row[11] == "1") {
      EXPECT_EQ(row[5], "") << "diverged, yet an orientation error";
    }
  }
  expect_finite_cells(read_file(dir / "exact-unstable-x-energy.csv"),
                      [](const std::string&) { return true; });
}

}  // namespace
}  // namespace bookspin::cli
