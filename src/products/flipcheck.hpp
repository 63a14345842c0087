#pragma once
// The conformance kit's products (`bookspin flipcheck`, docs/flipcheck.md): a scenario
// exported for any engine (its start as JSON, the exact motion at every step as CSV) and the
// judgement of motions an engine wrote (a CSV, one row per motion), each with its manifest.
// Every path they write is named here; the measuring is jobs' (jobs/exact_motion.hpp,
// jobs/motion_judgement.hpp) and analysis' (analysis/conformance.hpp).
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/conformance.hpp"
#include "cache/freshness.hpp"
#include "common/csv_writer.hpp"
#include "common/json_writer.hpp"
#include "common/stop.hpp"
#include "jobs/exact_motion.hpp"
#include "scene/scene.hpp"

namespace bookspin::products {

/// Every path an export of one scenario into OUT writes.
struct FlipcheckExportLayout {
  std::filesystem::path json;      ///< OUT/<scenario>.json: what an engine needs to run it
  std::filesystem::path csv;       ///< OUT/<scenario>-exact.csv: the exact motion, every step
  std::filesystem::path manifest;  ///< OUT/<scenario>/flipcheck-export-manifest.json
};

/// The layout of `scene`'s export in `out_dir`. No I/O.
FlipcheckExportLayout flipcheck_export_layout(const std::filesystem::path& out_dir,
                                              const scene::Scene& scene);
/// The same of the scenario named `scenario`.
FlipcheckExportLayout flipcheck_export_layout(const std::filesystem::path& out_dir,
                                              const std::string& scenario);

/// One scenario of an export: a scene file's (TOML), or the scenario JSON `export` wrote.
struct FlipcheckExportScenario {
  scene::Scene scene;  ///< a scene file's scene (one model, no [[compare]]); unused with `json`
  /// The scenario of a scenario JSON (analysis::scenario_from_json), exported as the npm
  /// package exports it: its files depend on it alone, its manifest records its SHA-256
  std::optional<analysis::Scenario> json = std::nullopt;
  /// With `json`: its canonical text's SHA-256 (analysis::scenario_sha256, as every door
  /// hashes it), made when it is read: its export's freshness key
  std::string json_sha256 = {};
  /// Its name: OUT/<name>.json
  const std::string& name() const { return json ? json->name : scene.name; }
};

/// The scenario `path` names for `flipcheck export`: a scenario JSON where its name ends in
/// .json in any case (is_scenario_json, one route per file at every door: docs/flipcheck.md,
/// "What a scenario may be"), read by analysis::scenario_from_json; else a scene file with
/// `overrides` (--set), refused for a comparison scene (analysis::scenario_of). Throws
/// InputError naming the file (a scenario JSON with `overrides`: --set changes a scene file).
FlipcheckExportScenario read_flipcheck_export_scenario(const std::filesystem::path& path,
                                                       const std::vector<std::string>& overrides);

struct FlipcheckExportJob {
  scene::Scene scene;  ///< the scenario (one model, no [[compare]])
  std::filesystem::path out_dir;
  cache::Freshness freshness;
  StopPoll stop;  ///< may be empty
};

/// (scenario) => OUT/<scenario>.json, OUT/<scenario>-exact.csv + manifest.
/// Unless its manifest says it is up to date: computes the exact motion
/// (jobs::exact_motion) and writes both files. Throws InputError for a comparison scene,
/// OutputError, Interrupted.
cache::Outcome make_flipcheck_export(const FlipcheckExportJob& job);

/// The export of several scenarios into one OUT, as one command (`bookspin flipcheck export
/// A B C`): every scenario that is not up to date computed and its files written under
/// temporary names, the stop asked once all are, and only then every file put in place together
/// (one output::OutputSet: all or none), each scenario's manifest after. A signal before then
/// leaves every earlier file, the manifests too, byte for byte (docs/outputs.md, "Signals").
/// Each scenario's outcome, in order. Throws as make_flipcheck_export().
std::vector<cache::Outcome> make_flipcheck_exports(const std::vector<scene::Scene>& scenes,
                                                   const std::filesystem::path& out_dir,
                                                   const cache::Freshness& freshness,
                                                   const StopPoll& stop = {});
/// The same of scenarios from scene files or scenario JSONs: a scenario JSON's files are
/// `npx flipcheck export`'s of the same file, byte for byte.
std::vector<cache::Outcome> make_flipcheck_exports(
    const std::vector<FlipcheckExportScenario>& scenarios, const std::filesystem::path& out_dir,
    const cache::Freshness& freshness, const StopPoll& stop = {});

/// Whether `path`'s name ends in `extension`, lower case (".json", ".toml"), in any case: one
/// route per file at every door (docs/flipcheck.md, "What a scenario may be"). No I/O.
bool has_extension(const std::filesystem::path& path, std::string_view extension);

/// Whether `path` names a scenario JSON (`export`'s OUT/<scenario>.json: its name ends in .json,
/// any case) rather than a scene file (TOML). No I/O.
bool is_scenario_json(const std::filesystem::path& path);

/// Every path a judgement of one scenario into OUT writes.
struct FlipcheckJudgeLayout {
  std::filesystem::path csv;       ///< OUT/<scenario>-judge.csv: one row per motion file
  std::filesystem::path manifest;  ///< OUT/<scenario>/flipcheck-judge-manifest.json
};

FlipcheckJudgeLayout flipcheck_judge_layout(const std::filesystem::path& out_dir,
                                            const std::string& scenario);
FlipcheckJudgeLayout flipcheck_judge_layout(const std::filesystem::path& out_dir,
                                            const scene::Scene& scene);

struct FlipcheckJudgeJob {
  /// The scenario: a scene file's (TOML), or, where `scenario_file` is set, the scenario JSON
  /// `export` wrote (analysis::scenario_from_json) with the scene's defaults for the methods'
  /// model settings
  scene::Scene scene;
  std::vector<std::filesystem::path> motions;  ///< motion CSVs (jobs/motion_csv.hpp)
  std::filesystem::path out_dir;
  cache::Freshness freshness;
  /// bookspin's own methods and the engines' modes, each run from the scenario's start with
  /// the scene's other model settings (analysis::simulated_motion), a row every
  /// time.steps_per_frame steps; judged after the files
  std::vector<analysis::Method> methods = {};
  StopPoll stop = {};                        ///< may be empty
  std::filesystem::path scenario_file = {};  ///< a scenario JSON, read by make_flipcheck_judge
};

struct FlipcheckJudgeResult {
  cache::Outcome outcome = cache::Outcome::made;
  std::string scenario;                        ///< its name
  FlipcheckJudgeLayout layout;                 ///< what it wrote
  std::vector<analysis::JudgedMotion> judged;  ///< in the order given (also when up to date)
};

/// (scenario, motions, methods) => OUT/<scenario>-judge.csv + manifest.
/// Asks jobs for the judgement as one value (jobs::judge_scenario: every motion file read
/// before anything is written, a bad file an InputError naming its file, line and column;
/// every method run; each motion judged; the table), then writes the CSV unless its manifest,
/// whose head holds every motion file's SHA-256 and the methods, says it is up to date. Throws
/// InputError, OutputError, Interrupted.
FlipcheckJudgeResult make_flipcheck_judge(const FlipcheckJudgeJob& job);

/// Every path a league table into OUT writes.
struct FlipcheckLeagueLayout {
  std::filesystem::path csv;       ///< OUT/flipcheck-league.csv: every scenario's judgement rows
  std::filesystem::path html;      ///< OUT/flipcheck-league.html: a motion per row, a scenario
                                   ///< per column
  std::filesystem::path manifest;  ///< OUT/flipcheck-league-manifest.json
};

FlipcheckLeagueLayout flipcheck_league_layout(const std::filesystem::path& out_dir);

struct FlipcheckLeagueJob {
  std::vector<scene::Scene> scenes;  ///< the scenarios, in the table's column order
  /// Motion files an engine wrote, each named "<scenario>-<motion>.csv" after the scenario it
  /// runs (the exported "<scenario>-exact.csv" among them); its row is "<motion>".
  std::vector<std::filesystem::path> motions;
  std::vector<analysis::Method> methods;  ///< run in every scenario, as FlipcheckJudgeJob's
  std::filesystem::path out_dir;
  cache::Freshness freshness;
  StopPoll stop = {};  ///< may be empty
};

struct FlipcheckLeagueResult {
  cache::Outcome outcome = cache::Outcome::made;
  int motions = 0;  ///< the table's rows
  int passed = 0;   ///< the rows that pass every scenario they ran
};

/// (scenarios, motions, methods) => OUT/flipcheck-league.csv + OUT/flipcheck-league.html +
/// manifest (docs/flipcheck.md, "The league table").
/// Gives each motion file to the scenario its name starts with (the longest such name; a file
/// that names none is an InputError), reads and runs everything before writing anything, and
/// judges it as make_flipcheck_judge() does; the CSV is the scenarios' judgement tables one
/// after the other, the page the league table: a row per motion (files by their <motion>
/// part, methods by label), a column per scenario, each cell pass or fail with the turn-overs
/// against the exact count, a stable spin's tumble time and the reasons of a failure.
/// Both files together or neither; up to date when the same table would be written. Throws
/// InputError, OutputError, Interrupted.
FlipcheckLeagueResult make_flipcheck_league(const FlipcheckLeagueJob& job);

/// The kit's SHA-256, which VERSION records beside the version (docs/flipcheck.md, "Versions"):
/// of the text "kit\n", then a line "NAME SHA256" per scenario in the order of their names
/// (analysis::scenario_sha256), then analysis::judge_rules(). A changed scenario or rule changes
/// it.
std::string flipcheck_kit_sha256(const std::vector<analysis::Scenario>& scenarios);

}  // namespace bookspin::products
