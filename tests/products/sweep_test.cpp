// The sweep product: a whole sweep writes OUT/<name>-sweep.csv and -sweep.png with its
// manifest OUT/<name>/sweep-manifest.json (the ranges and measures as given in its head) and
// is up to date the second time; a shard writes OUT/<name>-sweep.shard-K-of-N.csv and no
// manifest, and the shards merge into the one-process CSV (docs/outputs.md, docs/sweeps.md).
#include "products/sweep.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "output/manifest.hpp"
#include "support/cli_runner.hpp"
#include "support/scratch.hpp"

namespace bookspin::products {
namespace {

namespace fs = std::filesystem;

SweepJob tiny_sweep(const test::ScratchDir& dir) {
  std::ofstream(dir / "tiny.toml") << "[scene]\nname = \"tiny\"\n[model]\nkind = \"exact\"\n"
                                      "[time]\nframes = 10\n";
  SweepJob job;
  job.scene_path = dir / "tiny.toml";
  job.vary = {"initial.jiggle=0.001:0.002:2"};
  job.measures = "energy_drift";
  job.jobs = 1;
  job.out_dir = dir / "out";
  return job;
}

/// The lines of a text file.
std::vector<std::string> lines_of(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

TEST(Sweep, AWholeSweepWritesItsCsvPngAndManifestThenIsUpToDate) {
  test::ScratchDir dir;
  const SweepJob job = tiny_sweep(dir);
  const SweepOutcome done = make_sweep(job);
  EXPECT_EQ(done.outcome, cache::Outcome::made);
  EXPECT_EQ(done.name, "tiny");
  EXPECT_EQ(done.written, (std::vector<fs::path>{dir / "out" / "tiny-sweep.csv",
                                                 dir / "out" / "tiny-sweep.png"}));
  EXPECT_EQ(lines_of(dir / "out" / "tiny-sweep.csv").size(), 3u);  // the header, two points
  const fs::path manifest = dir / "out" / "tiny" / "sweep-manifest.json";
  EXPECT_EQ(output::read_manifest(manifest).outputs,
            (std::vector<std::string>{"tiny-sweep.csv", "tiny-sweep.png"}));
  const std::string text = test::read_file(manifest);
  EXPECT_NE(text.find("\"command\": \"sweep\""), std::string::npos) << text;
  EXPECT_NE(text.find("\"options\": {\n    \"vary\": [\"initial.jiggle=0.001:0.002:2\"],\n"
                      "    \"measures\": \"energy_drift\"\n  }"),
            std::string::npos)
      << text;
  EXPECT_EQ(make_sweep(job).outcome, cache::Outcome::up_to_date);
  SweepJob more = job;
  more.measures = "energy_drift,first_flip";
  EXPECT_EQ(make_sweep(more).outcome, cache::Outcome::made);
}

TEST(Sweep, NoMeasureIsABadInput) {
  test::ScratchDir dir;
  SweepJob job = tiny_sweep(dir);
  job.measures.clear();
  try {
    make_sweep(job);
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("give --measure"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(Sweep, ShardsWriteTheirCsvsWithoutAManifestAndMergeIntoTheWholeSweep) {
  test::ScratchDir dir;
  SweepJob job = tiny_sweep(dir);
  job.shard_count = 2;
  std::vector<fs::path> shards;
  for (int k = 0; k < 2; ++k) {
    job.shard_index = k;
    const SweepOutcome done = make_sweep(job);
    EXPECT_EQ(done.outcome, cache::Outcome::made);
    const fs::path shard = dir / "out" / ("tiny-sweep.shard-" + std::to_string(k) + "-of-2.csv");
    EXPECT_TRUE(fs::is_regular_file(shard)) << shard;
    shards.push_back(shard);
  }
  EXPECT_FALSE(fs::exists(dir / "out" / "tiny" / "sweep-manifest.json"));
  // A shard missing from the merge is named where the given ones are.
  try {
    merge_sweep_shards({shards[0]}, dir / "merged");
    ADD_FAILURE() << "merged without shard 1";
  } catch (const InputError& e) {
    const std::string missing = (dir / "out" / "tiny-sweep.shard-1-of-2.csv").string();
    EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
  }
  const std::vector<fs::path> merged = merge_sweep_shards(shards, dir / "merged");
  EXPECT_EQ(merged, (std::vector<fs::path>{dir / "merged" / "tiny-sweep.csv",
                                           dir / "merged" / "tiny-sweep.png"}));
  // The same table as the one-process sweep's.
  const SweepOutcome whole = make_sweep(tiny_sweep(dir));
  ASSERT_EQ(whole.outcome, cache::Outcome::made);
  EXPECT_EQ(test::read_file(dir / "merged" / "tiny-sweep.csv"),
            test::read_file(dir / "out" / "tiny-sweep.csv"));
}

}  // namespace
}  // namespace bookspin::products
