// The manifest file (output/manifest.hpp): its exact text around the caller's head and note,
// the outputs one a line with their sizes and SHA-256 (of "abc" and of nothing, the standard's
// test values), read back by manifest_stale() and read_manifest(), whatever the head: the
// outputs in their order and the warnings of the note (warnings_note()), each unescaped to the
// text it was, quotes, backslashes and control characters included.
#include "output/manifest.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "common/text_file.hpp"
#include "output/sha256.hpp"
#include "support/scratch.hpp"

namespace bookspin::output {
namespace {

TEST(ManifestReader, TheWarningsOfTheNoteAndTheOutputsReadBackAsWritten) {
  const test::ScratchDir dir;
  std::ofstream(dir / "a.txt") << "a";
  std::ofstream(dir / "b.csv") << "bb";
  const std::vector<std::string> warnings{"fig10: simulation diverged at t = 267; kept",
                                          "a \"quoted\" panel \\ with a\ttab", ""};
  const std::string note = "  \"scene\": \"x\",\n" + warnings_note(warnings);
  EXPECT_EQ(warnings_note({"a\"b"}), "  \"warnings\": [\"a\\\"b\"],\n");
  write_manifest(dir / "manifest.json", "  \"what\": \"one\",\n", note, dir.path(),
                 {"a.txt", "b.csv"});
  const ManifestRecord record = read_manifest(dir / "manifest.json");
  EXPECT_EQ(record.outputs, (std::vector<std::string>{"a.txt", "b.csv"}));
  EXPECT_EQ(record.warnings, warnings);
}

TEST(ManifestReader, NoManifestOrNoWarningsReadsEmpty) {
  const test::ScratchDir dir;
  EXPECT_TRUE(read_manifest(dir / "missing.json").outputs.empty());
  std::ofstream(dir / "a.txt") << "a";
  write_manifest(dir / "manifest.json", "  \"what\": \"one\",\n", "", dir.path(), {"a.txt"});
  const ManifestRecord record = read_manifest(dir / "manifest.json");
  EXPECT_EQ(record.outputs, std::vector<std::string>{"a.txt"});
  EXPECT_TRUE(record.warnings.empty());
}

using test::ScratchDir;

// In a program, the build id is its file's SHA-256 (the Python module's case, another program
// loading the stages, is tests/python/test_render.py's).
TEST(Manifest, TheBuildIdIsTheSha256OfTheProgramsFile) {
  EXPECT_EQ(program_build_id(), sha256_file("/proc/self/exe").value_or("none"));
}

TEST(Manifest, IsTheHeadTheNoteThenTheOutputsOneALine) {
  ScratchDir dir;
  std::ofstream(dir / "a.csv") << "abc";
  std::filesystem::create_directories(dir / "sub");
  std::ofstream(dir / "sub/b.txt");
  const std::string head = "  \"manifest\": 1,\n  \"command\": \"test\",\n";
  write_manifest(dir / "m/manifest.json", head, "  \"note\": [],\n", dir.path(),
                 {"a.csv", "sub/b.txt"});
  EXPECT_EQ(read_text_file(dir / "m/manifest.json", "the manifest"),
            "{\n"
            "  \"manifest\": 1,\n"
            "  \"command\": \"test\",\n"
            // The head's SHA-256 (sha256sum of its two lines), where the head ends.
            "  \"head_sha256\": "
            "\"e72328bb49ea39087588a1c47a42ec32203523d1c45e23c8af5ca61a02be9556\",\n"
            "  \"note\": [],\n"
            "  \"outputs\": [\n"
            "    {\"path\": \"a.csv\", \"size\": 3, \"sha256\": "
            "\"ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad\"},\n"
            "    {\"path\": \"sub/b.txt\", \"size\": 0, \"sha256\": "
            "\"e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855\"}\n"
            "  ]\n"
            "}\n");
  EXPECT_EQ(manifest_stale(dir / "m/manifest.json", head, dir.path(), true), std::nullopt);
  EXPECT_NE(manifest_stale(dir / "m/manifest.json", "  \"manifest\": 2,\n", dir.path(), false),
            std::nullopt);
  EXPECT_EQ(read_manifest(dir / "m/manifest.json").outputs,
            (std::vector<std::string>{"a.csv", "sub/b.txt"}));
}

// A head that is only the start of the recorded one (a run with one more option member) is
// another head, not this one with a longer note; and the other way round.
TEST(Manifest, AHeadThatStartsTheRecordedOneIsStale) {
  ScratchDir dir;
  std::ofstream(dir / "a.csv") << "abc";
  const std::string head = "  \"manifest\": 1,\n  \"command\": \"test\",\n";
  const std::string longer = head + "  \"render\": {\"slow\": 4},\n";
  write_manifest(dir / "long.json", longer, "", dir.path(), {"a.csv"});
  write_manifest(dir / "short.json", head, "  \"render\": {\"slow\": 4},\n", dir.path(), {"a.csv"});
  EXPECT_EQ(manifest_stale(dir / "long.json", longer, dir.path(), true), std::nullopt);
  EXPECT_NE(manifest_stale(dir / "long.json", head, dir.path(), true), std::nullopt);
  EXPECT_EQ(manifest_stale(dir / "short.json", head, dir.path(), true), std::nullopt);
  EXPECT_NE(manifest_stale(dir / "short.json", longer, dir.path(), true), std::nullopt);
  EXPECT_EQ(read_manifest(dir / "long.json").outputs, std::vector<std::string>{"a.csv"});
}

}  // namespace
}  // namespace bookspin::output
