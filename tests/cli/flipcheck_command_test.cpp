// `bookspin flipcheck export` then `judge` (docs/flipcheck.md): every exported exact motion
// passes its scenario; `bookspin simulate`'s CSV of an engine mode reads as a motion file; a
// file judge cannot use is one line naming file, line and column, exit 2, nothing written; a
// comparison scene is no scenario.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "support/cli_runner.hpp"
#include "support/scratch.hpp"

namespace bookspin::cli {
namespace {

using namespace bookspin::test;
namespace fs = std::filesystem;

std::string scenario(const std::string& name) {
  return std::string(BOOKSPIN_SOURCE_DIR) + "/scenes/flipcheck/" + name + ".toml";
}

std::string quoted(const fs::path& p) {
  std::string text(1, '\'');
  text += p.string();
  text += '\'';
  return text;
}

// `bookspin --version` is the one version, VERSION's (docs/flipcheck.md, "Versions"), which every
// judgement row records.
TEST(FlipcheckCommand, TheVersionIsTheOneOfTheFileVersion) {
  std::ifstream file(std::string(BOOKSPIN_SOURCE_DIR) + "/VERSION");
  std::string version;
  for (std::string line; std::getline(file, line);)
    if (line.rfind("version ", 0) == 0) version = line.substr(8);
  ASSERT_FALSE(version.empty());
  const SplitResult said = run_bookspin_split("--version");
  EXPECT_EQ(said.status, 0) << said.err;
  EXPECT_EQ(said.out, "bookspin " + version + "\n");
}

TEST(FlipcheckCommand, EveryExportedExactMotionPassesItsScenario) {
  ScratchDir dir;
  const char* names[] = {"book-intermediate-0.05", "book-intermediate-0.2", "mujoco-test-box",
                         "symmetric-top"};
  std::string list;
  for (const char* name : names) list.append(" ").append(scenario(name));
  const CliResult exported = run_bookspin("flipcheck export" + list + " -o " + quoted(dir.path()));
  ASSERT_EQ(exported.status, 0) << exported.output;
  for (const char* name : names) {
    SCOPED_TRACE(name);
    EXPECT_TRUE(fs::is_regular_file(dir / (std::string(name) + ".json")));
    const fs::path csv = dir / (std::string(name) + "-exact.csv");
    const SplitResult judged = run_bookspin_split("flipcheck judge " + scenario(name) + " " +
                                                  quoted(csv) + " -o " + quoted(dir / "judge"));
    EXPECT_EQ(judged.status, 0) << judged.err;
    EXPECT_NE(judged.out.find(": PASS: turn-overs "), std::string::npos) << judged.out;
    EXPECT_TRUE(fs::is_regular_file(dir / "judge" / (std::string(name) + "-judge.csv")));
  }
}

TEST(FlipcheckCommand, JudgesSimulatesCsvOfAnEngineMode) {
  ScratchDir dir;
  const std::string set = " --set 'model.kind=\"mujoco\"' --set 'model.integrator=\"euler\"'";
  const CliResult simulated = run_bookspin("simulate " + scenario("mujoco-test-box") + set +
                                           " --csv " + quoted(dir / "euler.csv"));
  ASSERT_EQ(simulated.status, 0) << simulated.output;
  const SplitResult judged =
      run_bookspin_split("flipcheck judge " + scenario("mujoco-test-box") + " " +
                         quoted(dir / "euler.csv") + " -o " + quoted(dir.path()));
  EXPECT_EQ(judged.status, 0) << judged.err;
  // MuJoCo's own test: E/E0 = 1.0869 after 500 explicit steps of its box.
  EXPECT_NE(judged.out.find("FAIL (energy drift 0.0869 (limit 0.01);"), std::string::npos)
      << judged.out;
}

TEST(FlipcheckCommand, ABadMotionFileIsOneLineAndExitTwoWithNothingWritten) {
  ScratchDir dir;
  std::ofstream(dir / "bad.csv")
      << "t,qw,qx,qy,qz,wx,wy,wz\n0,1,0,0,0,1,2,3\n0.01,1,0,0,0,1,inf,3\n";
  const SplitResult r = run_bookspin_split("flipcheck judge " + scenario("mujoco-test-box") + " " +
                                           quoted(dir / "bad.csv") + " -o " + quoted(dir / "out"));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "bookspin: error: " + (dir / "bad.csv").string() +
                       ":3: wy: \"inf\" is not a finite number\n");
  EXPECT_FALSE(fs::exists(dir / "out"));
  const SplitResult missing =
      run_bookspin_split("flipcheck judge " + scenario("mujoco-test-box") + " " +
                         quoted(dir / "none.csv") + " -o " + quoted(dir / "out"));
  EXPECT_EQ(missing.status, 2);
  EXPECT_FALSE(fs::exists(dir / "out"));
}

/// Every path under `dir`, relative to it.
std::vector<std::string> tree(const fs::path& dir) {
  std::vector<std::string> paths;
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    paths.push_back(fs::relative(entry.path(), dir).string());
  std::sort(paths.begin(), paths.end());
  return paths;
}

// A scenario fuzzer at the command line: the box scenario with one setting made hostile
// (scene.name, time.dt, time.frames, time.steps_per_frame, initial.angular_velocity), seeded.
// Each export and judge is a verdict (exit 0) or one line and exit 2 (a name that would leave
// the output folder among them); nothing is ever written outside -o.
TEST(FlipcheckCommand, AFuzzedScenarioIsOneLineAndExitTwoOrAVerdictAndStaysInItsFolder) {
  ScratchDir dir;
  const std::vector<std::pair<std::string, std::vector<std::string>>> settings = {
      {"scene.name",
       {"'\"../escaped\"'", "'\"..\"'", "'\".\"'", "'\"a/b\"'", "'\"/tmp/abs\"'", "'\"x y\"'",
        "'\"ok-name.v2\"'", "'\"\"'", "'\"a\\nb\"'", "'\".hidden\"'"}},
      {"time.dt", {"1e300", "0", "-0.01", "1e-300", "2.5", "0.02", "nan"}},
      {"time.frames", {"1", "2", "0", "-5", "1e12", "2.5", "3000000"}},
      {"time.steps_per_frame", {"0", "2.5", "1000000", "-1", "7"}},
      {"initial.angular_velocity",
       {"[1e200, 2, 3]", "[0, 0, 0]", "[1, 2]", "[1e6, 0, 0]", "[2e6, 0, 0]", "[1, 2, 3]"}}};
  std::mt19937_64 rng(8281);
  int refused = 0, judged = 0;
  for (int k = 0; k < 24; ++k) {
    const auto& [key, values] = settings[rng() % settings.size()];
    const std::string value = values[rng() % values.size()];
    SCOPED_TRACE(key + "=" + value);
    const fs::path out = dir / ("out" + std::to_string(k));
    const std::string set = " --set " + key + "=" + value;
    const SplitResult exported = run_bookspin_split(
        "flipcheck export " + scenario("mujoco-test-box") + set + " -o " + quoted(out));
    ASSERT_TRUE(exported.status == 0 || exported.status == 2) << exported.status << exported.err;
    if (exported.status == 2) {
      ++refused;
      EXPECT_EQ(exported.err.find('\n'), exported.err.size() - 1) << exported.err;
      EXPECT_FALSE(fs::exists(out));
    } else {
      ++judged;
      std::vector<std::string> csv;
      for (const auto& entry : fs::directory_iterator(out))
        if (entry.path().string().ends_with("-exact.csv")) csv.push_back(entry.path().string());
      ASSERT_EQ(csv.size(), 1u);
      const SplitResult j =
          run_bookspin_split("flipcheck judge " + scenario("mujoco-test-box") + set + " " +
                             quoted(fs::path(csv[0])) + " -o " + quoted(out));
      EXPECT_TRUE(j.status == 0 || j.status == 2) << j.status << j.err;
      if (j.status == 2) {
        EXPECT_EQ(j.err.find('\n'), j.err.size() - 1) << j.err;
      }
    }
    // Nothing beside the output folders, anywhere in the scratch folder.
    for (const std::string& path : tree(dir.path())) EXPECT_EQ(path.rfind("out", 0), 0u) << path;
  }
  EXPECT_GT(refused, 3);
  EXPECT_GT(judged, 3);
}

TEST(FlipcheckCommand, AComparisonSceneIsNoScenario) {
  ScratchDir dir;
  const SplitResult r =
      run_bookspin_split("flipcheck export " + std::string(BOOKSPIN_SOURCE_DIR) +
                         "/scenes/compare-engines.toml -o " + quoted(dir / "out"));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("a comparison scene ([[compare]]) is no scenario"), std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

// `judge --methods` runs the method itself: MuJoCo's Euler on its box gives MuJoCo's own
// E/E0 = 1.0869 after 500 steps, as its simulate CSV does above. `league` writes its page and
// CSV and says how many pass. Neither motion files nor --methods: exit 2, nothing written.
TEST(FlipcheckCommand, JudgeAndLeagueRunMethodsThemselves) {
  ScratchDir dir;
  const SplitResult judged = run_bookspin_split("flipcheck judge " + scenario("mujoco-test-box") +
                                                " --methods mujoco:euler -o " + quoted(dir.path()));
  EXPECT_EQ(judged.status, 0) << judged.err;
  EXPECT_NE(
      judged.out.find("mujoco-test-box mujoco euler: FAIL (energy drift 0.0869 (limit 0.01);"),
      std::string::npos)
      << judged.out;
  const SplitResult league = run_bookspin_split(
      "flipcheck league " + scenario("mujoco-test-box") + " " + scenario("symmetric-top") +
      " --methods mujoco:rk4,mujoco:euler -o " + quoted(dir / "league"));
  EXPECT_EQ(league.status, 0) << league.err;
  EXPECT_NE(league.out.find("flipcheck-league.csv (2 motions in 2 scenarios, 1 pass every one)"),
            std::string::npos)
      << league.out;
  EXPECT_TRUE(fs::is_regular_file(dir / "league" / "flipcheck-league.html"));
  for (const char* command : {"judge", "league"}) {
    const SplitResult none =
        run_bookspin_split("flipcheck " + std::string(command) + " " + scenario("mujoco-test-box") +
                           " -o " + quoted(dir / "none"));
    EXPECT_EQ(none.status, 2) << command;
    EXPECT_NE(none.err.find("nothing to judge"), std::string::npos) << none.err;
    EXPECT_FALSE(fs::exists(dir / "none"));
  }
}

}  // namespace
}  // namespace bookspin::cli
