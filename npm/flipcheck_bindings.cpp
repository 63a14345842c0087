// embind bindings of the conformance kit for the npm package `flipcheck` (docs/flipcheck.md, "In
// your engine's tests"): `bookspin flipcheck judge` and `export` with the same code compiled
// unchanged, as the explorer page compiles it (web/judge_bindings.cpp): the motion CSV's parser
// (src/jobs/motion_csv.cpp), the judgement and its table (src/analysis/judgement.cpp), the scenario
// file (src/analysis/scenario_file.cpp) and the exact motion (src/jobs/exact_motion.cpp). This
// file only translates.
//
// A scenario comes as the text of the JSON `bookspin flipcheck export` writes (the package carries
// the seven), and the name its messages give it: a scenario file's own text, or a JavaScript
// object written as JSON by index.mjs. It is read by the command line's and Python's reader
// (analysis::scenario_from_json), so that every door takes and refuses the same scenarios in the
// same words: {scenario, mass, principal_moments, omega0_body, dt, steps, ...}. Its start is
// omega0_body, the jiggle already in it: with no jiggle, analysis::start_omega gives it back to
// the last bit for every carried scenario (I ω / I = ω there), so the judgement is the command
// line's to the last digit (tests/npm/npm_package_test.py).
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <array>
#include <string>
#include <vector>

#include "analysis/judgement.hpp"
#include "analysis/scenario_file.hpp"
#include "common/errors.hpp"
#include "common/text_lines.hpp"
#include "common/version.hpp"
#include "jobs/exact_motion.hpp"
#include "jobs/motion_csv.hpp"

// The page's error mapping and judgement, shared (web/).
#include "../web/guarded.hpp"
#include "../web/judgement_value.hpp"

namespace {

using bookspin::InputError;
using bookspin::analysis::Scenario;
using bookspin::web::guarded;
using emscripten::val;

/// The scenario of a scenario JSON's `text`, `file` naming it in messages: read by the one
/// reader of the command line and Python (analysis::scenario_from_json), so that every door
/// refuses a scenario in the same words (index.mjs hands it a file's own text, or an object
/// written as JSON).
Scenario scenario_of(const std::string& text, const std::string& file) {
  return bookspin::analysis::scenario_from_json(text, file);
}

/// A judged motion as JavaScript: the page's (web/judgement_value.hpp: {columns, cells, line,
/// failures}), with csv (the judgement CSV's header and row, as the command line writes them) and
/// pass. `sha256` is the scenario's: of scenario_file()'s text, hashed by index.mjs (node:crypto).
val judged(const Scenario& s, const std::string& sha256, const bookspin::jobs::MotionFile& motion,
           const std::string& name) {
  const bookspin::analysis::JudgementRow row =
      bookspin::analysis::judgement_row(s, sha256, motion.rows, name);
  val out = bookspin::web::judgement_value(row);
  out.set("csv", row.csv);
  out.set("pass", row.pass);
  return out;
}

/// The bytes of `text`: a string's UTF-8, or a Uint8Array's (a file as node read it, copied
/// into the module's memory at once rather than a character at a time).
std::string bytes_of(const val& text) {
  if (text.isString()) return text.as<std::string>();
  std::string bytes(text["length"].as<std::size_t>(), '\0');
  val(emscripten::typed_memory_view(bytes.size(), reinterpret_cast<unsigned char*>(bytes.data())))
      .call<void>("set", text);  // the view is of the module's memory: set() writes there
  return bytes;
}

/// `bookspin flipcheck judge` of the motion CSV `text` (a string, or the file's bytes as a
/// Uint8Array): `file` names it in messages (the path as given), `name` in the judgement (the
/// file's name).
val judge_csv(const std::string& scenario, const std::string& scenario_file,
              const std::string& sha256, const val& text, const std::string& file,
              const std::string& name) {
  return guarded([&] {
    const Scenario s = scenario_of(scenario, scenario_file);
    return judged(s, sha256, bookspin::jobs::parse_motion_csv(bytes_of(text), file, s.dt, s.steps),
                  name);
  });
}

/// The same of a motion given as flat arrays: t (N), q (4N: w, x, y, z), ω world (3N);
/// `what` names them in messages, `name` is the judgement's motion.
val judge_arrays(const std::string& scenario, const std::string& scenario_file,
                 const std::string& sha256, const val& t_js, const val& q_js, const val& w_js,
                 const std::string& what, const std::string& name) {
  return guarded([&] {
    const Scenario s = scenario_of(scenario, scenario_file);
    const std::vector<double> t = emscripten::convertJSArrayToNumberVector<double>(t_js);
    const std::vector<double> q = emscripten::convertJSArrayToNumberVector<double>(q_js);
    const std::vector<double> w = emscripten::convertJSArrayToNumberVector<double>(w_js);
    const std::size_t n = t.size();
    if (q.size() != 4 * n)
      throw InputError(what + ": q: expected " + std::to_string(4 * n) + " numbers (N×4, N = " +
                       std::to_string(n) + " rows of t), got " + std::to_string(q.size()));
    if (w.size() != 3 * n)
      throw InputError(what + ": omegaWorld: expected " + std::to_string(3 * n) +
                       " numbers (N×3, N = " + std::to_string(n) + " rows of t), got " +
                       std::to_string(w.size()));
    std::vector<std::array<double, 8>> rows(n);
    for (std::size_t i = 0; i < n; ++i)
      rows[i] = {t[i],         q[4 * i], q[4 * i + 1], q[4 * i + 2],
                 q[4 * i + 3], w[3 * i], w[3 * i + 1], w[3 * i + 2]};
    return judged(s, sha256,
                  bookspin::jobs::motion_from_rows(rows, bookspin::jobs::OmegaFrame::world, what,
                                                   s.dt, s.steps),
                  name);
  });
}

val float64_array(const std::vector<double>& values) {
  const val view(emscripten::typed_memory_view(values.size(), values.data()));
  return val::global("Float64Array").new_(view);  // a copy, out of the module's memory
}

/// The exact motion at every step n = 0 … steps: {t (N), q (4N), omegaBody, omegaWorld, L (3N),
/// E (N)}, the rows of `flipcheck export`'s CSV.
val exact_motion(const std::string& scenario, const std::string& scenario_file) {
  return guarded([&] {
    const bookspin::jobs::ExactMotion m =
        bookspin::jobs::exact_motion(scenario_of(scenario, scenario_file));
    const std::size_t n = m.rows.size();
    std::vector<double> t(n), q(4 * n), wb(3 * n), ww(3 * n), L(3 * n), E(n);
    const bookspin::jobs::ExactRowArrays into{t.data(),  q.data(), wb.data(),
                                              ww.data(), L.data(), E.data()};
    for (std::size_t i = 0; i < n; ++i) into.put(i, m.rows[i]);
    val out = val::object();
    out.set("t", float64_array(t));
    out.set("q", float64_array(q));
    out.set("omegaBody", float64_array(wb));
    out.set("omegaWorld", float64_array(ww));
    out.set("L", float64_array(L));
    out.set("E", float64_array(E));
    return out;
  });
}

/// The bytes of the two files `bookspin flipcheck export` writes: {json, csv}.
val export_files(const std::string& scenario, const std::string& scenario_file) {
  return guarded([&] {
    const bookspin::jobs::ExportFiles files = bookspin::jobs::export_files(
        bookspin::jobs::exact_motion(scenario_of(scenario, scenario_file)));
    val out = val::object();
    out.set("json", files.json);
    out.set("csv", files.csv);
    return out;
  });
}

/// The bytes of OUT/<scenario>.json as `bookspin flipcheck export` writes them, without the exact
/// motion: what a judgement's scenario_sha256 is of (docs/flipcheck.md, "Versions").
val scenario_file(const std::string& scenario, const std::string& file) {
  return guarded(
      [&] { return val(bookspin::analysis::scenario_file(scenario_of(scenario, file))); });
}

std::string version() { return bookspin::version(); }

/// A scenario's name quoted as every door quotes one: whole up to 4096 bytes, else cut as a
/// cell (common/text_lines.hpp, quoted_name).
std::string quoted_name(const std::string& text) { return bookspin::quoted_name(text); }

/// The same unquoted (a message's prefix).
std::string cut_name(const std::string& text) { return bookspin::cut_name(text); }

}  // namespace

EMSCRIPTEN_BINDINGS(flipcheck_npm) {
  emscripten::function("scenarioFile", &scenario_file);
  emscripten::function("version", &version);
  emscripten::function("quotedName", &quoted_name);
  emscripten::function("cutName", &cut_name);
  emscripten::function("judgeCsv", &judge_csv);
  emscripten::function("judgeArrays", &judge_arrays);
  emscripten::function("exactMotion", &exact_motion);
  emscripten::function("exportFiles", &export_files);
}
