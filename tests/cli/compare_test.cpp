// Comparison scenes ([[compare]]): rendering, per-panel CSVs and key validation.
#include <gtest/gtest.h>

#include <algorithm>

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

// Bad [[compare]] keys are cases of the bad-input catalogue (tests/bad_scenes/compare-*).

TEST(Compare, SimulateRefusesAComparisonScene) {
  const CliResult r =
      run_bookspin("simulate " + scene_path("compare-methods-x") + " --csv /dev/null");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("comparison scene"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace bookspin::cli
