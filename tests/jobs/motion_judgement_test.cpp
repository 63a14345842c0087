// One scenario's judgement as a value (jobs::judge_scenario, docs/flipcheck.md): the scenario
// JSON `flipcheck export` writes judges as its scene does (the same table, row for row, and
// the SHA-256 of the file's own bytes), and every motion file is read before any method runs,
// so that a bad file is its one line before minutes of simulation.
#include "jobs/motion_judgement.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "analysis/scenario_file.hpp"
#include "common/errors.hpp"
#include "jobs/exact_motion.hpp"
#include "output/sha256.hpp"
#include "support/scratch.hpp"

namespace bookspin::jobs {
namespace {

namespace fs = std::filesystem;

scene::Scene box() {
  return scene::parse_scene(fs::path(BOOKSPIN_SOURCE_DIR) / "scenes" / "flipcheck" /
                            "mujoco-test-box.toml");
}

/// The scenario's two exported files written into `dir`: its JSON and its exact motion.
struct Exported {
  fs::path json, csv;
};
Exported export_into(const fs::path& dir, const analysis::Scenario& scenario) {
  const ExportFiles texts = export_files(exact_motion(scenario));
  const Exported files{dir / (scenario.name + ".json"), dir / (scenario.name + "-exact.csv")};
  std::ofstream(files.json, std::ios::binary) << texts.json;
  std::ofstream(files.csv, std::ios::binary) << texts.csv;
  return files;
}

/// A text cell of `table` (row `r`, column `c`).
std::string cell(const CsvTable& table, std::size_t r, std::size_t c) {
  return std::get<std::string>(table.rows.at(r).at(c));
}

TEST(JudgeScenario, TheExportedScenarioJsonJudgesAsItsScene) {
  test::ScratchDir dir;
  const scene::Scene scene = box();
  const Exported files = export_into(dir.path(), analysis::scenario_of(scene));
  const std::vector<analysis::Method> methods = analysis::parse_methods("rigid-quaternion:rk4");
  const Judgement of_scene =
      judge_scenario(scene, {}, {files.csv}, {"exact"}, methods, /*stop=*/{});
  // The JSON route: the scenario read from the file, the scene giving only the methods' model
  // settings and row spacing.
  const Judgement of_json = judge_scenario(scene, files.json, {files.csv}, {"exact"}, methods, {});
  EXPECT_EQ(of_json.scenario.name, "mujoco-test-box");
  // Its identity is the SHA-256 of the bytes export wrote, by either route.
  EXPECT_EQ(of_scene.scenario_sha256, output::sha256_file(files.json).value());
  EXPECT_EQ(of_json.scenario_sha256, of_scene.scenario_sha256);
  ASSERT_EQ(of_scene.table.rows.size(), 2u);  // the file, then the method
  EXPECT_EQ(csv_text(of_scene.table, "judgement"), csv_text(of_json.table, "judgement"));
  EXPECT_EQ(cell(of_scene.table, 0, 1), "exact");
  EXPECT_EQ(cell(of_scene.table, 1, 1), methods[0].label);
  // Whatever the scene beside it (here another scenario's, a row every 10 steps), the JSON's
  // scenario is judged: the file's row and the identity are the JSON's own.
  const scene::Scene top = scene::parse_scene(fs::path(BOOKSPIN_SOURCE_DIR) / "scenes" /
                                              "flipcheck" / "symmetric-top.toml");
  const Judgement beside_top = judge_scenario(top, files.json, {files.csv}, {"exact"}, {}, {});
  EXPECT_EQ(beside_top.scenario_sha256, of_scene.scenario_sha256);
  CsvTable file_row = of_scene.table;
  file_row.rows.resize(1);
  EXPECT_EQ(csv_text(beside_top.table, "judgement"), csv_text(file_row, "judgement"));
  // The exact motion passes its own scenario; the table says what the judged values say.
  ASSERT_EQ(of_scene.judged.size(), 2u);
  EXPECT_TRUE(of_scene.judged[0].result.pass());
  EXPECT_EQ(cell(of_scene.table, 0, 2), "pass");
  EXPECT_EQ(cell(of_scene.table, 1, 2), of_scene.judged[1].result.pass() ? "pass" : "fail");
}

TEST(JudgeScenario, EveryMotionFileIsReadBeforeAnyMethodRuns) {
  test::ScratchDir dir;
  const scene::Scene scene = box();
  const Exported files = export_into(dir.path(), analysis::scenario_of(scene));
  const fs::path bad = dir.path() / "bad.csv";
  std::ofstream(bad) << "t,qw,qx,qy,qz,wx,wy,wz\n0,1,0,0,0,1,2,3\n0.01,1,0,0\n";
  // Every stage the judgement asks the stop poll about, in order (a method's run asks it at
  // every row, "flipcheck steps").
  std::vector<std::string> asked;
  const StopPoll record = [&asked](std::string_view stage) {
    asked.emplace_back(stage);
    return 0;
  };
  try {
    judge_scenario(scene, {}, {files.csv, bad}, {"exact", "bad"},
                   analysis::parse_methods("rigid-quaternion:rk4"), record);
    FAIL() << "a motion file with a missing cell was judged";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(bad.string() + ":3:", 0), 0u) << e.what();
  }
  EXPECT_TRUE(asked.empty()) << "asked first: " << asked.front();
}

}  // namespace
}  // namespace bookspin::jobs
