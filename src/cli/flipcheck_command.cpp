// `bookspin flipcheck`: the conformance kit (docs/flipcheck.md). `export` writes each
// scenario's start and exact motion for any engine; `judge` compares motions an engine wrote
// with the exact one and says pass or fail.
#include <algorithm>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "analysis/conformance.hpp"
#include "cache/freshness.hpp"
#include "cli/commands.hpp"
#include "cli/interrupt.hpp"
#include "cli/subcommand.hpp"
#include "common/errors.hpp"
#include "common/file_name.hpp"
#include "products/flipcheck.hpp"
#include "scene/scene.hpp"

namespace bookspin::cli {
namespace {

struct FlipcheckOptions {
  std::vector<std::string> scenarios;  ///< export: SCENARIO...
  std::string scenario;                ///< judge: SCENARIO
  std::vector<std::string> motions;    ///< judge: MOTION.csv...; league: --motions
  std::string methods;                 ///< judge, league: analysis::parse_methods(), or none
  std::vector<std::string> overrides;
  std::string out_dir = "out/flipcheck";
  bool force = false;
  bool verify = false;
};

/// Writes OUT/<scenario>.json and OUT/<scenario>-exact.csv for each scenario: a scene file
/// (TOML) or a scenario JSON, by its extension (products::read_flipcheck_export_scenario).
int export_scenarios(const FlipcheckOptions& options) {
  // Every scenario read before anything is written.
  std::vector<products::FlipcheckExportScenario> scenarios;
  for (const std::string& path : options.scenarios)
    scenarios.push_back(products::read_flipcheck_export_scenario(path, options.overrides));
  // A scenario once: two of one name would write one pair of files twice.
  for (std::size_t i = 0; i < scenarios.size(); ++i)
    for (std::size_t k = 0; k < i; ++k)
      if (scenarios[i].name() == scenarios[k].name())
        throw InputError("flipcheck export: two scenarios named " + scenarios[i].name() +
                         " (one given twice, or two of one name): give each once");
  // One command, one stop: every scenario staged, then all put in place together.
  const std::vector<cache::Outcome> outcomes = products::make_flipcheck_exports(
      scenarios, options.out_dir, {options.force, options.verify, remake_note}, stop_poll());
  for (std::size_t i = 0; i < scenarios.size(); ++i) {
    const products::FlipcheckExportLayout layout =
        products::flipcheck_export_layout(options.out_dir, scenarios[i].name());
    std::cout << (outcomes[i] == cache::Outcome::up_to_date ? "up to date: " : "exported: ")
              << layout.json.string() << ", " << layout.csv.string() << std::endl;
  }
  return kExitOk;
}

/// What judge and league share: the --methods parsed (a list that names nothing is refused
/// before anything runs), the freshness flags and the stop poll, set on `job`.
template <typename Job>
void set_common(Job& job, const FlipcheckOptions& options, const char* command, const char* files) {
  if (!options.methods.empty()) job.methods = analysis::parse_methods(options.methods);
  if (job.motions.empty() && job.methods.empty())
    throw InputError(std::string("flipcheck ") + command + ": nothing to judge: give " + files +
                     " or --methods");
  job.out_dir = options.out_dir;
  job.freshness = {options.force, options.verify, remake_note};
  job.stop = stop_poll();
}

/// Judges each motion against the scenario's exact motion: one verdict line each, and
/// OUT/<scenario>-judge.csv. Exit 0 when every motion passes, kExitJudgedFail (3) when one
/// fails (the lines printed and the CSV written all the same), so that a CI step fails on it.
int judge_motions(const FlipcheckOptions& options) {
  products::FlipcheckJudgeJob job;
  // A scenario JSON as export wrote it (what an engine ran), or a scene file.
  if (products::is_scenario_json(options.scenario)) {
    if (!options.overrides.empty())
      throw InputError(options.scenario +
                       ": flipcheck judge: --set changes a scene file (TOML), not a scenario "
                       "JSON: edit the JSON, or give the scene file");
    job.scenario_file = options.scenario;
  } else {
    job.scene = scene::parse_scene(options.scenario, options.overrides);
  }
  for (const std::string& m : options.motions) job.motions.emplace_back(m);
  set_common(job, options, "judge", "MOTION files");
  const products::FlipcheckJudgeResult result = products::make_flipcheck_judge(job);
  for (const analysis::JudgedMotion& j : result.judged)
    // The file as given, in valid UTF-8 as its CSV row names it (common/file_name.hpp).
    std::cout << result.scenario << " "
              << (j.file.empty() ? j.name : utf8_replaced(j.file.string())) << ": "
              << analysis::verdict_line(j.result) << '\n';
  std::cout << (result.outcome == cache::Outcome::up_to_date ? "up to date: " : "wrote: ")
            << result.layout.csv.string() << std::endl;
  const bool all_pass =
      std::all_of(result.judged.begin(), result.judged.end(),
                  [](const analysis::JudgedMotion& j) { return j.result.pass(); });
  return all_pass ? kExitOk : kExitJudgedFail;
}

/// Judges every motion file and method in every scenario: OUT/flipcheck-league.csv and
/// OUT/flipcheck-league.html.
int league_table(const FlipcheckOptions& options) {
  products::FlipcheckLeagueJob job;
  for (const std::string& path : options.scenarios) {
    job.scenes.push_back(scene::parse_scene(path, options.overrides));
    analysis::scenario_of(job.scenes.back());  // a comparison scene is refused here
  }
  for (const std::string& m : options.motions) job.motions.emplace_back(m);
  set_common(job, options, "league", "--motions files");
  const products::FlipcheckLeagueResult result = products::make_flipcheck_league(job);
  const auto layout = products::flipcheck_league_layout(options.out_dir);
  std::cout << (result.outcome == cache::Outcome::up_to_date ? "up to date: " : "wrote: ")
            << layout.html.string() << ", " << layout.csv.string() << " (" << result.motions
            << " motions in " << job.scenes.size() << " scenarios, " << result.passed
            << " pass every one)" << std::endl;
  return kExitOk;
}

/// Every flipcheck subcommand's -o/--out, --set and freshness flags (its manifest `manifest`).
void add_out_set_and_freshness(CLI::App* cmd, FlipcheckOptions& options,
                               const std::string& manifest) {
  add_out_option(cmd, options.out_dir, "Output directory");
  cmd->add_option("--set", options.overrides, kSetHelp)->take_all()->allow_extra_args(false);
  add_freshness_flags(cmd, options.force, options.verify, manifest);
}

/// What `flipcheck judge --help` says of its exit statuses (docs/flipcheck.md, "In a CI job").
constexpr const char* kJudgeExitStatuses =
    "Exit status: 0 every motion passes; 3 a motion fails (its FAIL line printed and the CSV "
    "written: a CI step that runs judge fails on it); 2 bad input (a scenario or motion file it "
    "cannot use: one line, nothing written); 1 an output could not be written; 70 internal "
    "error; 128+n stopped by signal n (nothing written).";

}  // namespace

Subcommand add_flipcheck(CLI::App& cli) {
  const auto stored = std::make_shared<FlipcheckOptions>();
  FlipcheckOptions& options = *stored;
  CLI::App* cmd = cli.add_subcommand(
      "flipcheck",
      "The conformance kit for any engine (docs/flipcheck.md): export scenarios and their exact "
      "motion, judge the motion an engine wrote");
  cmd->require_subcommand(1);
  CLI::App* exporter = cmd->add_subcommand(
      "export",
      "Write OUT/<scenario>.json (mass, principal moments, q0, omega0, dt, steps) and "
      "OUT/<scenario>-exact.csv (the exact motion at every step) for each scenario");
  exporter
      ->add_option("SCENARIO", options.scenarios,
                   "Scenarios: scene files (TOML, e.g. scenes/flipcheck/*.toml) or scenario JSONs "
                   "export wrote (a name ending in .json)")
      ->required();
  add_out_set_and_freshness(exporter, options, "OUT/<scenario>/flipcheck-export-manifest.json");
  CLI::App* judge = cmd->add_subcommand(
      "judge",
      "Compare motion CSVs (t,qw,qx,qy,qz and wx,wy,wz or wx_world,wy_world,wz_world) with the "
      "scenario's exact motion: a verdict line each and OUT/<scenario>-judge.csv");
  judge->footer(kJudgeExitStatuses);
  judge
      ->add_option("SCENARIO", options.scenario,
                   "Scenario: a scene file (TOML, e.g. scenes/flipcheck/*.toml) or the scenario "
                   "JSON export wrote (OUT/<scenario>.json)")
      ->required();
  judge->add_option("MOTION", options.motions, "Motion CSV files written by an engine");
  const char* methods_help =
      "bookspin's own methods and the engines' modes to run from the scenario's start and "
      "judge too, comma-separated: all, engines, rigid, a model kind (every mode of it) or "
      "KIND:INTEGRATOR, e.g. engines,rigid-quaternion:rk4";
  judge->add_option("--methods", options.methods, methods_help);
  add_out_set_and_freshness(judge, options, "OUT/<scenario>/flipcheck-judge-manifest.json");
  CLI::App* league = cmd->add_subcommand(
      "league",
      "Judge motion files and methods in every scenario: OUT/flipcheck-league.html (a motion "
      "per row, a scenario per column) and OUT/flipcheck-league.csv");
  league->add_option("SCENARIO", options.scenarios, "Scenario files (TOML)")->required();
  league
      ->add_option("--motions", options.motions,
                   "Motion CSV files, each named <scenario>-<motion>.csv (the exported "
                   "<scenario>-exact.csv among them)")
      ->take_all();
  league->add_option("--methods", options.methods, methods_help);
  add_out_set_and_freshness(league, options, "OUT/flipcheck-league-manifest.json");
  return {cmd, [stored, exporter, league] {
            if (exporter->parsed()) return export_scenarios(*stored);
            return league->parsed() ? league_table(*stored) : judge_motions(*stored);
          }};
}

}  // namespace bookspin::cli
