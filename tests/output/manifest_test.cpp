// The manifest file (output/manifest.hpp): its exact text around the caller's head and note,
// the outputs one a line with their sizes and SHA-256 (of "abc" and of nothing, the standard's
// test values), and read back by manifest_stale() and manifest_outputs().
#include "output/manifest.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "common/text_file.hpp"
#include "support/scratch.hpp"

namespace bookspin::output {
namespace {

using test::ScratchDir;

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
  EXPECT_EQ(manifest_outputs(dir / "m/manifest.json"),
            (std::vector<std::string>{"a.csv", "sub/b.txt"}));
}

}  // namespace
}  // namespace bookspin::output
