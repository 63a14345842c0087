#include "output/atomic_output.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <map>
#include <string>

#include "output/output_dir.hpp"
#include "support/scratch.hpp"

namespace bookspin::output {
namespace {
namespace fs = std::filesystem;
using bookspin::test::ScratchDir;
using bookspin::test::tree_of;

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

std::vector<std::string> kept_sorted(std::vector<std::string> names) {
  std::sort(names.begin(), names.end());
  return names;
}

/// A pid no process has: a child that has exited and been reaped.
pid_t dead_pid() {
  const pid_t pid = fork();
  if (pid == 0) _exit(0);
  waitpid(pid, nullptr, 0);
  return pid;
}

// The first AtomicOutput in a folder removes the temporaries there whose run is gone: the
// pid is dead, or alive but started after the temporary was last written (reused). A live
// run's temporary, an aside copy (.old-) and names that only look alike stay.
TEST(AtomicOutput, RemovesTheTemporariesOfDeadRunsInItsFolder) {
  ScratchDir dir;
  const std::string dead = std::to_string(dead_pid()), live = std::to_string(getpid());
  write_text(dir / (".clip.mp4.tmp-" + dead + "-0"), "x");
  write_text(dir / (".other.png.tmp-" + dead + "-4"), "x");
  fs::create_directories(dir / (".clip.mp4.tmp-" + dead + "-1") / "inner");
  write_text(dir / (".clip.mp4.tmp-" + live + "-2"), "x");
  fs::last_write_time(dir / (".clip.mp4.tmp-" + live + "-2"),
                      fs::file_time_type::clock::now() - std::chrono::hours(24 * 365 * 20));
  const std::vector<std::string> kept = {".clip.mp4.tmp-" + live + "-3",
                                         ".clip.mp4.old-" + dead + "-0", ".clip.mp4.tmp-x-0",
                                         ".clip.mp4.tmp-" + dead, "clip.mp4.tmp-" + dead + "-0"};
  for (const auto& name : kept) write_text(dir / name, "x");
  AtomicFile file(dir / "clip.mp4");
  EXPECT_EQ(dir.entries(), kept_sorted(kept));
}

// ---- OutputSet: the outputs of one run, all or nothing (docs/outputs.md) ----------------

TEST(OutputSet, CommitPutsEveryOutputInPlaceAndLeavesNothingAside) {
  ScratchDir dir;
  write_text(dir / "clip.mp4", "old mp4");
  fs::create_directory(dir / "frames");
  write_text(dir / "frames" / "frame_0.png", "old frame");
  AtomicFile mp4(dir / "clip.mp4");
  AtomicFile gif(dir / "clip.gif");  // no earlier GIF
  AtomicDirectory frames(dir / "frames");
  write_text(mp4.temp_path(), "new mp4");
  write_text(gif.temp_path(), "new gif");
  write_text(frames.temp_path() / "frame_1.png", "new frame");
  OutputSet set;
  set.add(mp4);
  set.add(gif);
  set.add(frames);
  EXPECT_EQ(read_text(dir / "clip.mp4"), "old mp4");  // nothing in place before commit()
  EXPECT_FALSE(fs::exists(dir / "clip.gif"));
  set.commit();
  EXPECT_TRUE(mp4.committed() && gif.committed() && frames.committed());
  const std::map<std::string, std::string> expected{{"clip.gif", "new gif"},
                                                    {"clip.mp4", "new mp4"},
                                                    {"frames", "<dir>"},
                                                    {"frames/frame_1.png", "new frame"}};
  EXPECT_EQ(tree_of(dir.path()), expected);
  EXPECT_THROW(set.commit(), std::logic_error);
}

// The muxer or a rename failing on the last output must not cost the ones before it: an
// occupied GIF path (a folder with a file in it) cannot be replaced by a file, so the set
// puts back the MP4 and the frames it had already put in place, removes the CSV that had no
// earlier version, and leaves no temporary.
TEST(OutputSet, AnOutputThatCannotBePutInPlaceLeavesTheFolderAsItWas) {
  ScratchDir dir;
  write_text(dir / "clip.mp4", "old mp4");
  fs::create_directory(dir / "frames");
  write_text(dir / "frames" / "frame_0.png", "old frame");
  fs::create_directory(dir / "clip.gif");
  write_text(dir / "clip.gif" / "someone's.txt", "occupied");
  const auto before = tree_of(dir.path());
  {
    AtomicFile mp4(dir / "clip.mp4");
    AtomicDirectory frames(dir / "frames");
    AtomicFile csv(dir / "diagnostics.csv");
    AtomicFile gif(dir / "clip.gif");
    write_text(mp4.temp_path(), "new mp4");
    write_text(frames.temp_path() / "frame_1.png", "new frame");
    write_text(csv.temp_path(), "new csv");
    write_text(gif.temp_path(), "new gif");
    OutputSet set;
    for (AtomicOutput* output : std::initializer_list<AtomicOutput*>{&mp4, &frames, &csv, &gif})
      set.add(*output);
    try {
      set.commit();
      FAIL() << "a GIF replaced a folder";
    } catch (const OutputError& e) {
      EXPECT_NE(std::string(e.what()).find((dir / "clip.gif").string()), std::string::npos)
          << e.what();
    }
    EXPECT_FALSE(mp4.committed());
    EXPECT_EQ(tree_of(dir.path()), before);  // before the outputs' destructors, too
  }
  EXPECT_EQ(tree_of(dir.path()), before);
}

TEST(OutputSet, AddingAFinishedOutputIsALogicError) {
  ScratchDir dir;
  AtomicFile file(dir / "a.txt");
  write_text(file.temp_path(), "a");
  file.commit();
  OutputSet set;
  EXPECT_THROW(set.add(file), std::logic_error);
}

// make_directories notes only what it made; remove_empty_made_directories takes back the
// empty ones, deepest first, and leaves a folder that holds something.
TEST(OutputDir, RemovesOnlyTheEmptyFoldersItMade) {
  ScratchDir dir;
  fs::create_directories(dir / "there");
  std::error_code ec;
  make_directories(dir / "there" / "a" / "b" / "c", ec);
  ASSERT_FALSE(ec);
  make_directories(dir / "x" / "y", ec);
  ASSERT_FALSE(ec);
  write_text(dir / "x" / "kept.txt", "x");
  remove_empty_made_directories();
  EXPECT_TRUE(fs::is_directory(dir / "there"));  // not made here
  EXPECT_FALSE(fs::exists(dir / "there" / "a"));
  EXPECT_TRUE(fs::exists(dir / "x" / "kept.txt"));
  EXPECT_FALSE(fs::exists(dir / "x" / "y"));
}

}  // namespace
}  // namespace bookspin::output
