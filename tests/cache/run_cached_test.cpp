// run_cached (cache/run_cached.hpp): check the manifest, make, record. Counted against a make
// function that writes one file and counts its calls: made once, then up to date; made again
// when the head changes, an output is missing or changed size, or when forced; no manifest
// after a make that threw (unless it puts its outputs in place all or nothing) or was
// interrupted.
#include "cache/run_cached.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <stdexcept>

#include "common/errors.hpp"
#include "support/scratch.hpp"

namespace bookspin::cache {
namespace {

using test::ScratchDir;

/// A job writing `out/result.txt` with `content`, counting its calls in `calls`.
CachedJob counting_job(const ScratchDir& dir, const std::string& head, const std::string& content,
                       int& calls) {
  CachedJob job;
  job.manifest = dir / "manifest.json";
  job.head = head;
  job.out_dir = dir.path();
  job.make = [&dir, content, &calls]() -> std::optional<JobOutputs> {
    ++calls;
    std::ofstream(dir / "result.txt") << content;
    return JobOutputs{"  \"note\": \"test\",\n", {"result.txt"}};
  };
  return job;
}

const std::string kHead = "  \"what\": \"one\",\n";

TEST(RunCached, MakesOnceThenIsUpToDate) {
  ScratchDir dir;
  int calls = 0;
  const CachedJob job = counting_job(dir, kHead, "abc", calls);
  EXPECT_EQ(run_cached(job), CacheOutcome::made);
  EXPECT_TRUE(std::filesystem::is_regular_file(dir / "manifest.json"));
  EXPECT_EQ(run_cached(job), CacheOutcome::up_to_date);
  EXPECT_EQ(run_cached(job), CacheOutcome::up_to_date);
  EXPECT_EQ(calls, 1);
}

TEST(RunCached, MakesAgainWhenTheHeadChangesAndSaysWhy) {
  ScratchDir dir;
  int calls = 0;
  EXPECT_EQ(run_cached(counting_job(dir, kHead, "abc", calls)), CacheOutcome::made);
  std::vector<std::string> reasons;
  const auto note = [&reasons](const std::string& reason) { reasons.push_back(reason); };
  const CachedJob changed = counting_job(dir, "  \"what\": \"two\",\n", "abc", calls);
  EXPECT_EQ(run_cached(changed, note), CacheOutcome::made);
  EXPECT_EQ(run_cached(changed, note), CacheOutcome::up_to_date);
  EXPECT_EQ(calls, 2);
  ASSERT_EQ(reasons.size(), 1u);  // only the remake, and only because a manifest was there
  EXPECT_FALSE(reasons[0].empty());
}

TEST(RunCached, MakesAgainWhenAnOutputIsMissingOrChangedSize) {
  ScratchDir dir;
  int calls = 0;
  const CachedJob job = counting_job(dir, kHead, "abc", calls);
  EXPECT_EQ(run_cached(job), CacheOutcome::made);
  std::filesystem::remove(dir / "result.txt");
  EXPECT_EQ(run_cached(job), CacheOutcome::made);
  std::ofstream(dir / "result.txt") << "abcd";  // one byte more than the manifest says
  EXPECT_EQ(run_cached(job), CacheOutcome::made);
  EXPECT_EQ(run_cached(job), CacheOutcome::up_to_date);
  EXPECT_EQ(calls, 3);
}

TEST(RunCached, ForceMakesEvenWhenUpToDate) {
  ScratchDir dir;
  int calls = 0;
  CachedJob job = counting_job(dir, kHead, "abc", calls);
  EXPECT_EQ(run_cached(job), CacheOutcome::made);
  job.force = true;
  EXPECT_EQ(run_cached(job), CacheOutcome::made);
  EXPECT_EQ(calls, 2);
}

TEST(RunCached, AThrowingMakeRemovesTheManifestAndAnInterruptedOneWritesNone) {
  ScratchDir dir;
  int calls = 0;
  EXPECT_EQ(run_cached(counting_job(dir, kHead, "abc", calls)), CacheOutcome::made);
  CachedJob failing = counting_job(dir, "  \"what\": \"two\",\n", "abc", calls);
  failing.make = []() -> std::optional<JobOutputs> { throw std::runtime_error("disk full"); };
  EXPECT_THROW(run_cached(failing), std::runtime_error);
  EXPECT_FALSE(std::filesystem::exists(dir / "manifest.json"));  // the outputs may be half new

  CachedJob interrupted = counting_job(dir, kHead, "abc", calls);
  interrupted.make = []() -> std::optional<JobOutputs> { return std::nullopt; };
  EXPECT_EQ(run_cached(interrupted), CacheOutcome::interrupted);
  EXPECT_FALSE(std::filesystem::exists(dir / "manifest.json"));
  EXPECT_EQ(calls, 1);
}

// A job whose outputs go in place together or not at all (output::OutputSet): when its make
// throws, nothing of the earlier outputs changed, so their manifest keeps its bytes. A
// manifest that cannot be written after a make that succeeded (an output it lists cannot be
// read) is removed: it would describe the outputs just replaced.
TEST(RunCached, AllOrNothingKeepsTheManifestOnAThrowAndDropsOneItCannotRewrite) {
  ScratchDir dir;
  int calls = 0;
  EXPECT_EQ(run_cached(counting_job(dir, kHead, "abc", calls)), CacheOutcome::made);
  std::ifstream in(dir / "manifest.json");
  const std::string before(std::istreambuf_iterator<char>(in), {});
  CachedJob failing = counting_job(dir, "  \"what\": \"two\",\n", "abc", calls);
  failing.all_or_nothing = true;
  failing.make = []() -> std::optional<JobOutputs> { throw std::runtime_error("muxer failed"); };
  EXPECT_THROW(run_cached(failing), std::runtime_error);
  std::ifstream again(dir / "manifest.json");
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(again), {}), before);
  EXPECT_EQ(run_cached(counting_job(dir, kHead, "abc", calls)), CacheOutcome::up_to_date);

  CachedJob unlisted = counting_job(dir, "  \"what\": \"three\",\n", "abc", calls);
  unlisted.all_or_nothing = true;
  unlisted.make = []() -> std::optional<JobOutputs> {
    return JobOutputs{"", {"result.txt", "never-written.txt"}};
  };
  EXPECT_THROW(run_cached(unlisted), OutputError);
  EXPECT_FALSE(std::filesystem::exists(dir / "manifest.json"));
}

// A run that makes fewer outputs than the earlier one (another format, no frames) removes the
// files the earlier manifest listed and it did not make, and the folders that leaves empty;
// nothing it did not list, nothing outside out_dir, and nothing when interrupted.
TEST(RunCached, RemovesWhatTheEarlierRunListedAndThisOneDidNotMake) {
  ScratchDir dir;
  const std::filesystem::path out = dir / "out";
  std::filesystem::create_directories(out / "frames" / "deep");
  std::ofstream(dir / "outside.txt") << "not ours";
  CachedJob job;
  job.manifest = out / "manifest.json";
  job.out_dir = out;
  job.head = kHead;
  job.make = [&out]() -> std::optional<JobOutputs> {
    for (const char* name : {"kept.txt", "gone.gif", "frames/deep/f.png", "unlisted.txt"})
      std::ofstream(out / name) << name;
    return JobOutputs{"", {"kept.txt", "gone.gif", "frames/deep/f.png"}};
  };
  ASSERT_EQ(run_cached(job), CacheOutcome::made);
  // A hand-edited earlier manifest may name a path outside OUT: it is never touched.
  {
    std::ifstream in(job.manifest);
    std::string text(std::istreambuf_iterator<char>(in), {});
    const std::string outputs = "  \"outputs\": [\n";
    ASSERT_NE(text.find(outputs), std::string::npos);
    text.insert(text.find(outputs) + outputs.size(),
                "    {\"path\": \"../outside.txt\", \"size\": 8, \"sha256\": \"" +
                    std::string(64, '0') + "\"},\n");
    std::ofstream(job.manifest) << text;
  }

  CachedJob interrupted = job;
  interrupted.head = "  \"what\": \"two\",\n";
  interrupted.make = []() -> std::optional<JobOutputs> { return std::nullopt; };
  EXPECT_EQ(run_cached(interrupted), CacheOutcome::interrupted);
  EXPECT_TRUE(std::filesystem::exists(out / "gone.gif"));  // nothing removed when interrupted

  CachedJob fewer = interrupted;
  fewer.make = [&out]() -> std::optional<JobOutputs> {
    std::ofstream(out / "kept.txt") << "again";
    return JobOutputs{"", {"kept.txt"}};
  };
  EXPECT_EQ(run_cached(fewer), CacheOutcome::made);
  EXPECT_TRUE(std::filesystem::exists(out / "kept.txt"));
  EXPECT_FALSE(std::filesystem::exists(out / "gone.gif"));
  EXPECT_FALSE(std::filesystem::exists(out / "frames"));  // left empty, so removed
  EXPECT_TRUE(std::filesystem::exists(out / "unlisted.txt"));
  EXPECT_TRUE(std::filesystem::exists(dir / "outside.txt"));
}

}  // namespace
}  // namespace bookspin::cache
