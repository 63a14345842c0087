// `bookspin bench` (issue 7) and the render options it relies on. No timings are asserted:
// the numbers depend on the machine; only that they are measured and written.
#include <gtest/gtest.h>

#include <iterator>

#include "cli_runner.hpp"

namespace bookspin::test {
namespace {

struct BenchRun {
  std::filesystem::path dir;  ///< the -o directory
  CliResult result;
  std::string csv;  ///< dir/bench.csv ("" if not written)
};

/// `bookspin bench fig09 ARGS -o <fresh NAME dir>`.
BenchRun run_bench(const std::string& name, const std::string& args) {
  BenchRun run{fresh_dir(name), {}, {}};
  run.result = run_bookspin("bench " + scene_path("fig09-matrix-unstable-x") + " " + args + " -o " +
                            run.dir.string());
  run.csv = read_file(run.dir / "bench.csv");
  return run;
}

TEST(BenchCommand, MemorySectionWritesTheCsvWithBothRunsAndTheirRatio) {
  const BenchRun run = run_bench("bench-memory", "--only memory --memory-frames 150");
  const CliResult& r = run.result;
  ASSERT_EQ(r.status, 0) << r.output;
  const std::string& csv = run.csv;
  EXPECT_EQ(csv.rfind("section,metric,value,unit,note\n", 0), 0u) << csv;
  EXPECT_NE(csv.find("peak RSS, render --no-png 100 frames"), std::string::npos) << csv;
  EXPECT_NE(csv.find("peak RSS, render --no-png 150 frames"), std::string::npos) << csv;
  EXPECT_NE(csv.find("peak RSS 150 / 100 frames"), std::string::npos) << csv;
  EXPECT_NE(r.output.find("section"), std::string::npos) << "the table goes to stdout";
}

TEST(BenchCommand, PipelineSectionReportsBestOfAlternatedRunsAndTheRatios) {
  const BenchRun run = run_bench("bench-pipeline", "--only pipeline --frames 2 --rounds 2");
  ASSERT_EQ(run.result.status, 0) << run.result.output;
  const std::string& csv = run.csv;
  for (const char* row : {"encoder alone (the floor), 2 frames 1280x720", "render --no-png / floor",
                          "render with PNGs / floor", "render --no-png, 4x anisotropic / floor",
                          "render --no-png, render.msaa = 1 / floor"}) {
    EXPECT_NE(csv.find(row), std::string::npos) << row << " missing from\n" << csv;
  }
  EXPECT_NE(csv.find("best of 2 alternated runs"), std::string::npos) << csv;
  EXPECT_EQ(csv.find("physics"), std::string::npos) << "--only pipeline ran other sections";
  // The renders went to a scratch directory that is gone: only the CSV is left here.
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(run.dir),
                          std::filesystem::directory_iterator()),
            1);
}

TEST(BenchCommand, UnknownSectionIsAUsageError) {
  EXPECT_EQ(run_bookspin("bench --only nonsense").status, 2);
}

TEST(RenderOptions, PngCompressionOverridesTheSceneAndIsRangeChecked) {
  const auto dir = fresh_dir("render-png-compression");
  const std::string common = "render " + scene_path("fig09-matrix-unstable-x") +
                             " --frames 2 --set render.width=64 --set render.height=36 -o ";
  ASSERT_EQ(run_bookspin(common + (dir / "stored").string() + " --png-compression 0").status, 0);
  ASSERT_EQ(run_bookspin(common + (dir / "deflated").string() + " --png-compression 9").status, 0);
  const auto frame =
      std::filesystem::path("fig09-matrix-unstable-x") / "frames" / "frame_00001.png";
  // Level 0 stores the pixels uncompressed: bigger than level 9's file.
  EXPECT_GT(std::filesystem::file_size(dir / "stored" / frame),
            std::filesystem::file_size(dir / "deflated" / frame));
  EXPECT_EQ(run_bookspin(common + dir.string() + " --png-compression 10").status, 2);
}

}  // namespace
}  // namespace bookspin::test
