// The accuracy product: its manifest head holds --flips, --dt and --methods (docs/outputs.md:
// "`--flips`, `--dt` and `--methods` in its head", numbers to 17 digits, methods as "KIND
// INTEGRATOR"); a report writes the seven files of its layout and their manifest, and is up to
// date the second time (its ns/step column then the first run's timing, docs/accuracy.md).
#include "products/accuracy.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "output/manifest.hpp"
#include "support/cli_runner.hpp"
#include "support/scratch.hpp"

namespace bookspin::products {
namespace {

namespace fs = std::filesystem;

AccuracyJob quaternion_rk4(const test::ScratchDir& dir) {
  fs::copy_file(fs::path(BOOKSPIN_SOURCE_DIR) / "scenes" / "exact-unstable-x.toml", dir / "x.toml",
                fs::copy_options::overwrite_existing);
  AccuracyJob job;
  job.request.scene = scene::parse_scene(dir / "x.toml", {"scene.name=\"x\""});
  job.request.flips = 1.5;
  job.request.dts = {0.1, 0.2};
  job.request.methods = analysis::parse_methods("rigid-quaternion:rk4");
  job.out_dir = dir / "out";
  return job;
}

TEST(Accuracy, TheHeadHoldsTheFlipsTheStepsAndTheMethods) {
  test::ScratchDir dir;
  AccuracyJob job = quaternion_rk4(dir);
  job.request.dts = {0.1, 1.0 / 3.0};
  job.request.methods = analysis::parse_methods("rigid-matrix:euler,rigid-quaternion:rk4");
  const std::string head = accuracy_manifest_head(job);
  EXPECT_NE(head.find("\"command\": \"accuracy\""), std::string::npos) << head;
  EXPECT_NE(head.find("\"options\": {\n"
                      "    \"flips\": 1.5,\n"
                      "    \"dt\": [0.10000000000000001, 0.33333333333333331],\n"
                      "    \"methods\": [\"rigid-matrix euler\", \"rigid-quaternion rk4\"]\n"
                      "  }"),
            std::string::npos)
      << head;
}

TEST(Accuracy, AReportWritesItsSevenFilesAndManifestThenIsUpToDate) {
  test::ScratchDir dir;
  const AccuracyJob job = quaternion_rk4(dir);
  EXPECT_EQ(make_accuracy(job), cache::Outcome::made);
  const std::vector<std::string> files{
      "x-accuracy.csv",  "x-accuracy.png", "x-work-precision.png", "x-energy-vs-dt.png",
      "x-turnovers.png", "x-energy.png",   "x-energy.csv"};
  for (const std::string& file : files)
    EXPECT_TRUE(fs::is_regular_file(dir / "out" / file)) << file;
  EXPECT_EQ(output::read_manifest(dir / "out" / "x" / "accuracy-manifest.json").outputs, files);
  // The table: the header and one row per dt.
  std::ifstream csv(dir / "out" / "x-accuracy.csv");
  int lines = 0;
  for (std::string line; std::getline(csv, line);) ++lines;
  EXPECT_EQ(lines, 3);
  const std::string before = test::read_file(dir / "out" / "x-accuracy.csv");
  EXPECT_EQ(make_accuracy(job), cache::Outcome::up_to_date);
  EXPECT_EQ(test::read_file(dir / "out" / "x-accuracy.csv"), before);  // not measured again
}

}  // namespace
}  // namespace bookspin::products
