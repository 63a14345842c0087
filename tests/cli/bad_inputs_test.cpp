// The catalogue of bad inputs in tests/bad_scenes/. Each case is NAME.toml (the
// scene passed), NAME.expected (the exact error line after "bookspin: error: ", with {SCENE}
// for the path passed and {SCENE_DIR} for its folder) and optionally NAME.args (extra
// command-line words, shell-quoted). Every case must exit with status 2, print exactly that
// one line and write nothing. The cases are listed at run time, so adding one is adding files.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>

#include "support/cli_runner.hpp"

namespace bookspin::cli {
namespace {

using namespace bookspin::test;  // the shared runner (tests/support)

namespace fs = std::filesystem;

constexpr std::size_t kMinimumCases = 30;

struct BadScene {
  std::string name;      ///< file stem, e.g. "dt-zero"
  fs::path scene;        ///< NAME.toml
  std::string args;      ///< NAME.args, or empty
  std::string expected;  ///< the full line, placeholders substituted
};
// gtest prints parameters into the names ctest registers; print a stable text, not bytes.
[[maybe_unused]] void PrintTo(const BadScene& p, std::ostream* out) { *out << p.name; }

fs::path catalogue_dir() { return fs::path(BOOKSPIN_SOURCE_DIR) / "tests" / "bad_scenes"; }

std::string trim_line_end(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  return text;
}

void replace_all(std::string& text, const std::string& from, const std::string& to) {
  for (auto at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
    text.replace(at, from.size(), to);
  }
}

/// The line bookspin must print for `scene`, from NAME.expected.
std::string expected_line(const fs::path& expected_file, const fs::path& scene) {
  std::string line = trim_line_end(read_file(expected_file));
  replace_all(line, "{SCENE_DIR}", scene.parent_path().string());
  replace_all(line, "{SCENE}", scene.string());
  return "bookspin: error: " + line + "\n";
}

BadScene load_case(const fs::path& toml) {
  BadScene c;
  c.name = toml.stem().string();
  c.scene = toml;
  const fs::path args = fs::path(toml).replace_extension(".args");
  if (fs::exists(args)) c.args = trim_line_end(read_file(args));
  const fs::path expected = fs::path(toml).replace_extension(".expected");
  // A case without its .expected file gets an impossible line, so it fails loudly.
  c.expected =
      fs::exists(expected) ? expected_line(expected, toml) : "(missing " + expected.string() + ")";
  return c;
}

/// Every NAME.toml in the catalogue, sorted so test order is stable.
std::vector<BadScene> load_catalogue() {
  std::vector<BadScene> cases;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(catalogue_dir(), ec)) {
    if (entry.path().extension() == ".toml") cases.push_back(load_case(entry.path()));
  }
  std::sort(cases.begin(), cases.end(),
            [](const auto& a, const auto& b) { return a.name < b.name; });
  return cases;
}

std::vector<BadScene> scene_only_cases() {
  std::vector<BadScene> cases = load_catalogue();
  std::erase_if(cases, [](const BadScene& c) { return !c.args.empty(); });
  return cases;
}

/// GoogleTest names allow only letters, digits and '_'.
std::string test_name(const ::testing::TestParamInfo<BadScene>& info) {
  std::string name = info.param.name;
  std::replace_if(
      name.begin(), name.end(), [](unsigned char ch) { return !std::isalnum(ch); }, '_');
  return name;
}

/// Single-quoted for the shell. Built with append: GCC 12 warns falsely (-Wrestrict) on
/// "literal" + std::string.
std::string quoted(const fs::path& path) {
  std::string out;
  return out.append("'").append(path.string()).append("'");
}

/// Every path under `dir`, so a failure shows what was left behind (outputs, temporaries).
std::vector<std::string> files_under(const fs::path& dir) {
  std::vector<std::string> found;
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    found.push_back(entry.path().string());
  return found;
}

/// The checks every bad input must pass: status 2, exactly the expected line, nothing written.
void expect_rejected(const CliResult& r, const std::string& expected, const fs::path& out_dir) {
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_EQ(r.output, expected);
  EXPECT_EQ(files_under(out_dir), std::vector<std::string>{});
}

class BadSceneRender : public ::testing::TestWithParam<BadScene> {};

TEST_P(BadSceneRender, ExitsTwoWithTheExactLineAndWritesNothing) {
  const BadScene& c = GetParam();
  const fs::path out = fresh_dir("bad_scenes/render-" + c.name);
  const CliResult r =
      run_bookspin("render " + quoted(c.scene) + " -o " + quoted(out) + " --no-png " + c.args);
  expect_rejected(r, c.expected, out);
}

INSTANTIATE_TEST_SUITE_P(Catalogue, BadSceneRender, ::testing::ValuesIn(load_catalogue()),
                         test_name);

// simulate reads scenes through the same parser; the .args cases are render's command line.
class BadSceneSimulate : public ::testing::TestWithParam<BadScene> {};

TEST_P(BadSceneSimulate, ExitsTwoWithTheSameLineAndWritesNoCsv) {
  const BadScene& c = GetParam();
  const fs::path out = fresh_dir("bad_scenes/simulate-" + c.name);
  const CliResult r =
      run_bookspin("simulate " + quoted(c.scene) + " --csv " + quoted(out / "out.csv"));
  expect_rejected(r, c.expected, out);
}

INSTANTIATE_TEST_SUITE_P(Catalogue, BadSceneSimulate, ::testing::ValuesIn(scene_only_cases()),
                         test_name);

TEST(BadSceneCatalogue, HasAtLeastThirtyCasesEachWithItsExpectedLine) {
  const auto cases = load_catalogue();
  EXPECT_GE(cases.size(), kMinimumCases);
  for (const auto& c : cases) {
    EXPECT_TRUE(fs::exists(fs::path(c.scene).replace_extension(".expected"))) << c.name;
  }
}

TEST(BadSceneCatalogue, EveryExpectedOrArgsFileHasItsScene) {
  for (const auto& entry : fs::directory_iterator(catalogue_dir())) {
    const auto ext = entry.path().extension();
    if (ext == ".expected" || ext == ".args") {
      EXPECT_TRUE(fs::exists(fs::path(entry.path()).replace_extension(".toml"))) << entry.path();
    }
  }
}

// The cases below need a path that cannot be a committed file.

TEST(BadSceneFiles, MissingFileIsRejected) {
  const fs::path out = fresh_dir("bad_scenes/missing");
  const fs::path scene = catalogue_dir() / "no-such-scene.toml";
  const CliResult r = run_bookspin("render " + quoted(scene) + " -o " + quoted(out) + " --no-png");
  expect_rejected(r, "bookspin: error: " + scene.string() + ": scene file not found\n", out);
}

TEST(BadSceneFiles, DirectoryIsRejected) {
  const fs::path out = fresh_dir("bad_scenes/directory");
  const CliResult r =
      run_bookspin("render " + quoted(catalogue_dir()) + " -o " + quoted(out) + " --no-png");
  expect_rejected(
      r, "bookspin: error: " + catalogue_dir().string() + ": is a directory, not a scene file\n",
      out);
}

// Generated rather than committed: one byte over the 1 MiB limit, otherwise a valid scene
// (a comment, then one key), so only the size can be what is rejected.
TEST(BadSceneFiles, FileOverOneMebibyteIsRejected) {
  const fs::path dir = fresh_dir("bad_scenes/oversized");
  const fs::path scene = dir / "oversized.toml";
  const std::string tail = R"toml(
[time]
frames = 2
)toml";
  const std::size_t limit = std::size_t{1} << 20;
  {
    std::ofstream file(scene, std::ios::binary);
    file << '#' << std::string(limit - tail.size(), 'x') << tail;
  }
  ASSERT_EQ(fs::file_size(scene), limit + 1);
  const fs::path out = fresh_dir("bad_scenes/oversized-out");
  const CliResult r = run_bookspin("render " + quoted(scene) + " -o " + quoted(out) + " --no-png");
  expect_rejected(
      r, "bookspin: error: " + scene.string() + ": scene file is larger than 1048576 bytes\n", out);
}

// Not a bad input: a known table left empty ([render] with no keys) once read as an unknown
// key. Guards the unknown-key check against rejecting too much.
TEST(BadSceneFiles, EmptyKnownTableIsAccepted) {
  const fs::path dir = fresh_dir("bad_scenes/empty-table");
  const fs::path scene = dir / "empty-table.toml";
  std::ofstream(scene) << R"toml([render]

[time]
frames = 2
)toml";
  const CliResult r =
      run_bookspin("simulate " + quoted(scene) + " --csv " + quoted(dir / "out.csv"));
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(fs::exists(dir / "out.csv"));
}

}  // namespace
}  // namespace bookspin::cli
