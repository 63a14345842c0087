// make_cached (cache/make_cached.hpp): check the manifest, make, record. Counted against a
// make function that writes one file and counts its calls: made once, then up to date; made
// again when the head changes, an output is missing or changed size, or when forced; no
// manifest after a make that threw (unless it puts its outputs in place all or nothing); the
// earlier manifest and outputs untouched by one that was interrupted.
#include "cache/make_cached.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <stdexcept>
#include <vector>

#include "common/errors.hpp"
#include "common/stop.hpp"
#include "support/scratch.hpp"

namespace bookspin::cache {
namespace {

using test::ScratchDir;

/// The outputs `out/result.txt` under a head whose one member is "what": `what`.
CachedOutputs cached_in(const ScratchDir& dir, const std::string& what) {
  return {"result", dir / "manifest.json", "test", {{"what", {what}}}, dir.path()};
}

/// A make writing `out/result.txt` with `content`, counting its calls in `calls`.
std::function<Made()> counting_make(const ScratchDir& dir, const std::string& content, int& calls) {
  return [&dir, content, &calls] {
    ++calls;
    std::ofstream(dir / "result.txt") << content;
    return Made{{dir / "result.txt"}, "  \"note\": \"test\",\n"};
  };
}

/// make_cached of `cached` with `make`, up-to-date check by sizes, no note.
Outcome run(const CachedOutputs& cached, const std::function<Made()>& make, bool force = false) {
  return make_cached(cached, {force, false, {}}, make);
}

const std::string kHead = "one";

TEST(MakeCached, MakesOnceThenIsUpToDate) {
  ScratchDir dir;
  int calls = 0;
  const CachedOutputs cached = cached_in(dir, kHead);
  const auto make = counting_make(dir, "abc", calls);
  EXPECT_EQ(run(cached, make), Outcome::made);
  EXPECT_TRUE(std::filesystem::is_regular_file(dir / "manifest.json"));
  EXPECT_EQ(run(cached, make), Outcome::up_to_date);
  EXPECT_EQ(run(cached, make), Outcome::up_to_date);
  EXPECT_EQ(calls, 1);
}

TEST(MakeCached, MakesAgainWhenTheHeadChangesAndSaysWhy) {
  ScratchDir dir;
  int calls = 0;
  const auto make = counting_make(dir, "abc", calls);
  EXPECT_EQ(run(cached_in(dir, kHead), make), Outcome::made);
  std::vector<std::string> names, reasons;
  const Freshness freshness{false, false, [&](const std::string& name, const std::string& reason) {
                              names.push_back(name);
                              reasons.push_back(reason);
                            }};
  const CachedOutputs changed = cached_in(dir, "two");
  EXPECT_EQ(make_cached(changed, freshness, make), Outcome::made);
  EXPECT_EQ(make_cached(changed, freshness, make), Outcome::up_to_date);
  EXPECT_EQ(calls, 2);
  ASSERT_EQ(reasons.size(), 1u);  // only the remake, and only because a manifest was there
  EXPECT_FALSE(reasons[0].empty());
  EXPECT_EQ(names[0], "result");
}

TEST(MakeCached, MakesAgainWhenAnInputFileChangesAndRefusesOneItCannotRead) {
  ScratchDir dir;
  int calls = 0;
  const auto make = counting_make(dir, "abc", calls);
  std::ofstream(dir / "motion.csv") << "t\n0\n";
  CachedOutputs cached = cached_in(dir, kHead);
  cached.input_files = {dir / "motion.csv"};
  EXPECT_EQ(run(cached, make), Outcome::made);
  EXPECT_NE(cached_head(cached).find("\"file\": \"motion.csv\""), std::string::npos);
  EXPECT_EQ(run(cached, make), Outcome::up_to_date);
  std::ofstream(dir / "motion.csv") << "t\n1\n";  // same size, other bytes
  EXPECT_EQ(run(cached, make), Outcome::made);
  EXPECT_EQ(calls, 2);
  cached.input_files = {dir / "missing.csv"};
  EXPECT_THROW(run(cached, make), InputError);
  EXPECT_EQ(calls, 2);
}

TEST(MakeCached, MakesAgainWhenAnOutputIsMissingOrChangedSize) {
  ScratchDir dir;
  int calls = 0;
  const CachedOutputs cached = cached_in(dir, kHead);
  const auto make = counting_make(dir, "abc", calls);
  EXPECT_EQ(run(cached, make), Outcome::made);
  std::filesystem::remove(dir / "result.txt");
  EXPECT_EQ(run(cached, make), Outcome::made);
  std::ofstream(dir / "result.txt") << "abcd";  // one byte more than the manifest says
  EXPECT_EQ(run(cached, make), Outcome::made);
  EXPECT_EQ(run(cached, make), Outcome::up_to_date);
  EXPECT_EQ(calls, 3);
}

TEST(MakeCached, ForceMakesEvenWhenUpToDate) {
  ScratchDir dir;
  int calls = 0;
  const CachedOutputs cached = cached_in(dir, kHead);
  const auto make = counting_make(dir, "abc", calls);
  EXPECT_EQ(run(cached, make), Outcome::made);
  EXPECT_EQ(run(cached, make, /*force=*/true), Outcome::made);
  EXPECT_EQ(calls, 2);
}

/// The bytes of `file`.
std::string bytes_of(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// A make stopped by a signal puts nothing in place: Interrupted goes on, and the earlier
// manifest keeps its bytes (its outputs are still the ones it lists). Any other throw removes
// the manifest: the outputs may be half new.
TEST(MakeCached, AnInterruptedMakeKeepsTheManifestAndAThrowingOneRemovesIt) {
  ScratchDir dir;
  int calls = 0;
  EXPECT_EQ(run(cached_in(dir, kHead), counting_make(dir, "abc", calls)), Outcome::made);
  const std::string before = bytes_of(dir / "manifest.json");
  const CachedOutputs changed = cached_in(dir, "two");

  try {
    run(changed, []() -> Made { throw Interrupted(2); });
    ADD_FAILURE() << "Interrupted did not go on";
  } catch (const Interrupted& stop) {
    EXPECT_EQ(stop.signal(), 2);
  }
  EXPECT_EQ(bytes_of(dir / "manifest.json"), before);
  EXPECT_EQ(run(cached_in(dir, kHead), counting_make(dir, "abc", calls)), Outcome::up_to_date);

  EXPECT_THROW(run(changed, []() -> Made { throw std::runtime_error("disk full"); }),
               std::runtime_error);
  EXPECT_FALSE(std::filesystem::exists(dir / "manifest.json"));
  EXPECT_EQ(calls, 1);
}

// Outputs that go in place together or not at all (output::OutputSet): when make throws,
// nothing of the earlier outputs changed, so their manifest keeps its bytes. A manifest that
// cannot be written after a make that succeeded (an output it lists cannot be read) is
// removed: it would describe the outputs just replaced.
TEST(MakeCached, AllOrNothingKeepsTheManifestOnAThrowAndDropsOneItCannotRewrite) {
  ScratchDir dir;
  int calls = 0;
  EXPECT_EQ(run(cached_in(dir, kHead), counting_make(dir, "abc", calls)), Outcome::made);
  const std::string before = bytes_of(dir / "manifest.json");
  CachedOutputs failing = cached_in(dir, "two");
  failing.all_or_nothing = true;
  EXPECT_THROW(run(failing, []() -> Made { throw std::runtime_error("muxer failed"); }),
               std::runtime_error);
  EXPECT_EQ(bytes_of(dir / "manifest.json"), before);
  EXPECT_EQ(run(cached_in(dir, kHead), counting_make(dir, "abc", calls)), Outcome::up_to_date);

  CachedOutputs unlisted = cached_in(dir, "three");
  unlisted.all_or_nothing = true;
  EXPECT_THROW(run(unlisted,
                   [&dir] {
                     return Made{{dir / "result.txt", dir / "never-written.txt"}};
                   }),
               OutputError);
  EXPECT_FALSE(std::filesystem::exists(dir / "manifest.json"));
}

// A run that makes fewer outputs than the earlier one (another format, no frames) removes the
// files the earlier manifest listed and it did not make, and the folders that leaves empty;
// nothing it did not list, nothing outside out_dir, and nothing when interrupted.
TEST(MakeCached, RemovesWhatTheEarlierRunListedAndThisOneDidNotMake) {
  ScratchDir dir;
  const std::filesystem::path out = dir / "out";
  std::filesystem::create_directories(out / "frames" / "deep");
  std::ofstream(dir / "outside.txt") << "not ours";
  const CachedOutputs cached{"out", out / "manifest.json", "test", {{"what", {kHead}}}, out};
  ASSERT_EQ(
      run(cached,
          [&out] {
            for (const char* name : {"kept.txt", "gone.gif", "frames/deep/f.png", "unlisted.txt"})
              std::ofstream(out / name) << name;
            return Made{{out / "kept.txt", out / "gone.gif", out / "frames/deep/f.png"}};
          }),
      Outcome::made);
  // A hand-edited earlier manifest may name a path outside OUT: it is never touched.
  {
    std::string text = bytes_of(cached.manifest);
    const std::string outputs = "  \"outputs\": [\n";
    ASSERT_NE(text.find(outputs), std::string::npos);
    text.insert(text.find(outputs) + outputs.size(),
                "    {\"path\": \"../outside.txt\", \"size\": 8, \"sha256\": \"" +
                    std::string(64, '0') + "\"},\n");
    std::ofstream(cached.manifest) << text;
  }

  CachedOutputs changed = cached;
  changed.options = {{"what", {std::string("two")}}};
  EXPECT_THROW(run(changed, []() -> Made { throw Interrupted(15); }), Interrupted);
  EXPECT_TRUE(std::filesystem::exists(out / "gone.gif"));  // nothing removed when interrupted

  EXPECT_EQ(run(changed,
                [&out] {
                  std::ofstream(out / "kept.txt") << "again";
                  return Made{{out / "kept.txt"}};
                }),
            Outcome::made);
  EXPECT_TRUE(std::filesystem::exists(out / "kept.txt"));
  EXPECT_FALSE(std::filesystem::exists(out / "gone.gif"));
  EXPECT_FALSE(std::filesystem::exists(out / "frames"));  // left empty, so removed
  EXPECT_TRUE(std::filesystem::exists(out / "unlisted.txt"));
  EXPECT_TRUE(std::filesystem::exists(dir / "outside.txt"));
}

// make_cached_together: only the stale ones are made, in order; every output is put in place
// once, after every make and before any manifest; a throw while putting them in place leaves
// every earlier output and manifest as they were; one that is not all or nothing is refused.
TEST(MakeCached, TogetherPutsEveryOutputInPlaceBeforeAnyManifest) {
  ScratchDir dir;
  std::vector<CachedOutputs> each;
  for (const char* name : {"a", "b", "c"}) {
    std::filesystem::create_directories(dir / name);
    each.push_back({name,
                    dir / name / "manifest.json",
                    "test",
                    {{"what", {kHead}}},
                    dir.path(),
                    nullptr,
                    /*all_or_nothing=*/true});
  }
  std::vector<std::size_t> made;
  int put = 0;
  const auto make = [&](std::size_t i) {
    made.push_back(i);
    EXPECT_EQ(put, 0);
    std::ofstream(dir / (each[i].name + ".txt")) << each[i].name;
    return Made{{dir / (each[i].name + ".txt")}};
  };
  const auto put_in_place = [&] {
    ++put;
    for (const CachedOutputs& c : each) EXPECT_FALSE(std::filesystem::exists(c.manifest));
  };
  const Freshness freshness{false, false, {}};
  EXPECT_EQ(make_cached_together(each, freshness, make, put_in_place),
            (std::vector<Outcome>{Outcome::made, Outcome::made, Outcome::made}));
  EXPECT_EQ(made, (std::vector<std::size_t>{0, 1, 2}));
  EXPECT_EQ(put, 1);
  // b changed: only b made again.
  std::ofstream(dir / "b.txt") << "longer";
  made.clear();
  put = 0;
  const std::string a_manifest = bytes_of(each[0].manifest);
  EXPECT_EQ(make_cached_together(each, freshness, make, [&] { ++put; }),
            (std::vector<Outcome>{Outcome::up_to_date, Outcome::made, Outcome::up_to_date}));
  EXPECT_EQ(made, (std::vector<std::size_t>{1}));
  EXPECT_EQ(put, 1);
  EXPECT_EQ(bytes_of(each[0].manifest), a_manifest);
  // A throw while putting in place: every manifest as it was.
  std::vector<std::string> manifests;
  for (const CachedOutputs& c : each) manifests.push_back(bytes_of(c.manifest));
  put = 0;
  EXPECT_THROW(make_cached_together(each, {true, false, {}}, make, [] { throw Interrupted(2); }),
               Interrupted);
  for (std::size_t i = 0; i < each.size(); ++i) EXPECT_EQ(bytes_of(each[i].manifest), manifests[i]);
  each[2].all_or_nothing = false;
  made.clear();
  EXPECT_THROW(make_cached_together(each, {true, false, {}}, make, [] {}), InternalError);
  EXPECT_TRUE(made.empty());
}

}  // namespace
}  // namespace bookspin::cache
