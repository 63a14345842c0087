#include "output/atomic_output.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "scratch_dir.hpp"

namespace bookspin::output {
namespace {
namespace fs = std::filesystem;
using testing::ScratchDir;

void write_text(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(AtomicFile, TemporaryIsAHiddenSiblingAndAppearsOnlyOnCommit) {
  ScratchDir dir;
  AtomicFile file(dir / "clip.mp4");
  EXPECT_EQ(file.temp_path().parent_path(), dir.path());
  EXPECT_EQ(file.temp_path().filename().string().rfind(".clip.mp4.tmp-", 0), 0u);
  EXPECT_EQ(dir.entries().size(), 0u);  // only a name is reserved: nothing on disk yet

  write_text(file.temp_path(), "complete");
  EXPECT_FALSE(fs::exists(dir / "clip.mp4"));
  file.commit();
  EXPECT_TRUE(file.committed());
  EXPECT_EQ(read_text(dir / "clip.mp4"), "complete");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"clip.mp4"});
}

TEST(AtomicFile, UncommittedTemporaryIsRemovedByDestructorOrAbandon) {
  ScratchDir dir;
  {
    AtomicFile file(dir / "a.png");
    write_text(file.temp_path(), "half");
  }
  AtomicFile other(dir / "b.png");
  write_text(other.temp_path(), "half");
  other.abandon();
  EXPECT_TRUE(dir.entries().empty());
}

TEST(AtomicFile, CommitReplacesAnExistingFile) {
  ScratchDir dir;
  write_text(dir / "a.txt", "old");
  AtomicFile file(dir / "a.txt");
  write_text(file.temp_path(), "new");
  EXPECT_EQ(read_text(dir / "a.txt"), "old");
  file.commit();
  EXPECT_EQ(read_text(dir / "a.txt"), "new");
}

TEST(AtomicFile, FailedCommitThrowsOutputErrorNamingThePath) {
  ScratchDir dir;
  AtomicFile file(dir / "never-written.png");
  try {
    file.commit();
    FAIL() << "commit of a missing temporary succeeded";
  } catch (const OutputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find((dir / "never-written.png").string()), std::string::npos) << message;
    EXPECT_NE(message.find("No such file or directory"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos);
  }
  EXPECT_THROW(file.commit(), std::logic_error);
}

TEST(AtomicFile, TwoOutputsToOneNameGetDistinctTemporaries) {
  ScratchDir dir;
  AtomicFile first(dir / "x");
  AtomicFile second(dir / "x");
  EXPECT_NE(first.temp_path(), second.temp_path());
}

TEST(AtomicDirectory, EarlierCompleteDirectorySurvivesUntilCommit) {
  ScratchDir dir;
  fs::create_directory(dir / "frames");
  write_text(dir / "frames" / "old.png", "old");

  AtomicDirectory frames(dir / "frames");
  write_text(frames.temp_path() / "new.png", "new");
  EXPECT_TRUE(fs::exists(dir / "frames" / "old.png"));
  EXPECT_FALSE(fs::exists(dir / "frames" / "new.png"));

  frames.commit();
  EXPECT_FALSE(fs::exists(dir / "frames" / "old.png"));
  EXPECT_EQ(read_text(dir / "frames" / "new.png"), "new");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"frames"});  // nothing left aside
}

TEST(AtomicDirectory, AbandonedDirectoryLeavesTheOldOneUntouched) {
  ScratchDir dir;
  fs::create_directory(dir / "frames");
  write_text(dir / "frames" / "old.png", "old");
  {
    AtomicDirectory frames(dir / "frames/");  // trailing slash names the same directory
    write_text(frames.temp_path() / "new.png", "half");
  }
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"frames"});
  EXPECT_EQ(read_text(dir / "frames" / "old.png"), "old");
  EXPECT_FALSE(fs::exists(dir / "frames" / "new.png"));
}

TEST(AtomicDirectory, CreatesMissingParentsAndCommitsWhenNoOldDirectory) {
  ScratchDir dir;
  AtomicDirectory frames(dir / "out" / "run1" / "frames");
  write_text(frames.temp_path() / "0000.png", "x");
  frames.commit();
  EXPECT_TRUE(fs::exists(dir / "out" / "run1" / "frames" / "0000.png"));
}

TEST(AtomicDirectory, RefusesToReplaceAPlainFile) {
  ScratchDir dir;
  write_text(dir / "frames", "a file, not a directory");
  EXPECT_THROW(AtomicDirectory(dir / "frames"), OutputError);
  EXPECT_EQ(read_text(dir / "frames"), "a file, not a directory");
}

TEST(AtomicTextFile, AppearsOnlyOnCommitAndLeavesNothingWithoutIt) {
  ScratchDir dir;
  {
    AtomicTextFile file(dir / "rows.csv");
    file.stream() << "a,b\n";
    EXPECT_FALSE(fs::exists(dir / "rows.csv"));
    EXPECT_EQ(dir.entries().size(), 1u);  // the hidden temporary
  }
  EXPECT_TRUE(dir.entries().empty());
  write_text_file(dir / "page.html", "<p>done</p>");
  EXPECT_EQ(read_text(dir / "page.html"), "<p>done</p>");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"page.html"});
}

TEST(AtomicTextFile, UnwritableFolderIsAnOutputErrorNamingThePath) {
  ScratchDir dir;
  try {
    AtomicTextFile file(dir / "missing-folder" / "rows.csv");
    FAIL() << "no error";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("missing-folder/rows.csv"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace bookspin::output
