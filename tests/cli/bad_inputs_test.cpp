// The catalogue of bad inputs in tests/bad_scenes/. Each case is NAME.toml (the
// scene passed), NAME.expected (the exact error line after "bookspin: error: ", with {SCENE}
// for the path passed and {SCENE_DIR} for its folder) and optionally NAME.args (extra
// command-line words, shell-quoted). Every case must exit with status 2, print exactly that
// one line and write nothing. The cases are listed at run time, so adding one is adding files.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>

#include "support/catalogue.hpp"
#include "support/cli_runner.hpp"
#include "support/scratch.hpp"

namespace bookspin::cli {
namespace {

using namespace bookspin::test;  // the shared runner (tests/support)

namespace fs = std::filesystem;

constexpr std::size_t kMinimumCases = 30;

/// A catalogue case plus its NAME.args (extra command-line words), if any.
struct BadScene : CatalogueCase {
  std::string args;
};
// The case's name in the test names ctest registers (gtest's own printer, an exact match,
// would win over PrintTo(const CatalogueCase&) and print the object's bytes).
[[maybe_unused]] void PrintTo(const BadScene& c, std::ostream* out) { *out << c.name; }

std::vector<BadScene> load_scenes() {
  std::vector<BadScene> cases;
  for (CatalogueCase& c : load_catalogue(
           "bad_scenes", [](const fs::path& p) { return p.extension() == ".toml"; },
           [](const fs::path& scene) {
             return Placeholders{{"{SCENE_DIR}", scene.parent_path().string()},
                                 {"{SCENE}", scene.string()}};
           })) {
    const fs::path args = fs::path(c.file).replace_extension(".args");
    cases.push_back({std::move(c), fs::exists(args) ? trim_line_end(read_file(args)) : ""});
  }
  return cases;
}

std::vector<BadScene> scene_only_cases() {
  std::vector<BadScene> cases = load_scenes();
  std::erase_if(cases, [](const BadScene& c) { return !c.args.empty(); });
  return cases;
}

std::string test_name(const ::testing::TestParamInfo<BadScene>& info) {
  return case_test_name({info.param, info.index});
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
      run_bookspin("render " + quoted(c.file) + " -o " + quoted(out) + " --no-png " + c.args);
  expect_rejected(r, c.expected, out);
}

INSTANTIATE_TEST_SUITE_P(Catalogue, BadSceneRender, ::testing::ValuesIn(load_scenes()), test_name);

// simulate reads scenes through the same parser; the .args cases are render's command line.
class BadSceneSimulate : public ::testing::TestWithParam<BadScene> {};

TEST_P(BadSceneSimulate, ExitsTwoWithTheSameLineAndWritesNoCsv) {
  const BadScene& c = GetParam();
  const fs::path out = fresh_dir("bad_scenes/simulate-" + c.name);
  const CliResult r =
      run_bookspin("simulate " + quoted(c.file) + " --csv " + quoted(out / "out.csv"));
  expect_rejected(r, c.expected, out);
}

INSTANTIATE_TEST_SUITE_P(Catalogue, BadSceneSimulate, ::testing::ValuesIn(scene_only_cases()),
                         test_name);

TEST(BadSceneCatalogue, HasAtLeastThirtyCasesEachWithItsExpectedLine) {
  expect_complete(load_scenes(), kMinimumCases);
}

TEST(BadSceneCatalogue, EveryExpectedOrArgsFileHasItsScene) {
  for (const auto& entry :
       fs::directory_iterator((fs::path(BOOKSPIN_SOURCE_DIR) / "tests" / "bad_scenes"))) {
    const auto ext = entry.path().extension();
    if (ext == ".expected" || ext == ".args") {
      EXPECT_TRUE(fs::exists(fs::path(entry.path()).replace_extension(".toml"))) << entry.path();
    }
  }
}

// The cases below need a path that cannot be a committed file.

TEST(BadSceneFiles, MissingFileIsRejected) {
  const fs::path out = fresh_dir("bad_scenes/missing");
  const fs::path scene =
      (fs::path(BOOKSPIN_SOURCE_DIR) / "tests" / "bad_scenes") / "no-such-scene.toml";
  const CliResult r = run_bookspin("render " + quoted(scene) + " -o " + quoted(out) + " --no-png");
  expect_rejected(r, "bookspin: error: " + scene.string() + ": scene file not found\n", out);
}

TEST(BadSceneFiles, DirectoryIsRejected) {
  const fs::path out = fresh_dir("bad_scenes/directory");
  const CliResult r =
      run_bookspin("render " + quoted((fs::path(BOOKSPIN_SOURCE_DIR) / "tests" / "bad_scenes")) +
                   " -o " + quoted(out) + " --no-png");
  expect_rejected(
      r,
      "bookspin: error: " + (fs::path(BOOKSPIN_SOURCE_DIR) / "tests" / "bad_scenes").string() +
          ": is a directory, not a scene file\n",
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

// accuracy runs the engines of --methods whatever the scene's model: a body one of them cannot
// run (MuJoCo's mjMINVAL) is refused before anything runs, exit 2 and one line, as simulate
// and render refuse it.
TEST(BadInputs, AccuracyRefusesABodyAnEngineOfItsMethodsCannotRun) {
  const fs::path dir = fresh_dir("bad_scenes/accuracy-mujoco-tiny");
  const fs::path scene = dir / "tiny.toml";
  std::ofstream(scene) << "[book]\nsize = [1e-3, 1e-3, 1e-3]\nmass = 1e-12\n"
                          "[initial]\nangular_velocity = [1.0, 0.1, 0.0]\n";
  const SplitResult r =
      run_bookspin_split("accuracy " + quoted(scene) +
                         " --methods rigid-quaternion:rk4,mujoco -o " + quoted(dir / "out"));
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(r.err.rfind("bookspin: error: --methods mujoco ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(": book.size: MuJoCo needs every principal moment above its mjMINVAL"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

// Option values are quoted escaped, CLI11's own messages too: one line, no control sequence
// reaches the terminal (the values made by printf in the shell: ESC, CR, LF).
TEST(BadInputs, OptionValuesAreEscapedInEveryMessage) {
  const std::string scene = scene_path("fig09-matrix-unstable-x");
  for (const auto& [args, expected] : std::vector<std::pair<std::string, std::string>>{
           {"render --frames \"$(printf '1\\033')\" " + scene,
            "--frames: Value 1\\x1b not in range"},
           {"render " + scene + " --format \"$(printf 'mp4\\r')\" -o /nonexistent-dir",
            "unknown video format 'mp4\\r'"},
           {"accuracy " + scene + " --methods \"$(printf 'mujoco:rk4\\nx')\" -o /nonexistent-dir",
            "--methods mujoco:rk4\\nx"}}) {
    const SplitResult r = run_bookspin_split(args);
    EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(expected), std::string::npos) << args << "\n" << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_EQ(r.err.find('\x1b'), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find('\r'), std::string::npos) << r.err;
  }
}

// An empty output folder is bad input at every command that writes one, worded as npx words it
// (npm/package/cli.mjs): exit 2, one line naming the default, nothing written in the working
// folder; never a failed write to "" (exit 1 before).
TEST(BadInputs, AnEmptyOutputFolderIsBadInputAtEveryCommandThatWritesOne) {
  ScratchDir dir;
  const std::string scene = scene_path("fig09-matrix-unstable-x");
  const std::string kit =
      std::string(BOOKSPIN_SOURCE_DIR) + "/scenes/flipcheck/mujoco-test-box.toml";
  for (const auto& [args, fallback] : std::vector<std::pair<std::string, std::string>>{
           {"render " + scene, "out"},
           {"accuracy " + scene, "out"},
           {"explore " + scene, "out"},
           {"export " + scene, "out"},
           {"plot " + scene, "out"},
           {"sweep " + scene, "out"},
           {"fit toss.csv", "out"},  // refused at the option, before the recording is read
           {"flipcheck export " + kit, "out/flipcheck"}}) {
    for (const std::string spelled : {" -o ''", " --out ''"}) {
      std::string out;
      const int status = run_shell("cd " + quoted(dir.path()) + " && " + std::string(BOOKSPIN_EXE) +
                                       " " + args + spelled + " 2>&1",
                                   out);
      EXPECT_EQ(status, 2) << args << spelled << "\n" << out;
      EXPECT_EQ(out,
                "bookspin: error: --out: expected a directory, got an empty name (leave it "
                "out for " +
                    fallback + ") (see bookspin --help)\n")
          << args << spelled;
      EXPECT_TRUE(fs::is_empty(dir.path())) << args << spelled;
    }
  }
}

// An empty output that is no -o is bad input too: gallery's positional OUT_DIR (it wrote into
// the current folder, exit 0) and simulate's --csv (exit 1, "cannot rename temporary into
// place"): exit 2, one line naming the option and what to give instead, nothing written.
TEST(BadInputs, AnEmptyPositionalOrFileOutputIsBadInput) {
  ScratchDir dir;
  const std::string scene = scene_path("fig09-matrix-unstable-x");
  for (const auto& [args, said] : std::vector<std::pair<std::string, std::string>>{
           {"gallery '' " + scene,
            "OUT_DIR: expected a directory, got an empty name (give . for the current folder)"},
           {"simulate " + scene + " --csv ''",
            "--csv: expected a file name, got an empty name ('-' for the standard output)"}}) {
    std::string out;
    const int status = run_shell(
        "cd " + quoted(dir.path()) + " && " + std::string(BOOKSPIN_EXE) + " " + args + " 2>&1",
        out);
    EXPECT_EQ(status, 2) << args << "\n" << out;
    EXPECT_EQ(out, "bookspin: error: " + said + " (see bookspin --help)\n") << args;
    EXPECT_TRUE(fs::is_empty(dir.path())) << args;
  }
}

// A standard output that cannot be written (/dev/full) is a failed write at every command that
// prints its results: exit 1 naming it, never exit 0 with every line lost (fit did so; info
// alone checked). One check after every command (cli.cpp, flush_standard_output).
TEST(FailedWrites, AFullStandardOutputIsExitOneAtEveryCommandThatPrints) {
  ScratchDir dir;
  const std::string source = BOOKSPIN_SOURCE_DIR;
  const std::string kit = source + "/scenes/flipcheck/mujoco-test-box.toml";
  for (const std::string& args : std::vector<std::string>{
           "fit " + quoted(fs::path(source) / "recordings" / "phone-on-book-synthetic") + " -o " +
               quoted(dir.path() / "fit"),
           "simulate " + scene_path("fig09-matrix-unstable-x") + " --set time.frames=3",
           "inertia " + quoted(fs::path(source) / "scenes" / "long-box.obj") + " --mass 1",
           "flipcheck export " + kit + " -o " + quoted(dir.path() / "kit"),
           "gallery " + quoted(dir.path() / "gallery") + " " +
               scene_path("fig09-matrix-unstable-x")}) {
    std::string said;
    const int status = run_shell(std::string(BOOKSPIN_EXE) + " " + args + " 2>&1 >/dev/full", said);
    EXPECT_EQ(status, 1) << args << "\n" << said;
    EXPECT_NE(said.find("bookspin: error: cannot write the standard output: No space left on "
                        "device\n"),
              std::string::npos)
        << args << "\n"
        << said;
  }
}

}  // namespace
}  // namespace bookspin::cli
