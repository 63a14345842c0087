// The manifest reader (output/manifest.hpp): what write_manifest() wrote comes back through
// read_manifest(), whatever the head: the outputs in their order and the warnings of the note
// (warnings_note()), each unescaped to the text it was, quotes, backslashes and control
// characters included.
#include "output/manifest.hpp"

#include <gtest/gtest.h>

#include <fstream>

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

}  // namespace
}  // namespace bookspin::output
