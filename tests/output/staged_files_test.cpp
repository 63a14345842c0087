// A product's several files staged and put in place together (output::StagedFiles), with a file
// made elsewhere adopted into the set (a clip rendered into a scratch folder).
#include "output/staged_files.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "common/errors.hpp"
#include "common/text_file.hpp"
#include "support/scratch.hpp"

namespace bookspin::output {
namespace {

namespace fs = std::filesystem;

TEST(StagedFiles, AdoptedFileGoesInPlaceWithTheOthers) {
  const fs::path dir = bookspin::test::fresh_dir("output/staged_adopt");
  fs::create_directories(dir / "scratch");
  std::ofstream(dir / "scratch" / "made.bin") << "video bytes";
  {
    StagedFiles files;
    files.text(dir / "table.csv", "a,b\n1,2\n");
    files.adopt(dir / "clip.mp4", dir / "scratch" / "made.bin");
    // Nothing in place before the commit; the made file has moved to the staged temporary.
    EXPECT_FALSE(fs::exists(dir / "table.csv"));
    EXPECT_FALSE(fs::exists(dir / "clip.mp4"));
    EXPECT_FALSE(fs::exists(dir / "scratch" / "made.bin"));
    files.commit();
  }
  EXPECT_EQ(read_text_file(dir / "clip.mp4", "clip"), "video bytes");
  EXPECT_EQ(read_text_file(dir / "table.csv", "table"), "a,b\n1,2\n");
  // Only the two files: no temporary left beside them.
  int entries = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++entries;
  EXPECT_EQ(entries, 3);  // table.csv, clip.mp4, scratch/
}

TEST(StagedFiles, AdoptingAMissingFileThrowsAndPutsNothingInPlace) {
  const fs::path dir = bookspin::test::fresh_dir("output/staged_adopt_missing");
  std::ofstream(dir / "table.csv") << "earlier\n";
  {
    StagedFiles files;
    files.text(dir / "table.csv", "new\n");
    try {
      files.adopt(dir / "clip.mp4", dir / "no-such-file");
      ADD_FAILURE() << "no error";
    } catch (const OutputError& e) {
      EXPECT_NE(std::string(e.what()).find("clip.mp4"), std::string::npos) << e.what();
    }
  }  // never committed
  EXPECT_EQ(read_text_file(dir / "table.csv", "table"), "earlier\n");
  EXPECT_FALSE(fs::exists(dir / "clip.mp4"));
  int entries = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++entries;
  EXPECT_EQ(entries, 1);
}

}  // namespace
}  // namespace bookspin::output
