#include "products/flipcheck.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <sstream>
#include <stdexcept>

#include "analysis/scenario_file.hpp"
#include "cache/make_cached.hpp"
#include "common/csv_writer.hpp"
#include "common/errors.hpp"
#include "common/file_name.hpp"
#include "common/sha256.hpp"
#include "common/text_file.hpp"
#include "jobs/motion_judgement.hpp"
#include "jobs/scenario_export.hpp"
#include "output/atomic_output.hpp"
#include "output/manifest.hpp"
#include "output/output_dir.hpp"
#include "output/staged_files.hpp"
#include "products/gallery_page.hpp"

namespace bookspin::products {

namespace {

JsonValue method_labels(const std::vector<analysis::Method>& methods) {
  JsonArray labels;
  for (const analysis::Method& m : methods) labels.push_back({m.label});
  return {std::move(labels)};
}

/// The motion column's name of each file: its name (made valid UTF-8 where the judgement is
/// made: jobs::judge_scenario).
std::vector<std::string> file_names(const std::vector<std::filesystem::path>& files) {
  std::vector<std::string> names;
  for (const auto& f : files) names.push_back(f.filename().string());
  return names;
}

}  // namespace

FlipcheckExportLayout flipcheck_export_layout(const std::filesystem::path& out_dir,
                                              const std::string& scenario) {
  return {out_dir / (scenario + ".json"), out_dir / (scenario + "-exact.csv"),
          out_dir / scenario / "flipcheck-export-manifest.json"};
}

FlipcheckExportLayout flipcheck_export_layout(const std::filesystem::path& out_dir,
                                              const scene::Scene& scene) {
  return flipcheck_export_layout(out_dir, scene.name);
}

FlipcheckExportScenario read_flipcheck_export_scenario(const std::filesystem::path& path,
                                                       const std::vector<std::string>& overrides) {
  FlipcheckExportScenario read;
  if (is_scenario_json(path)) {
    if (!overrides.empty())
      throw InputError(path.string() +
                       ": flipcheck export: --set changes a scene file (TOML), not a scenario "
                       "JSON: edit the JSON, or give the scene file");
    read.json =
        analysis::scenario_from_json(read_text_file(path, "the scenario file"), path.string());
    read.json_sha256 = analysis::scenario_sha256(*read.json);
    return read;
  }
  read.scene = scene::parse_scene(path, overrides);
  analysis::scenario_of(read.scene);  // a comparison scene is refused here
  return read;
}

cache::Outcome make_flipcheck_export(const FlipcheckExportJob& job) {
  return make_flipcheck_exports({job.scene}, job.out_dir, job.freshness, job.stop).front();
}

std::vector<cache::Outcome> make_flipcheck_exports(const std::vector<scene::Scene>& scenes,
                                                   const std::filesystem::path& out_dir,
                                                   const cache::Freshness& freshness,
                                                   const StopPoll& stop) {
  std::vector<FlipcheckExportScenario> scenarios;
  for (const scene::Scene& scene : scenes) scenarios.push_back({scene});
  return make_flipcheck_exports(scenarios, out_dir, freshness, stop);
}

std::vector<cache::Outcome> make_flipcheck_exports(
    const std::vector<FlipcheckExportScenario>& scenarios, const std::filesystem::path& out_dir,
    const cache::Freshness& freshness, const StopPoll& stop) {
  std::vector<FlipcheckExportLayout> layouts;
  std::vector<cache::CachedOutputs> cached;
  for (const FlipcheckExportScenario& scenario : scenarios) {
    layouts.push_back(flipcheck_export_layout(out_dir, scenario.name()));
    // A scenario JSON has no scene: its export is up to date for the same scenario (its
    // canonical text's SHA-256, as every door hashes it) and the same program.
    JsonObject options;
    BOOKSPIN_ASSERT(!scenario.json || !scenario.json_sha256.empty());
    if (scenario.json)
      options = {{"bookspin",
                  {JsonObject{{"version", {output::program_version()}},
                              {"build_id", {"sha256:" + output::program_build_id()}}}}},
                 {"scenario_sha256", {scenario.json_sha256}}};
    cached.push_back({scenario.name() + "-flipcheck", layouts.back().manifest, "flipcheck export",
                      std::move(options), out_dir, scenario.json ? nullptr : &scenario.scene,
                      /*all_or_nothing=*/true});
  }
  output::StagedFiles staged;
  // Every scenario's files staged, then put in place at once: all of them or none.
  return cache::make_cached_together(
      cached, freshness,
      [&](std::size_t i) {
        const FlipcheckExportLayout& layout = layouts[i];
        {  // the texts freed once written: only the temporaries wait for the rest
          const jobs::ExportFiles texts =
              scenarios[i].json
                  ? jobs::export_files(jobs::exact_motion(*scenarios[i].json, stop), stop)
                  : jobs::scenario_export(scenarios[i].scene, stop);
          output::prepare_output_dir(layout.json.parent_path());
          staged.text(layout.json, texts.json);
          staged.text(layout.csv, texts.csv);
        }
        return cache::Made{{layout.json, layout.csv}};
      },
      [&] {
        // Asked once every temporary is written (a CSV of 10^6 rows takes a while to write),
        // just before they are put in place: a signal until then leaves every earlier file.
        stop_if_asked(stop, "flipcheck export write");
        staged.commit();
      });
}

bool has_extension(const std::filesystem::path& path, std::string_view extension) {
  std::string own = path.extension().string();
  std::transform(own.begin(), own.end(), own.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return own == extension;
}

bool is_scenario_json(const std::filesystem::path& path) { return has_extension(path, ".json"); }

FlipcheckJudgeLayout flipcheck_judge_layout(const std::filesystem::path& out_dir,
                                            const std::string& scenario) {
  return {out_dir / (scenario + "-judge.csv"),
          out_dir / scenario / "flipcheck-judge-manifest.json"};
}

FlipcheckJudgeLayout flipcheck_judge_layout(const std::filesystem::path& out_dir,
                                            const scene::Scene& scene) {
  return flipcheck_judge_layout(out_dir, scene.name);
}

FlipcheckJudgeResult make_flipcheck_judge(const FlipcheckJudgeJob& job) {
  JsonObject options;
  if (!job.methods.empty()) options.push_back({"methods", method_labels(job.methods)});
  const bool from_json = !job.scenario_file.empty();
  // The measuring room's value: the scenario, its motions read and run, each judged, the table.
  const std::vector<std::string> names = file_names(job.motions);
  jobs::Judgement judgement =
      jobs::judge_scenario(job.scene, job.scenario_file, job.motions, names, job.methods, job.stop);
  const FlipcheckJudgeLayout layout = flipcheck_judge_layout(job.out_dir, judgement.scenario.name);
  // A scenario JSON has no scene: its judgement is up to date for the same scenario (its
  // canonical text's SHA-256, as every door hashes it), options and motion files.
  if (from_json) options.push_back({"scenario_sha256", {judgement.scenario_sha256}});
  const cache::CachedOutputs cached{judgement.scenario.name + "-judge",
                                    layout.manifest,
                                    "flipcheck judge",
                                    std::move(options),
                                    job.out_dir,
                                    from_json ? nullptr : &job.scene,
                                    /*all_or_nothing=*/true,
                                    job.motions};
  FlipcheckJudgeResult result;
  result.outcome = cache::make_cached(cached, job.freshness, [&] {
    output::prepare_output_dir(layout.csv.parent_path());
    output::write_text_file(layout.csv, csv_text(judgement.table, "flipcheck judge CSV"));
    return cache::Made{{layout.csv}};
  });
  result.scenario = judgement.scenario.name;
  result.layout = layout;
  result.judged = std::move(judgement.judged);
  return result;
}

FlipcheckLeagueLayout flipcheck_league_layout(const std::filesystem::path& out_dir) {
  return {out_dir / "flipcheck-league.csv", out_dir / "flipcheck-league.html",
          out_dir / "flipcheck-league-manifest.json"};
}

namespace {

/// One scenario's column of the league: its name and every motion judged in it.
struct LeagueColumn {
  std::string scenario;
  std::string title;
  std::vector<analysis::JudgedMotion> judged;
};

/// "pass 6/6" (turn-overs: the motion's / the exact motion's), "fail 0/6", "pass, no
/// turn-over" (a stable spin kept), "fail, tumbles at t = 42.6": a league cell (the docs' table).
std::string league_cell(const analysis::Conformance& c) {
  std::string cell = c.pass() ? "pass" : "fail";
  if (c.stable_spin && c.tumble_time) {
    std::ostringstream t;
    t.precision(3);
    t << *c.tumble_time;
    return cell + ", tumbles at t = " + t.str();
  }
  // "no turn-over" only where neither turns over: 0/6 is an engine that never flips.
  if (c.flips == 0 && c.flips_exact == 0) return cell + ", no turn-over";
  return cell + " " + std::to_string(c.flips) + "/" + std::to_string(c.flips_exact);
}

/// What a row's name says of the engine that made it (docs/flipcheck.md, "Any engine").
constexpr const char* kMotionNames =
    "<p>What the motions' names say:</p>\n<dl class=\"names\">\n"
    "<dt>rigid-matrix euler, rigid-quaternion rk4, particle velocity-verlet</dt>"
    "<dd>bookspin's own models (its rigid body as a matrix or a quaternion, or a lattice of "
    "particles), each with the integrator named after it.</dd>\n"
    "<dt>mujoco euler, bullet none, ode step</dt><dd>an engine built into bookspin from its C or "
    "C++ library (MuJoCo, Bullet, ODE: docs/engines.md) with the integrator or option named "
    "after it (bullet none: without its gyroscopic term).</dd>\n"
    "<dt>mujoco-js@0.0.7+euler, jolt-physics@1.1.0+gyroscopic</dt><dd>a JavaScript engine, "
    "named by its npm package and version, run under node by web/flipcheck-engines.mjs, in "
    "the mode after the +: mujoco-js is MuJoCo compiled to WebAssembly, so "
    "mujoco-js@0.0.7+euler and mujoco euler are the same method in two builds.</dd>\n"
    "<dt>exact</dt><dd>the exact motion itself, as <code>bookspin flipcheck export</code> "
    "writes it: it passes by construction.</dd>\n</dl>\n";

/// The league page: a self-contained HTML5 table, a motion per row in order of first
/// appearance, a scenario per column; a failed cell lists its reasons.
/// A motion's name as HTML that breaks only after the separators of an engine's name ('/', '@',
/// '-'), never inside a version or a word ("cannon-es@0.20.0/fixed": "cannon-", "es@",
/// "0.20.0/", "fixed").
std::string breakable_name(const std::string& name) {
  std::string html;
  for (char c : name) {
    html += html_escape(std::string(1, c));
    if (c == '/' || c == '@' || c == '-') html += "<wbr>";
  }
  return html;
}

std::string league_html(const std::vector<LeagueColumn>& columns) {
  std::vector<std::string> rows;
  for (const LeagueColumn& col : columns)
    for (const auto& j : col.judged)
      if (std::find(rows.begin(), rows.end(), j.name) == rows.end()) rows.push_back(j.name);
  std::ostringstream page;
  page << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
          // A phone lays the page out at its own width (the text wraps, the table scrolls
          // in its box under its kept header row and first column), not at 980 px shrunk to a
          // third.
          "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
          "<title>bookspin flipcheck: the league table</title>\n<style>\n"
          "body { font-family: sans-serif; margin: 2em; color: #222; background: #fff; }\n"
          "@media (max-width: 599px) { body { margin: 1em 0.6em; } }\n"
          // Separate borders (each cell its right and bottom one): a sticky cell carries its
          // own borders, where collapsed ones stay behind and let the rows show through.
          "table { border-collapse: separate; border-spacing: 0; font-size: 0.95em; "
          "border-top: 1px solid #ccc; border-left: 1px solid #ccc; }\n"
          "th, td { border-right: 1px solid #ccc; border-bottom: 1px solid #ccc; "
          "padding: 0.3em 0.6em; text-align: left; vertical-align: top; }\n"
          "td { min-width: 9em; }\n"
          // The table's own box, no taller than the window: its header row and first column
          // stay while it scrolls either way (a page scrolled sideways is shrunk on a phone).
          ".league { overflow: auto; max-height: calc(100vh - 1em); width: fit-content; "
          "max-width: 100%; }\n"
          "td.pass { background: #e3f4e1; } td.fail { background: #f9e0de; }\n"
          "td.none { color: #999; background: #fff; } td small { color: #555; }\n"
          // The scenarios' row stays on screen while the motions scroll under it, the
          // motions' column while the scenarios scroll sideways (a phone).
          "thead th { position: sticky; top: 0; background: #f4f4f4; z-index: 1; }\n"
          "tbody th { position: sticky; left: 0; background: #fafafa; z-index: 1; "
          "max-width: 40vw; }\n"
          "thead th:first-child { left: 0; z-index: 2; }\n"
          "dl.names dt { font-family: monospace; margin-top: 0.4em; }\n"
          "dl.names dd { margin-left: 1.5em; }\n"
          // On paper every motion and every scenario (docs/flipcheck.md, "The league on paper"):
          // the table's box as tall as the table (at the window's height it printed 5 of 37
          // motions, and a scroll bar), the scenarios' columns the page's width (7 columns of
          // 9em each ran 3 past A4's edge), a row never split, the scenarios' row over each
          // page's rows, nothing sticky; the pass and fail colours kept; a word broken only where
          // it would not fit its column (break-word, not anywhere: a column keeps its width).
          "@media print {\n"
          "  body { margin: 0; font-size: 9pt; color: #000; }\n"
          "  .league { overflow: visible; max-height: none; width: auto; max-width: none; }\n"
          "  table { width: 100%; table-layout: fixed; font-size: 7.5pt; }\n"
          "  td { min-width: 0; }\n"
          "  th, td { overflow-wrap: break-word; padding: 0.2em 0.3em; }\n"
          "  thead th, tbody th { position: static; max-width: none; }\n"
          "  thead { display: table-header-group; }\n"
          "  tr { break-inside: avoid; }\n"
          "  a { color: #000; } td.none { color: #555; }\n"
          "  th, td { print-color-adjust: exact; -webkit-print-color-adjust: exact; }\n"
          "}\n</style>\n</head>\n<body>\n"
          // Every part of the page in one main landmark (docs/explorer.md, "For every person").
          "<main>\n<h1>Does the engine get the flip right? The league table</h1>\n"
          "<p>Each motion judged against the exact motion from the same start "
          "(<code>bookspin flipcheck</code>, docs/flipcheck.md): pass or fail against the "
          "documented thresholds, the turn-overs counted against the exact count (6/6: the "
          "motion's six of the exact motion's six), and for a stable spin the time it starts "
          "to tumble; under a failure, its reasons. Every "
          "number is in <a href=\"flipcheck-league.csv\">flipcheck-league.csv"
          "</a>.</p>\n"
       << kMotionNames
       // Scrolled by keyboard too, and named for a screen reader (axe's
       // scrollable-region-focusable).
       << "<div class=\"league\" tabindex=\"0\" role=\"region\" aria-label=\"The league "
          "table: each motion against each scenario\"><table>\n<thead><tr><th>motion</th>";
  for (const LeagueColumn& col : columns)
    page << "<th title=\"" << html_escape(col.title) << "\">" << html_escape(col.scenario)
         << "</th>";
  page << "</tr></thead>\n<tbody>\n";
  for (const std::string& row : rows) {
    page << "<tr><th>" << breakable_name(row) << "</th>";
    for (const LeagueColumn& col : columns) {
      const auto it = std::find_if(col.judged.begin(), col.judged.end(),
                                   [&](const analysis::JudgedMotion& j) { return j.name == row; });
      if (it == col.judged.end()) {
        page << "<td class=\"none\">not run</td>";
        continue;
      }
      std::string reasons;
      for (const std::string& f : it->result.failures) reasons += (reasons.empty() ? "" : "; ") + f;
      page << "<td class=\"" << (it->result.pass() ? "pass" : "fail") << "\">"
           << html_escape(league_cell(it->result));
      if (!reasons.empty()) page << "<br><small>" << html_escape(reasons) << "</small>";
      page << "</td>";
    }
    page << "</tr>\n";
  }
  page << "</tbody>\n</table></div>\n</main>\n</body>\n</html>\n";
  return page.str();
}

/// Why `file` cannot be a motion CSV, or "": "no such file" (with a word on unmatched shell
/// patterns when it holds *, ? or [), "is a folder, not a motion CSV", or another
/// not_a_file_reason().
std::string motion_path_problem(const std::filesystem::path& file) {
  std::string why = not_a_file_reason(file);
  if (why == "no such file" && file.string().find_first_of("*?[") != std::string::npos)
    return why + " (a pattern that matched no file is passed on as written by the shell)";
  if (why == "is a directory")
    return "is a folder, not a motion CSV (give its files, e.g. " + (file / "*.csv").string() + ")";
  return why;
}

}  // namespace

FlipcheckLeagueResult make_flipcheck_league(const FlipcheckLeagueJob& job) {
  const FlipcheckLeagueLayout layout = flipcheck_league_layout(job.out_dir);
  // A scenario once: two of one name (or one given twice) would be two columns of one name.
  for (std::size_t i = 0; i < job.scenes.size(); ++i)
    for (std::size_t k = 0; k < i; ++k)
      if (job.scenes[i].name == job.scenes[k].name)
        throw InputError("flipcheck league: two scenarios named " + job.scenes[i].name +
                         " (one given twice, or two files of one scene.name): give each once");
  // Each file to the scenario whose "<name>-" its name starts with, the longest such name.
  std::vector<std::vector<std::filesystem::path>> files(job.scenes.size());
  std::vector<std::vector<std::string>> motion_names(job.scenes.size());
  for (const std::filesystem::path& file : job.motions) {
    // What the path is, before what it is called: a folder or a missing file (a pattern the
    // shell matched to nothing arrives as written) is named as such, not by its name.
    if (const std::string why = motion_path_problem(file); !why.empty())
      throw InputError(file.string() + ": flipcheck league: --motions: " + why);
    const std::string base = file.filename().string();
    std::size_t best = job.scenes.size();
    for (std::size_t i = 0; i < job.scenes.size(); ++i) {
      const std::string prefix = job.scenes[i].name + "-";
      if (base.size() > prefix.size() && base.rfind(prefix, 0) == 0 &&
          (best == job.scenes.size() || prefix.size() > job.scenes[best].name.size() + 1))
        best = i;
    }
    if (best == job.scenes.size()) {
      std::string scenarios;
      for (const auto& s : job.scenes) scenarios += (scenarios.empty() ? "" : ", ") + s.name;
      throw InputError(file.string() +
                       ": flipcheck league: the file's name starts with no scenario's (expected "
                       "<scenario>-<motion>.csv; scenarios: " +
                       scenarios + ")");
    }
    std::string name = utf8_replaced(base.substr(job.scenes[best].name.size() + 1));
    if (const std::size_t dot = name.rfind('.'); dot != std::string::npos && dot > 0)
      name.erase(dot);
    // Two files of one name in one scenario would be one row: refused, naming both.
    for (std::size_t k = 0; k < motion_names[best].size(); ++k)
      if (motion_names[best][k] == name)
        throw InputError(file.string() + ": flipcheck league: its motion \"" + name +
                         "\" is also " + files[best][k].string() + "'s in scenario " +
                         job.scenes[best].name + ": rename one (a row per motion)");
    files[best].push_back(file);
    motion_names[best].push_back(name);
  }
  // Each scenario derived and its motion files read once, before anything is judged or
  // written: a bad one is its one line.
  std::vector<analysis::Scenario> scenarios;
  std::vector<std::vector<jobs::MotionFile>> read;
  for (std::size_t i = 0; i < job.scenes.size(); ++i) {
    scenarios.push_back(analysis::scenario_of(job.scenes[i]));
    read.push_back(jobs::read_motion_files(scenarios[i], files[i]));
  }
  // Up to date: the same scenarios (each its canonical form, input files and bookspin build:
  // a scene's own head), methods and motion files (each name and SHA-256), so that an
  // unchanged league is not judged again.
  JsonArray scenario_heads, method_labels;
  for (const scene::Scene& scene : job.scenes) {
    const cache::CachedOutputs of_scene{scene.name, {},          "flipcheck scenario",
                                        {},         job.out_dir, &scene};
    scenario_heads.push_back({sha256_text(cache::cached_head(of_scene))});
  }
  for (const analysis::Method& m : job.methods) method_labels.push_back({m.label});
  const cache::CachedOutputs cached{
      layout.html.filename().string(),
      layout.manifest,
      "flipcheck league",
      {{"scenarios", {std::move(scenario_heads)}}, {"methods", {std::move(method_labels)}}},
      job.out_dir,
      nullptr,
      /*all_or_nothing=*/true,
      job.motions};
  FlipcheckLeagueResult result;
  std::string csv;
  result.outcome = cache::make_cached(cached, job.freshness, [&] {
    std::vector<LeagueColumn> columns;
    CsvTable table;
    for (std::size_t i = 0; i < job.scenes.size(); ++i) {
      stop_if_asked(job.stop, "flipcheck league");
      const scene::Scene& scene = job.scenes[i];
      LeagueColumn col{
          scene.name, scene.title,
          jobs::judge_motions(scene.model, scene.steps_per_frame, scenarios[i], files[i], read[i],
                              motion_names[i], job.methods, job.stop)};
      CsvTable part = analysis::judgement_table(
          scenarios[i], analysis::scenario_sha256(scenarios[i]), col.judged);
      table.columns = part.columns;
      for (auto& row : part.rows) table.rows.push_back(std::move(row));
      columns.push_back(std::move(col));
    }
    csv = csv_text(table, "flipcheck league CSV");
    const std::string html = league_html(columns);
    output::prepare_output_dir(job.out_dir);
    output::StagedFiles staged;
    staged.text(layout.csv, csv);
    staged.text(layout.html, html);
    stop_if_asked(job.stop, "flipcheck league write");  // the last poll before they are in place
    staged.commit();
    return cache::Made{{layout.csv, layout.html}};
  });
  if (result.outcome == cache::Outcome::up_to_date)
    csv = read_text_file(layout.csv, "the league's CSV");
  // The counts from the table's CSV (made now or up to date): its motion and pass columns. A
  // record may span lines (a motion's name holding a line break, in double quotes): lines are
  // joined while a quote is open.
  std::map<std::string, bool> passes;
  std::istringstream lines(csv);
  std::string line;
  std::getline(lines, line);  // the header: scenario, motion, pass, …
  while (std::getline(lines, line)) {
    for (std::string more;
         std::count(line.begin(), line.end(), '"') % 2 != 0 && std::getline(lines, more);)
      line += "\n" + more;
    std::vector<std::string> cells;
    try {
      cells = csv_cells(line);
    } catch (const std::invalid_argument&) {
    }
    if (cells.size() < 3) continue;  // not a row as written (edited): not counted
    const auto [it, fresh] = passes.emplace(cells[1], true);
    it->second = it->second && cells[2] == "pass";
  }
  result.motions = static_cast<int>(passes.size());
  for (const auto& [name, pass] : passes) result.passed += pass ? 1 : 0;
  return result;
}

std::string flipcheck_kit_sha256(const std::vector<analysis::Scenario>& scenarios) {
  std::vector<std::string> lines;
  for (const analysis::Scenario& s : scenarios)
    lines.push_back(s.name + " " + analysis::scenario_sha256(s));
  std::sort(lines.begin(), lines.end());
  std::string text = "kit\n";
  for (const std::string& line : lines) text += line + "\n";
  return sha256_text(text + analysis::judge_rules());
}

}  // namespace bookspin::products
