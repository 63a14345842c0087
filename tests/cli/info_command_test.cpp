// `bookspin info` names the faces every text is drawn with and their options
// (docs/architecture.md, the typeface stage), the same whatever the machine's font set-up.
#include <gtest/gtest.h>

#include <string>

#include "support/cli_runner.hpp"

namespace bookspin::cli {
namespace {

using namespace bookspin::test;  // the shared runner (tests/support)

// The text lines of `bookspin info` alone (the EGL and FFmpeg lines depend on the machine).
std::string text_lines(const std::string& info) {
  std::string lines;
  std::size_t at = 0;
  while (at < info.size()) {
    const std::size_t end = info.find('\n', at);
    const std::string line =
        info.substr(at, end == std::string::npos ? std::string::npos : end - at);
    if (line.rfind("text ", 0) == 0) lines += line + '\n';
    if (end == std::string::npos) break;
    at = end + 1;
  }
  return lines;
}

TEST(InfoCommand, NamesEveryFaceItsFileItsHashAndTheTextOptions) {
  const CliResult r = run_bookspin("info");
  ASSERT_EQ(r.status, 0) << r.output;
  const std::string text = text_lines(r.output);
  for (const char* file : {"DejaVuSans.ttf", "DejaVuSans-Bold.ttf", "DejaVuSansMono.ttf",
                           "DejaVuSerif.ttf", "DejaVuSerif-Bold.ttf", "DejaVuSerif-Italic.ttf",
                           "DroidSansFallbackFull.ttf", "Symbola_hint.ttf"}) {
    const std::size_t at = text.find(std::string("/") + file + ", SHA-256 ");
    ASSERT_NE(at, std::string::npos) << file << " not named:\n" << text;
    // The hash printed is the file's own, hashed here by sha256sum, not by bookspin.
    const std::size_t start = text.rfind("built in from ", at) + 14;
    const std::string path = text.substr(start, at + 1 + std::string(file).size() - start);
    std::string sum;
    if (run_shell("sha256sum '" + path + "' 2>/dev/null", sum) == 0) {
      const std::string printed = text.substr(at + std::string(file).size() + 11, 64);
      EXPECT_EQ(sum.substr(0, 64), printed) << path;
    }
  }
  EXPECT_NE(text.find("text face: DejaVu Sans (Version 2.37)"), std::string::npos) << text;
  EXPECT_NE(text.find("text face: Droid Sans Fallback ("), std::string::npos) << text;
  EXPECT_NE(text.find("text face: Symbola ("), std::string::npos) << text;
  EXPECT_NE(text.find("text options: antialias gray, hint style slight, hint metrics on, "
                      "subpixel order default"),
            std::string::npos)
      << text;
}

// Another fontconfig file, locale and home: the same words (and so the same faces and options).
TEST(InfoCommand, TheTextLinesAreTheSameUnderAnotherTextSetUp) {
  const CliResult plain = run_bookspin("info");
  const CliResult other = run_bookspin_env(
      std::string("FONTCONFIG_FILE=") + BOOKSPIN_SOURCE_DIR +
          "/tests/picture/another_text_set_up/fonts.conf HOME=/nonexistent LC_ALL=ja_JP.UTF-8 "
          "FREETYPE_PROPERTIES=truetype:interpreter-version=35",
      "info");
  ASSERT_EQ(other.status, 0) << other.output;
  EXPECT_FALSE(text_lines(plain.output).empty());
  EXPECT_EQ(text_lines(plain.output), text_lines(other.output));
}

// A standard output that cannot be written (/dev/full: every write fails with ENOSPC) is a
// failed write: exit 1, naming it, not exit 0 with everything lost.
TEST(InfoCommand, AStandardOutputThatCannotBeWrittenIsAFailedWrite) {
  std::string said;
  const int status = run_shell(std::string(BOOKSPIN_EXE) + " info 2>&1 >/dev/full", said);
  EXPECT_EQ(status, 1) << said;
  EXPECT_EQ(said, "bookspin: error: cannot write the standard output: No space left on device\n");
}

// The text lines need no GL: without an EGL driver (libglvnd given no vendor library) they are
// printed, the same as with one, before the EGL failure (exit 1) is said.
TEST(InfoCommand, TheTextLinesArePrintedWithoutAnEglDriver) {
  const CliResult plain = run_bookspin("info");
  ASSERT_EQ(plain.status, 0) << plain.output;
  const SplitResult none = [] {
    SplitResult r;
    const std::string dir = std::string(BOOKSPIN_BINARY_DIR) + "/test-output";
    std::filesystem::create_directories(dir);
    const std::string err = dir + "/info-no-egl-" + std::to_string(getpid()) + ".txt";
    r.status = run_shell(
        "__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent.json "
        "__EGL_VENDOR_LIBRARY_DIRS=/nonexistent " +
            std::string(BOOKSPIN_EXE) + " info 2>'" + err + "'",
        r.out);
    r.err = read_file(err);
    std::filesystem::remove(err);
    return r;
  }();
  ASSERT_EQ(none.status, 1) << none.out << none.err;
  EXPECT_FALSE(text_lines(plain.output).empty());
  EXPECT_EQ(text_lines(none.out), text_lines(plain.output));
  EXPECT_EQ(none.err.rfind("bookspin: error: ", 0), 0u) << none.err;
}

}  // namespace
}  // namespace bookspin::cli
