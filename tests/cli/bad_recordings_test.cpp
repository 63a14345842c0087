// The catalogues of bad recordings (tests/bad_recordings/, `bookspin fit`) and bad motion files
// (tests/bad_motions/, `bookspin flipcheck judge` and `league`): NAME.<ext> and NAME.expected
// (the exact error line after "bookspin: error: ", with {FILE} for the path passed and {DIR}
// for its folder), a recording's NAME.args its extra words ({DIR} there too). Every case must exit
// with status 2, print exactly that one line on stderr and write nothing. The cases are listed at
// run time.
#include <gtest/gtest.h>

#include <fstream>

#include "support/catalogue.hpp"
#include "support/cli_runner.hpp"

namespace bookspin::cli {
namespace {

using namespace bookspin::test;  // the shared runner (tests/support)

namespace fs = std::filesystem;

bool is_input(const fs::path& p) {
  return p.extension() != ".expected" && p.extension() != ".md" && p.extension() != ".args";
}

std::vector<CatalogueCase> load(const std::string& folder) {
  return load_catalogue(folder, is_input, [](const fs::path& file) {
    return Placeholders{{"{FILE}", file.string()}, {"{DIR}", file.parent_path().string()}};
  });
}

void expect_refused(const std::string& command, const std::string& expected, const fs::path& out) {
  const SplitResult r = run_bookspin_split(command);
  EXPECT_EQ(r.status, 2) << command << "\n" << r.err;
  EXPECT_EQ(r.err, expected) << command;
  EXPECT_FALSE(fs::exists(out)) << command;
}

class BadRecording : public ::testing::TestWithParam<CatalogueCase> {};

TEST_P(BadRecording, ExitsTwoWithTheExactLineAndWritesNothing) {
  const CatalogueCase& c = GetParam();
  const fs::path out = fresh_dir("bad_recordings/" + c.name) / "out";
  const fs::path args = fs::path(c.file).replace_extension(".args");
  std::string extra = fs::exists(args) ? " " + trim_line_end(read_file(args)) : "";
  replace_all(extra, "{DIR}", c.file.parent_path().string());  // the same file spelled anew
  expect_refused("fit " + quoted(c.file) + extra + " -o " + quoted(out), c.expected, out);
}

INSTANTIATE_TEST_SUITE_P(Catalogue, BadRecording, ::testing::ValuesIn(load("bad_recordings")),
                         case_test_name);

class BadMotion : public ::testing::TestWithParam<CatalogueCase> {};

// Judged alone, and in a league as the scenario's motion (a copy named for it): one line each.
TEST_P(BadMotion, ExitsTwoWithTheExactLineAndWritesNothing) {
  const CatalogueCase& c = GetParam();
  const std::string scenario =
      quoted(fs::path(BOOKSPIN_SOURCE_DIR) / "scenes" / "flipcheck" / "mujoco-test-box.toml");
  const fs::path dir = fresh_dir("bad_motions/" + c.name);
  expect_refused(
      "flipcheck judge " + scenario + " " + quoted(c.file) + " -o " + quoted(dir / "out"),
      c.expected, dir / "out");
  const fs::path copy = dir / ("mujoco-test-box-" + c.name + ".csv");
  fs::copy_file(c.file, copy);
  std::string expected = c.expected;
  replace_all(expected, c.file.string(), copy.string());
  expect_refused(
      "flipcheck league " + scenario + " --motions " + quoted(copy) + " -o " + quoted(dir / "out"),
      expected, dir / "out");
}

INSTANTIATE_TEST_SUITE_P(Catalogue, BadMotion, ::testing::ValuesIn(load("bad_motions")),
                         case_test_name);

// The league's --motions: what a path is comes before what it is called. A folder, a missing
// file and a shell pattern that matched nothing (passed on as written) are each named so.
TEST(BadMotionPaths, TheLeagueNamesAFolderAMissingFileAndAnUnmatchedPattern) {
  const std::string scenario =
      quoted(fs::path(BOOKSPIN_SOURCE_DIR) / "scenes" / "flipcheck" / "mujoco-test-box.toml");
  const fs::path dir = fresh_dir("bad_motions/paths");
  const fs::path folder = dir / "motions";
  fs::create_directories(folder);
  const std::string prefix = " --motions ";
  const auto line = [](const std::string& message) { return "bookspin: error: " + message + "\n"; };
  const std::string out = " -o " + quoted(dir / "out");
  expect_refused("flipcheck league " + scenario + prefix + quoted(folder) + out,
                 line(folder.string() +
                      ": flipcheck league: --motions: is a folder, not a motion CSV (give its "
                      "files, e.g. " +
                      (folder / "*.csv").string() + ")"),
                 dir / "out");
  const fs::path missing = dir / "mujoco-test-box-gone.csv";
  expect_refused("flipcheck league " + scenario + prefix + quoted(missing) + out,
                 line(missing.string() + ": flipcheck league: --motions: no such file"),
                 dir / "out");
  const fs::path pattern = folder / "*.csv";
  expect_refused("flipcheck league " + scenario + prefix + quoted(pattern) + out,
                 line(pattern.string() +
                      ": flipcheck league: --motions: no such file (a pattern that matched no "
                      "file is passed on as written by the shell)"),
                 dir / "out");
}

TEST(BadRecordingAndMotionCatalogues, HaveTheirCasesEachWithItsExpectedLine) {
  expect_complete(load("bad_recordings"), 14);
  expect_complete(load("bad_motions"), 11);
}

}  // namespace
}  // namespace bookspin::cli
