// The conformance kit's products (docs/flipcheck.md): the export writes the scenario's JSON
// (the numbers an engine needs, read back by value) and the exact motion's CSV (its header
// and a row a step) under its layout with a manifest, and is up to date the second time; the
// judgement writes one row per motion file, and a changed motion file makes it again.
#include "products/flipcheck.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "analysis/scenario_file.hpp"
#include "common/errors.hpp"
#include "jobs/simulation.hpp"
#include "output/manifest.hpp"
#include "output/sha256.hpp"
#include "support/cli_runner.hpp"
#include "support/scratch.hpp"

namespace bookspin::products {
namespace {

namespace fs = std::filesystem;

scene::Scene box() {
  return scene::parse_scene(fs::path(BOOKSPIN_SOURCE_DIR) / "scenes" / "flipcheck" /
                            "mujoco-test-box.toml");
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  for (std::size_t end; (end = text.find('\n', start)) != std::string::npos; start = end + 1)
    lines.push_back(text.substr(start, end - start));
  return lines;
}

TEST(Flipcheck, TheExportWritesTheScenarioAndItsExactMotionThenIsUpToDate) {
  test::ScratchDir dir;
  const FlipcheckExportJob job{box(), dir / "out", {}, {}};
  EXPECT_EQ(make_flipcheck_export(job), cache::Outcome::made);
  const FlipcheckExportLayout layout = flipcheck_export_layout(dir / "out", job.scene);
  EXPECT_EQ(layout.json, dir / "out" / "mujoco-test-box.json");
  EXPECT_EQ(layout.csv, dir / "out" / "mujoco-test-box-exact.csv");
  EXPECT_EQ(output::read_manifest(layout.manifest).outputs,
            (std::vector<std::string>{"mujoco-test-box.json", "mujoco-test-box-exact.csv"}));
  const std::string json = test::read_file(layout.json);
  // MuJoCo's box: mass 1, I = m/3 (b² + c²) … with half-sizes 0.1, 0.2, 0.3, ω = (1, 2, 3).
  for (const std::string& member :
       {std::string("\"mass\": 1,"),
        std::string("\"principal_moments\": [0.043333333333333335, 0.03333333333333333, "
                    "0.01666666666666667],"),
        std::string("\"q0\": [1, 0, 0, 0],"), std::string("\"omega0_body\": [1, 2, 3],"),
        std::string("\"omega0_world\": [1, 2, 3],"), std::string("\"dt\": 0.01,"),
        std::string("\"steps\": 500,"), std::string("\"angular_velocity\": \"rad per time unit\"")})
    EXPECT_NE(json.find(member), std::string::npos) << member << "\n" << json;
  const std::vector<std::string> csv = lines_of(test::read_file(layout.csv));
  ASSERT_EQ(csv.size(), 502u);  // the header and steps + 1 rows
  EXPECT_EQ(csv[0], "t,qw,qx,qy,qz,wx,wy,wz,wx_world,wy_world,wz_world,Lx,Ly,Lz,E");
  // R(0) = I to round-off: t, q = (1, 0, 0, 0), ω body = (1, 2, 3), then ω world = R(0) ω.
  EXPECT_EQ(csv[1].substr(0, 16), "0,1,0,0,0,1,2,3,");
  std::vector<double> row;
  for (std::size_t at = 0; at != std::string::npos;) {
    const std::size_t comma = csv[1].find(',', at);
    row.push_back(std::stod(csv[1].substr(at, comma - at)));
    at = comma == std::string::npos ? comma : comma + 1;
  }
  ASSERT_EQ(row.size(), 15u);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(row[8 + i], row[5 + i], 1e-14) << csv[1];
  EXPECT_EQ(csv[501].substr(0, 2), "5,");  // t = 500 · 0.01
  EXPECT_EQ(make_flipcheck_export(job), cache::Outcome::up_to_date);
}

TEST(Flipcheck, TheJudgementIsARowPerMotionAndIsRemadeWhenAMotionChanges) {
  test::ScratchDir dir;
  const scene::Scene scene = box();
  make_flipcheck_export({scene, dir / "exact", {}, {}});
  const fs::path exact = dir / "exact" / "mujoco-test-box-exact.csv";
  // A second motion: the exact one with every other row's q negated (the same rotations).
  const std::vector<std::string> lines = lines_of(test::read_file(exact));
  std::ofstream negated(dir / "negated.csv");
  negated << "t,qw,qx,qy,qz,wx,wy,wz\n";
  for (std::size_t i = 1; i < lines.size(); ++i) {
    std::vector<std::string> cells;
    std::size_t start = 0;
    for (int k = 0; k < 8; ++k) {
      const std::size_t comma = lines[i].find(',', start);
      cells.push_back(lines[i].substr(start, comma - start));
      start = comma + 1;
    }
    for (int k = 0; k < 8; ++k) {
      std::string cell = cells[static_cast<std::size_t>(k)];
      if (i % 2 == 0 && k >= 1 && k <= 4)
        cell = cell[0] == '-' ? cell.substr(1) : (cell == "0" ? cell : "-" + cell);
      negated << (k ? "," : "") << cell;
    }
    negated << '\n';
  }
  negated.close();
  FlipcheckJudgeJob job{scene, {exact, dir / "negated.csv"}, dir / "out", {}};
  const FlipcheckJudgeResult result = make_flipcheck_judge(job);
  EXPECT_EQ(result.outcome, cache::Outcome::made);
  ASSERT_EQ(result.judged.size(), 2u);
  for (const analysis::JudgedMotion& j : result.judged) EXPECT_TRUE(j.result.pass()) << j.file;
  const std::vector<std::string> csv =
      lines_of(test::read_file(flipcheck_judge_layout(dir / "out", scene).csv));
  ASSERT_EQ(csv.size(), 3u);
  EXPECT_EQ(csv[0],
            "scenario,motion,verdict,stride,last_step,start_error,energy_drift,L_drift,flips,"
            "flips_exact,first_flip,first_flip_exact,first_flip_error,orientation_error,"
            "orientation_error_step,L_direction_error,L_direction_error_step,"
            "stable_spin,tumble_time,separatrix_ratio_drift,separatrix_approach,failures,"
            "version,scenario_sha256");
  EXPECT_EQ(csv[1].substr(0, 53), "mujoco-test-box,mujoco-test-box-exact.csv,pass,1,500,");
  EXPECT_EQ(csv[2].substr(0, 39), "mujoco-test-box,negated.csv,pass,1,500,");
  // Each row ends with what judged it: the version and the SHA-256 of the exported scenario
  // JSON's bytes, as `sha256sum OUT/mujoco-test-box.json` gives it.
  std::string stamp = ",";
  stamp += output::program_version();
  stamp += ",";
  stamp += output::sha256_file(dir / "exact" / "mujoco-test-box.json").value();
  for (int row : {1, 2}) {
    ASSERT_GE(csv[row].size(), stamp.size());
    EXPECT_EQ(csv[row].substr(csv[row].size() - stamp.size()), stamp) << csv[row];
  }
  EXPECT_EQ(make_flipcheck_judge(job).outcome, cache::Outcome::up_to_date);
  std::ofstream(dir / "negated.csv", std::ios::app) << "# a comment changes the file\n";
  EXPECT_EQ(make_flipcheck_judge(job).outcome, cache::Outcome::made);
}

// A method run in-process (--methods) is judged as the same method's `simulate` CSV is, which
// goes through the diagnostics writer and the motion reader instead (docs/flipcheck.md: "judge
// on a bookspin engine mode's CSV gives the same numbers"): every measure to 1e-9 relative.
TEST(Flipcheck, AMethodJudgedInProcessEqualsItsSimulateCsvJudged) {
  test::ScratchDir dir;
  for (const char* method : {"mujoco:rk4", "rigid-quaternion:rescaled-euler"}) {
    scene::Scene scene = box();
    const std::vector<analysis::Method> methods = analysis::parse_methods(method);
    scene::Scene simulated = scene;
    simulated.model.kind = methods[0].kind;
    simulated.model.integrator = methods[0].integrator;
    const fs::path csv = dir / "simulated.csv";
    {
      std::ofstream file(csv);
      jobs::write_diagnostics_rows(simulated, file);
    }
    FlipcheckJudgeJob job{scene, {csv}, dir / "out", {}};
    job.methods = methods;
    const FlipcheckJudgeResult result = make_flipcheck_judge(job);
    ASSERT_EQ(result.judged.size(), 2u);
    EXPECT_EQ(result.judged[1].name, methods[0].label);
    EXPECT_TRUE(result.judged[1].file.empty());
    const analysis::Conformance& a = result.judged[0].result;
    const analysis::Conformance& b = result.judged[1].result;
    EXPECT_EQ(a.stride, b.stride);
    EXPECT_EQ(a.last_step, b.last_step);
    EXPECT_EQ(a.flips, b.flips);
    EXPECT_EQ(a.flips_exact, b.flips_exact);
    EXPECT_EQ(a.failures, b.failures);
    const auto near = [](double x, double y) {
      return std::abs(x - y) <= 1e-9 * std::abs(y) + 1e-15;
    };
    EXPECT_TRUE(near(a.energy_drift, b.energy_drift))
        << method << a.energy_drift << " " << b.energy_drift;
    EXPECT_TRUE(near(a.L_drift, b.L_drift)) << method;
    EXPECT_TRUE(near(a.orientation_error, b.orientation_error)) << method;
    ASSERT_TRUE(a.first_flip && b.first_flip) << method;
    EXPECT_TRUE(near(*a.first_flip, *b.first_flip)) << method;
    // The box turns over 3 times in its 500 steps (docs/flipcheck.md's league table): MuJoCo's
    // RK4 passes, the rescaled Euler step drifts the energy by 2.5 % and fails.
    EXPECT_EQ(b.flips_exact, 3) << method;
    EXPECT_EQ(b.pass(), std::string(method) == "mujoco:rk4") << method;
  }
}

// The league: each motion file goes to the scenario its name starts with, the longest such
// name ("box-long-exact.csv" is box-long's "exact", not box's "long-exact"); a row per motion,
// a column per scenario; a file that names no scenario is refused before anything is written.
TEST(Flipcheck, TheLeagueGivesEachFileToItsScenarioARowPerMotion) {
  test::ScratchDir dir;
  const fs::path source = fs::path(BOOKSPIN_SOURCE_DIR) / "scenes" / "flipcheck";
  const scene::Scene short_box =
      scene::parse_scene(source / "mujoco-test-box.toml", {"scene.name=\"box\""});
  const scene::Scene long_box = scene::parse_scene(source / "mujoco-test-box.toml",
                                                   {"scene.name=\"box-long\"", "time.frames=21"});
  for (const scene::Scene& s : {short_box, long_box})
    make_flipcheck_export({s, dir / "exact", {}, {}});
  FlipcheckLeagueJob job;
  job.scenes = {short_box, long_box};
  job.motions = {dir / "exact" / "box-long-exact.csv", dir / "exact" / "box-exact.csv"};
  job.methods = analysis::parse_methods("rigid-quaternion:euler");
  job.out_dir = dir / "out";
  const FlipcheckLeagueResult result = make_flipcheck_league(job);
  EXPECT_EQ(result.outcome, cache::Outcome::made);
  EXPECT_EQ(result.motions, 2);  // "exact" and "rigid-quaternion euler"
  EXPECT_EQ(result.passed, 1);   // the exact motion
  const FlipcheckLeagueLayout layout = flipcheck_league_layout(dir / "out");
  const std::vector<std::string> csv = lines_of(test::read_file(layout.csv));
  ASSERT_EQ(csv.size(), 5u);  // the header, two rows per scenario
  EXPECT_EQ(csv[1].substr(0, 21), "box,exact,pass,1,500,");
  EXPECT_EQ(csv[2].substr(0, 32), "box,rigid-quaternion euler,fail,");
  EXPECT_EQ(csv[3].substr(0, 26), "box-long,exact,pass,1,200,");
  EXPECT_EQ(csv[4].substr(0, 37), "box-long,rigid-quaternion euler,fail,");
  const std::string html = test::read_file(layout.html);
  EXPECT_NE(html.find("<tr><th>motion</th><th title=\"flipcheck: MuJoCo&#39;s test box\">box</th>"),
            std::string::npos)
      << html;
  EXPECT_NE(html.find("<tr><th>exact</th><td class=\"pass\">pass 3/3</td><td class=\"pass\">pass "),
            std::string::npos)
      << html;
  // A motion's name breaks after its separators only, never inside a word or a version; the
  // scrolling table is reached by the keyboard and named (docs/flipcheck.md, "The league table").
  EXPECT_NE(html.find("<tr><th>rigid-<wbr>quaternion euler</th>"), std::string::npos) << html;
  EXPECT_EQ(html.find("overflow-wrap: anywhere"), std::string::npos);
  EXPECT_EQ(html.substr(0, html.find("@media print")).find("overflow-wrap"), std::string::npos);
  EXPECT_NE(html.find("<div class=\"league\" tabindex=\"0\" role=\"region\" aria-label=\""),
            std::string::npos);
  EXPECT_EQ(output::read_manifest(layout.manifest).outputs,
            (std::vector<std::string>{"flipcheck-league.csv", "flipcheck-league.html"}));
  // Up to date, the league judges nothing (a stop poll that always answers SIGINT is never
  // asked) and counts the table it keeps; another method, or a motion file changed, remakes it.
  {
    FlipcheckLeagueJob again = job;
    int asked = 0;
    again.stop = [&asked](std::string_view) { return ++asked, 2; };
    const FlipcheckLeagueResult kept = make_flipcheck_league(again);
    EXPECT_EQ(kept.outcome, cache::Outcome::up_to_date);
    EXPECT_EQ(asked, 0);
    EXPECT_EQ(kept.motions, 2);
    EXPECT_EQ(kept.passed, 1);
    again.stop = {};
    again.methods = analysis::parse_methods("rigid-quaternion:rk4");
    EXPECT_EQ(make_flipcheck_league(again).outcome, cache::Outcome::made);
    EXPECT_EQ(make_flipcheck_league(job).outcome, cache::Outcome::made);
    EXPECT_EQ(make_flipcheck_league(job).outcome, cache::Outcome::up_to_date);
    std::ofstream(job.motions[0], std::ios::app) << "\n";  // a blank line: the same motion
    EXPECT_EQ(make_flipcheck_league(job).outcome, cache::Outcome::made);
  }

  // A file that is there (what a path is comes first: a missing one is "no such file").
  fs::copy_file(job.motions[0], dir / "exact" / "mujoco-test-box-exact.csv",
                fs::copy_options::overwrite_existing);
  job.motions.push_back(dir / "exact" / "mujoco-test-box-exact.csv");
  job.out_dir = dir / "refused";
  try {
    make_flipcheck_league(job);
    ADD_FAILURE() << "a file naming no scenario was taken";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("mujoco-test-box-exact.csv: flipcheck league: the file's "
                                         "name starts with no scenario's"),
              std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(fs::exists(dir / "refused"));
}

// A league cell reads "no turn-over" only where neither the motion nor the exact one turns
// over: an engine that never flips where the exact motion flips six times (Bullet without its
// gyroscopic term) is "fail 0/6"; the exact motion of a stable spin is "pass, no turn-over".
TEST(Flipcheck, ALeagueCellSaysNoTurnOverOnlyWhereBothCountsAreZero) {
  test::ScratchDir dir;
  const fs::path source = fs::path(BOOKSPIN_SOURCE_DIR) / "scenes" / "flipcheck";
  FlipcheckLeagueJob job;
  const scene::Scene spin = scene::parse_scene(source / "symmetric-top.toml");
  make_flipcheck_export({spin, dir / "exact", {}, {}});
  job.scenes = {scene::parse_scene(source / "book-intermediate-0.2.toml"), spin};
  job.motions = {dir / "exact" / "symmetric-top-exact.csv"};
  job.methods = analysis::parse_methods("bullet:none");
  job.out_dir = dir / "out";
  make_flipcheck_league(job);
  const std::string html = test::read_file(flipcheck_league_layout(dir / "out").html);
  const std::size_t row = html.find("<tr><th>bullet none</th>");
  ASSERT_NE(row, std::string::npos) << html;
  const std::string cells = html.substr(row, html.find("</tr>", row) - row);
  EXPECT_NE(cells.find("<td class=\"fail\">fail 0/6<br>"), std::string::npos) << cells;
  EXPECT_NE(html.find("<tr><th>exact</th><td class=\"none\">not run</td><td class=\"pass\">pass, "
                      "no turn-over</td>"),
            std::string::npos)
      << html;
}

/// The InputError `job` raises, or "".
std::string league_error(const FlipcheckLeagueJob& job) {
  try {
    make_flipcheck_league(job);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// What a row or a column cannot tell apart is refused before anything is written: two motion
// files of one name (in two folders), two scenarios of one name, one scenario given twice.
TEST(Flipcheck, TheLeagueRefusesTwoRowsOrColumnsOfOneName) {
  test::ScratchDir dir;
  const scene::Scene s = box();
  make_flipcheck_export({s, dir / "a", {}, {}});
  fs::create_directories(dir / "b");
  fs::copy_file(dir / "a" / "mujoco-test-box-exact.csv", dir / "b" / "mujoco-test-box-exact.csv");
  FlipcheckLeagueJob job;
  job.scenes = {s};
  job.motions = {dir / "a" / "mujoco-test-box-exact.csv", dir / "b" / "mujoco-test-box-exact.csv"};
  job.out_dir = dir / "out";
  EXPECT_EQ(league_error(job), (dir / "b" / "mujoco-test-box-exact.csv").string() +
                                   ": flipcheck league: its motion \"exact\" is also " +
                                   (dir / "a" / "mujoco-test-box-exact.csv").string() +
                                   "'s in scenario mujoco-test-box: rename one (a row per motion)");
  job.motions.pop_back();
  job.scenes = {s, s};
  EXPECT_EQ(league_error(job),
            "flipcheck league: two scenarios named mujoco-test-box (one given twice, or two files "
            "of one scene.name): give each once");
  EXPECT_FALSE(fs::exists(dir / "out"));
  // A bad motion is refused before the cache is asked: nothing written, one error.
  std::ofstream(dir / "mujoco-test-box-bad.csv") << "t,qw,qx,qy,qz,wx,wy,wz\n0,1,0,0,0,1e200,2,3\n";
  job.scenes = {s};
  job.motions = {dir / "mujoco-test-box-bad.csv"};
  EXPECT_NE(league_error(job).find("mujoco-test-box-bad.csv:2: wx: \"1e200\" is beyond"),
            std::string::npos);
  EXPECT_FALSE(fs::exists(dir / "out"));
}

// A motion's name is the page's text, never its markup; a line break in it is one row of the
// CSV, counted once (made now and up to date alike).
TEST(Flipcheck, TheLeaguePageEscapesMotionNamesAndCountsEachOnce) {
  test::ScratchDir dir;
  const scene::Scene s = box();
  make_flipcheck_export({s, dir / "exact", {}, {}});
  const fs::path exact = dir / "exact" / "mujoco-test-box-exact.csv";
  const fs::path script = dir / "mujoco-test-box-<script>alert(1)<script>.csv";
  const fs::path broken = dir / "mujoco-test-box-two\nlines.csv";
  fs::copy_file(exact, script);
  fs::copy_file(exact, broken);
  FlipcheckLeagueJob job;
  job.scenes = {s};
  job.motions = {script, broken, exact};
  job.out_dir = dir / "out";
  const FlipcheckLeagueResult made = make_flipcheck_league(job);
  EXPECT_EQ(made.motions, 3);
  EXPECT_EQ(made.passed, 3);
  const std::string html = test::read_file(flipcheck_league_layout(job.out_dir).html);
  EXPECT_EQ(html.find("<script>"), std::string::npos);
  EXPECT_NE(html.find("<tr><th>&lt;script&gt;alert(1)&lt;script&gt;</th>"), std::string::npos)
      << html;
  const FlipcheckLeagueResult kept = make_flipcheck_league(job);
  EXPECT_EQ(kept.outcome, cache::Outcome::up_to_date);
  EXPECT_EQ(kept.motions, 3);
  EXPECT_EQ(kept.passed, 3);
}

// The scenario's SHA-256 is of the bytes `flipcheck export` writes, computed without the exact
// motion's rows.
TEST(Flipcheck, TheScenarioSha256IsOfTheExportedJson) {
  test::ScratchDir dir;
  const scene::Scene scene = box();
  make_flipcheck_export({scene, dir / "out", {}, {}});
  const analysis::Scenario scenario = analysis::scenario_of(scene);
  const fs::path json = dir / "out" / "mujoco-test-box.json";
  EXPECT_EQ(analysis::scenario_file(scenario), test::read_file(json));
  EXPECT_EQ(analysis::scenario_sha256(scenario), output::sha256_file(json).value());
}

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

/// Every file under `dir` (relative path → bytes).
std::map<std::string, std::string> files_under(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file())
      files[fs::relative(e.path(), dir).string()] = test::read_file(e.path());
  return files;
}

// The stop contract of an export of several scenarios (docs/outputs.md, "Signals"): a stop asked
// at any of its polls, the first or the last, leaves every earlier file, manifests included,
// byte for byte; never asked, every file is new and each manifest lists its scenario's files.
// So the last poll comes before the first file is put in place: asked after (a signal then
// replaced every file and left the manifests as they were), the stop at the last poll breaks
// it. Every poll is tried, so no moment of the run is left to chance.
TEST(Flipcheck, AStopAtAnyPollOfAnExportKeepsEveryEarlierFileOrMakesThemAll) {
  test::ScratchDir dir;
  const fs::path out = dir / "out";
  const std::vector<scene::Scene> scenes{
      box(), scene::parse_scene(fs::path(BOOKSPIN_SOURCE_DIR) / "scenes" / "flipcheck" /
                                "symmetric-top.toml")};
  const cache::Freshness force{true, false, {}};
  make_flipcheck_exports(scenes, out, force);
  std::map<std::string, std::string> earlier = files_under(out);
  ASSERT_EQ(earlier.size(), 6u);  // two files and a manifest each
  for (auto& [name, bytes] : earlier) {
    bytes = "earlier " + name + "\n";
    write_text(out / name, bytes);
  }
  int polls = 0;
  make_flipcheck_exports(scenes, out, force, [&](std::string_view) {
    ++polls;
    return 0;
  });
  ASSERT_GE(polls, 2);
  const std::map<std::string, std::string> made = files_under(out);
  for (int stop_at = 1; stop_at <= polls; ++stop_at) {
    SCOPED_TRACE("the stop asked at poll " + std::to_string(stop_at) + " of " +
                 std::to_string(polls));
    for (const auto& [name, bytes] : earlier) write_text(out / name, bytes);
    int asked = 0;
    EXPECT_THROW(
        make_flipcheck_exports(scenes, out, force,
                               [&](std::string_view) { return ++asked >= stop_at ? 2 : 0; }),
        Interrupted);
    EXPECT_EQ(files_under(out), earlier) << "an earlier file replaced by a stopped export";
  }
  // Not stopped: every file new, each manifest listing its scenario's two files.
  for (const auto& [name, bytes] : earlier) write_text(out / name, bytes);
  make_flipcheck_exports(scenes, out, force, [](std::string_view) { return 0; });
  const std::map<std::string, std::string> remade = files_under(out);
  ASSERT_EQ(remade.size(), earlier.size());
  for (const auto& [name, bytes] : remade) {
    EXPECT_NE(bytes, earlier.at(name)) << name;
    if (name.find("manifest") == std::string::npos) {
      EXPECT_EQ(bytes, made.at(name)) << name;
    }
  }
  for (const scene::Scene& scene : scenes) {
    const FlipcheckExportLayout layout = flipcheck_export_layout(out, scene);
    EXPECT_EQ(output::read_manifest(layout.manifest).outputs,
              (std::vector<std::string>{layout.json.filename().string(),
                                        layout.csv.filename().string()}));
  }
}

// One route per file (docs/flipcheck.md, "What a scenario may be"): the scenario JSON an export
// wrote, exported again, writes the same two files byte for byte (what `npx flipcheck export`
// writes of it), is up to date the second time, and takes no --set.
TEST(Flipcheck, AScenarioJsonExportsAsItsSceneFileDoes) {
  test::ScratchDir dir;
  make_flipcheck_export({box(), dir / "toml", {}, {}});
  const fs::path json = dir / "toml" / "mujoco-test-box.json";
  for (const fs::path& spelled : {json, dir / "toml" / "again.JSON"}) {
    SCOPED_TRACE(spelled.string());
    if (spelled != json) fs::copy_file(json, spelled);
    const FlipcheckExportScenario read = read_flipcheck_export_scenario(spelled, {});
    ASSERT_TRUE(read.json.has_value());
    EXPECT_EQ(read.name(), "mujoco-test-box");
    const fs::path out = dir / ("from-" + spelled.filename().string());
    EXPECT_EQ(make_flipcheck_exports({read}, out, {}).front(), cache::Outcome::made);
    for (const char* file : {"mujoco-test-box.json", "mujoco-test-box-exact.csv"})
      EXPECT_EQ(test::read_file(out / file), test::read_file(dir / "toml" / file)) << file;
    EXPECT_EQ(make_flipcheck_exports({read}, out, {}).front(), cache::Outcome::up_to_date);
  }
  try {
    read_flipcheck_export_scenario(json, {"body.mass=2"});
    ADD_FAILURE() << "--set taken for a scenario JSON";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--set changes a scene file (TOML), not a scenario JSON"),
              std::string::npos)
        << e.what();
  }
}

/// The `kit` line of VERSION (docs/flipcheck.md, "Versions").
std::string recorded_kit() {
  std::istringstream in(test::read_file(fs::path(BOOKSPIN_SOURCE_DIR) / "VERSION"));
  for (std::string line; std::getline(in, line);)
    if (line.rfind("kit ", 0) == 0) return line.substr(4);
  ADD_FAILURE() << "VERSION has no line \"kit SHA256\"";
  return {};
}

std::vector<analysis::Scenario> kit_scenarios() {
  std::vector<analysis::Scenario> scenarios;
  for (const fs::directory_entry& e :
       fs::directory_iterator(fs::path(BOOKSPIN_SOURCE_DIR) / "scenes" / "flipcheck"))
    if (e.path().extension() == ".toml")
      scenarios.push_back(analysis::scenario_of(scene::parse_scene(e.path())));
  return scenarios;
}

// The seven scenarios and the judge's rules are the ones VERSION records beside the version: a
// change to either must come with a new version (and its new kit line).
TEST(Flipcheck, TheKitIsTheOneItsVersionRecords) {
  const std::vector<analysis::Scenario> scenarios = kit_scenarios();
  ASSERT_EQ(scenarios.size(), 7u);
  const std::string kit = flipcheck_kit_sha256(scenarios);
  EXPECT_EQ(kit, recorded_kit())
      << "scenario or judge rules changed: bump the version (VERSION: version "
      << output::program_version() << " -> a new one) and record the new kit there: \"kit " << kit
      << "\" (docs/flipcheck.md, \"Versions\")";
}

// The kit's hash sees a scenario's every number, its name and every rule, and not the order the
// scenarios come in.
TEST(Flipcheck, TheKitHashChangesWithAScenarioAndNotWithTheirOrder) {
  std::vector<analysis::Scenario> scenarios = kit_scenarios();
  const std::string kit = flipcheck_kit_sha256(scenarios);
  std::reverse(scenarios.begin(), scenarios.end());
  EXPECT_EQ(flipcheck_kit_sha256(scenarios), kit);
  std::vector<analysis::Scenario> changed = scenarios;
  changed[0].steps += 1;
  EXPECT_NE(flipcheck_kit_sha256(changed), kit);
  changed = scenarios;
  changed[0].dt *= 1.0 + 1e-15;
  EXPECT_NE(flipcheck_kit_sha256(changed), kit);
  changed = scenarios;
  changed[0].body.moments[2] = std::nextafter(changed[0].body.moments[2], 1e9);
  EXPECT_NE(flipcheck_kit_sha256(changed), kit);
  changed = scenarios;
  changed[0].name += "-renamed";
  EXPECT_NE(flipcheck_kit_sha256(changed), kit);
  changed = scenarios;
  changed.pop_back();
  EXPECT_NE(flipcheck_kit_sha256(changed), kit);
  // Every threshold is a line of the rules that the kit hashes.
  const std::string rules = analysis::judge_rules();
  for (const char* rule :
       {"start 1e-06\n", "energy_drift 0.01\n", "L_drift 0.01\n", "first_flip 0.05\n",
        "orientation_error 0.1\n", "separatrix_approach 0.1\n", "tumble_cosine 0.5\n",
        "flip_margin 0.5\n", " version scenario_sha256\n"})
    EXPECT_NE(rules.find(rule), std::string::npos) << rule << " not in\n" << rules;
}

}  // namespace
}  // namespace bookspin::products
