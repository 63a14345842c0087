// Comparison scenes ([[compare]]): rendering, per-panel CSVs and key validation.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "support/cli_runner.hpp"

namespace bookspin::cli {
namespace {

using namespace bookspin::test;  // the shared runner (tests/support)

namespace fs = std::filesystem;

std::size_t line_count(const std::string& text) {
  return std::count(text.begin(), text.end(), '\n');
}

TEST(Compare, RendersAFewSmallFramesWithOneCsvPerPanel) {
  const fs::path out = fresh_dir("compare_render");
  const CliResult r = run_bookspin("render " + scene_path("compare-methods-x") +
                                   " --set render.width=160 --set render.height=96"
                                   " --set 'render.preset=\"ultrafast\"' --frames 4 --jobs 2 -o " +
                                   out.string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(fs::is_regular_file(out / "compare-methods-x.mp4"));
  EXPECT_TRUE(fs::is_regular_file(out / "compare-methods-x/frames/frame_00003.png"));
  for (const char* name : {"particle-mass-spring-euler", "rigid-body-rotation-matrix-rk4",
                           "rigid-body-quaternion-rk4", "exact-jacobi-elliptic-functions"}) {
    const fs::path csv = out / "compare-methods-x" / ("diagnostics-" + std::string(name) + ".csv");
    ASSERT_TRUE(fs::is_regular_file(csv)) << csv;
    const std::string text = read_file(csv);
    EXPECT_EQ(line_count(text), 5u) << csv;  // header + 4 frames
    EXPECT_EQ(text.rfind("frame,t,omega_x", 0), 0u);
  }
  EXPECT_FALSE(fs::exists(out / "compare-methods-x/diagnostics.csv"));
}

TEST(Compare, PanelsShareTheInitialStateAndTime) {
  const fs::path out = fresh_dir("compare_rows");
  ASSERT_EQ(run_bookspin("render " + scene_path("compare-normalization") +
                         " --set render.width=128 --set render.height=96 --no-png --frames 3 -o " +
                         out.string())
                .status,
            0);
  const auto rows = [&](const char* name) {
    std::istringstream in(
        read_file(out / "compare-normalization" / (std::string("diagnostics-") + name + ".csv")));
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);)
      lines.push_back(line.substr(0, line.find(',', 2)));
    return lines;
  };
  // Frame 0 is the same initial state; every panel has the same frames and times.
  EXPECT_EQ(rows("matrix-svd"), rows("quaternion-not-normalized"));
  EXPECT_EQ(rows("particle-normalized").size(), 4u);
}

// Each tile's CSV is byte for byte what `bookspin simulate` writes for the tile's own scene:
// the comparison's keys without its [[compare]] entries, with the tile's model.* keys set
// (scenes/README.md, "Comparison scenes").
TEST(Compare, EachTilesCsvIsTheSimulationOfItsOwnScene) {
  struct Tile {
    const char* scene;
    const char* name;
    std::string model;  ///< the entry's model.* keys, as --set arguments
  };
  const std::vector<Tile> tiles = {
      {"compare-normalization", "particle-normalized",
       "--set 'model.kind=\"particle\"' --set model.normalize=true"},
      {"compare-normalization", "matrix-no-svd",
       "--set 'model.kind=\"rigid-matrix\"' --set model.normalize=false"},
      {"compare-normalization", "quaternion-not-normalized",
       "--set 'model.kind=\"rigid-quaternion\"' --set model.normalize=false"},
      {"compare-methods-x", "particle-mass-spring-euler",
       "--set 'model.kind=\"particle\"' --set 'model.integrator=\"euler\"'"},
      {"compare-methods-x", "rigid-body-quaternion-rk4",
       "--set 'model.kind=\"rigid-quaternion\"' --set 'model.integrator=\"rk4\"'"},
      {"compare-methods-x", "exact-jacobi-elliptic-functions", "--set 'model.kind=\"exact\"'"}};
  const fs::path out = fresh_dir("compare_tile_csvs");
  for (const char* scene : {"compare-normalization", "compare-methods-x"}) {
    const CliResult r = run_bookspin("render " + scene_path(scene) +
                                     " --set render.width=128 --set render.height=96 --no-png"
                                     " --frames 6 --jobs 2 -o " +
                                     (out / "render").string());
    ASSERT_EQ(r.status, 0) << r.output;
    const std::string text = read_file(scene_path(scene));
    std::ofstream(out / (std::string(scene) + ".toml")) << text.substr(0, text.find("[[compare]]"));
  }
  for (const Tile& tile : tiles) {
    const fs::path csv = out / (std::string(tile.name) + ".csv");
    const CliResult r =
        run_bookspin("simulate " + (out / (std::string(tile.scene) + ".toml")).string() + " " +
                     tile.model + " --set time.frames=6 --csv " + csv.string());
    ASSERT_EQ(r.status, 0) << r.output;
    const std::string simulated = read_file(csv);
    EXPECT_EQ(line_count(simulated), 7u) << csv;  // header + 6 frames
    EXPECT_EQ(
        read_file(out / "render" / tile.scene / ("diagnostics-" + std::string(tile.name) + ".csv")),
        simulated)
        << tile.scene << ": " << tile.name;
  }
}

// Bad [[compare]] keys are cases of the bad-input catalogue (tests/bad_scenes/compare-*).

TEST(Compare, SimulateRefusesAComparisonScene) {
  const CliResult r =
      run_bookspin("simulate " + scene_path("compare-methods-x") + " --csv /dev/null");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("comparison scene"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace bookspin::cli
