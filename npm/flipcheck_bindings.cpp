// embind bindings of the conformance kit for the npm package `flipcheck` (docs/flipcheck.md, "In
// your engine's tests"): `bookspin flipcheck judge` and `export` with the same code compiled
// unchanged, as the explorer page compiles it (web/judge_bindings.cpp): the motion CSV's parser
// (src/jobs/motion_csv.cpp), the judgement and its table (src/analysis/judgement.cpp), the scenario
// file (src/analysis/scenario_file.cpp) and the exact motion (src/jobs/exact_motion.cpp). This
// file only translates.
//
// A scenario comes as the JSON `bookspin flipcheck export` writes (the package carries the seven),
// parsed: {scenario, mass, principal_moments, omega0_body, dt, steps, ...}. Its start is
// omega0_body, the jiggle already in it: with no jiggle, analysis::start_omega gives it back to
// the last bit for every carried scenario (I ω / I = ω there), so the judgement is the command
// line's to the last digit (tests/npm/npm_package_test.py).
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "analysis/judgement.hpp"
#include "analysis/scenario_file.hpp"
#include "common/csv_writer.hpp"
#include "common/errors.hpp"
#include "common/version.hpp"
#include "jobs/exact_motion.hpp"
#include "jobs/motion_csv.hpp"

namespace {

using bookspin::InputError;
using bookspin::analysis::Scenario;
using emscripten::val;

/// f()'s answer; {error: the one line} for an InputError (what the command line prints after
/// "bookspin: error: "), {error: "internal error: …"} for any other exception.
template <typename F>
val guarded(F&& f) {
  try {
    return f();
  } catch (const InputError& e) {
    val out = val::object();
    out.set("error", std::string(e.what()));
    return out;
  } catch (const std::exception& e) {
    val out = val::object();
    out.set("error", std::string("internal error: ") + e.what());
    return out;
  }
}

/// JavaScript's typeof of `v`, "null" and "array" told apart: a field's type in a message.
std::string type_of(const val& v) {
  if (v.isNull()) return "null";
  if (val::global("Array").call<bool>("isArray", v)) return "an array";
  return "a " + v.typeOf().as<std::string>();
}

bool missing(const val& v) { return v.isUndefined() || v.isNull(); }

/// json[key], a number, or InputError "WHERE: KEY: …" naming what is wrong with it.
double number_field(const val& json, const char* key, const std::string& where) {
  const val v = json[key];
  if (v.isUndefined())
    throw InputError(where + ": " + key +
                     ": missing (a scenario JSON as flipcheck export writes it)");
  if (!v.isNumber())
    throw InputError(where + ": " + key + ": expected a number, got " + type_of(v));
  return v.as<double>();
}

/// json[key], an array of `n` numbers, or InputError naming what is wrong with it.
std::vector<double> numbers_field(const val& json, const char* key, std::size_t n,
                                  const std::string& where) {
  const val v = json[key];
  const std::string expected = "expected an array of " + std::to_string(n) + " numbers";
  if (v.isUndefined())
    throw InputError(where + ": " + key +
                     ": missing (a scenario JSON as flipcheck export writes it)");
  if (!val::global("Array").call<bool>("isArray", v))
    throw InputError(where + ": " + key + ": " + expected + ", got " + type_of(v));
  const std::size_t length = v["length"].as<std::size_t>();
  if (length != n)
    throw InputError(where + ": " + key + ": " + expected + ", got " + std::to_string(length));
  std::vector<double> out;
  for (std::size_t i = 0; i < n; ++i) {
    const val item = v[i];
    if (!item.isNumber())
      throw InputError(where + ": " + key + "[" + std::to_string(i) + "]: expected a number, got " +
                       type_of(item));
    out.push_back(item.as<double>());
  }
  return out;
}

/// A number as a message gives it: its shortest "%.17g"-safe digits, "%.15g" where it reads back.
std::string plain(double value) {
  char number[32];
  std::snprintf(number, sizeof number, "%.15g", value);
  if (std::strtod(number, nullptr) != value) std::snprintf(number, sizeof number, "%.17g", value);
  return number;
}

std::string vector_text(const std::vector<double>& v) {
  std::string text = "(";
  for (std::size_t i = 0; i < v.size(); ++i) text += (i ? ", " : "") + plain(v[i]);
  return text + ")";
}

/// The scenario of an exported scenario JSON (see the head of this file). Every field is taken
/// as written or refused by name (InputError): `scenario` (a name, analysis::
/// scenario_name_problem), `mass`, `principal_moments`, `omega0_body` (or `omega0_world` alone),
/// `dt` and `steps` (a whole number) as analysis::check_scenario allows them; `q0`, where given,
/// the identity (either sign), the start every scenario has; `omega0_world`, where given beside
/// omega0_body, equal to it (at the identity they are one vector).
Scenario scenario_of(const val& json) {
  if (missing(json) || json.typeOf().as<std::string>() != "object" ||
      val::global("Array").call<bool>("isArray", json))
    throw InputError("flipcheck: a scenario is a name or a scenario JSON object, got " +
                     type_of(json));
  Scenario s;
  const val name = json["scenario"];
  if (name.isUndefined())
    throw InputError(
        "scenario JSON: scenario: missing (the scenario's name, as flipcheck export "
        "writes it)");
  if (!name.isString())
    throw InputError("scenario JSON: scenario: expected a name (a string), got " + type_of(name));
  s.name = name.as<std::string>();
  if (const std::string why = bookspin::analysis::scenario_name_problem(s.name); !why.empty())
    bookspin::analysis::check_scenario(s);  // refuses the name, printable, in one line
  const std::vector<double> moments = numbers_field(json, "principal_moments", 3, s.name);
  s.body.moments = {moments[0], moments[1], moments[2]};
  s.body.cage.mass = number_field(json, "mass", s.name);
  const bool has_body = !json["omega0_body"].isUndefined();
  const bool has_world = !json["omega0_world"].isUndefined();
  const std::vector<double> body =
      numbers_field(json, has_body || !has_world ? "omega0_body" : "omega0_world", 3, s.name);
  if (has_body && has_world) {
    const std::vector<double> world = numbers_field(json, "omega0_world", 3, s.name);
    for (int i = 0; i < 3; ++i)
      if (!(std::abs(world[i] - body[i]) <= 1e-12 * std::max(std::abs(body[i]), 1e-300)))
        throw InputError(s.name + ": omega0_world: " + vector_text(world) + " is not omega0_body " +
                         vector_text(body) +
                         ": at q0 = identity they are one vector (give them equal, or one)");
  }
  if (!json["q0"].isUndefined()) {
    const std::vector<double> q0 = numbers_field(json, "q0", 4, s.name);
    if (!(q0[0] != 0.0 && std::isfinite(q0[0]) && q0[1] == 0.0 && q0[2] == 0.0 && q0[3] == 0.0))
      throw InputError(s.name + ": q0: " + vector_text(q0) +
                       ": every scenario starts at the identity, q0 = (1, 0, 0, 0) (w, x, y, z)");
  }
  s.initial.omega0_body = {body[0], body[1], body[2]};
  s.initial.jiggle = 0.0;
  s.dt = number_field(json, "dt", s.name);
  const double steps = number_field(json, "steps", s.name);
  if (!(std::floor(steps) == steps))
    throw InputError(s.name + ": steps: " + plain(steps) + " is not a whole number of steps");
  if (!(steps >= 1.0 &&
        steps <= static_cast<double>(bookspin::analysis::ScenarioLimits::max_steps)))
    throw InputError(s.name + ": steps: " + plain(steps) +
                     " must be from 1 to 10^7 (the exact motion is exported at every step)");
  s.steps = static_cast<long long>(steps);
  bookspin::analysis::check_scenario(s);
  return s;
}

/// A judged motion as JavaScript: {columns, cells (the judgement CSV's row as the command line
/// writes it, as text), csv (its header and that row, as the command line writes them), line
/// (analysis::verdict_line), failures (one phrase each), pass}.
/// `sha256` is the scenario's: of scenario_file()'s text, hashed by index.mjs (node:crypto).
val judged(const Scenario& s, const std::string& sha256, const bookspin::jobs::MotionFile& motion,
           const std::string& name) {
  const bookspin::analysis::Conformance c = bookspin::analysis::judge_motion(s, motion.rows);
  const bookspin::CsvTable table =
      bookspin::analysis::judgement_table(s, sha256, {{name, name, c}});
  val columns = val::array(), cells = val::array(), failures = val::array();
  for (const std::string& column : table.columns) columns.call<void>("push", column);
  const std::string csv = bookspin::csv_text(table, "flipcheck judge CSV");
  const std::size_t row = csv.find('\n') + 1;
  for (const std::string& cell : bookspin::csv_cells(csv.substr(row, csv.size() - row - 1)))
    cells.call<void>("push", cell);
  for (const std::string& f : c.failures) failures.call<void>("push", f);
  val out = val::object();
  out.set("columns", columns);
  out.set("cells", cells);
  out.set("csv", csv);
  out.set("line", bookspin::analysis::verdict_line(c));
  out.set("failures", failures);
  out.set("pass", c.pass());
  return out;
}

/// `bookspin flipcheck judge` of the motion CSV `text`: `file` names it in messages (the path as
/// given), `name` in the judgement (the file's name).
val judge_csv(const val& json, const std::string& sha256, const std::string& text,
              const std::string& file, const std::string& name) {
  return guarded([&] {
    const Scenario s = scenario_of(json);
    return judged(s, sha256, bookspin::jobs::parse_motion_csv(text, file, s.dt, s.steps), name);
  });
}

/// The same of a motion given as flat arrays: t (N), q (4N: w, x, y, z), ω world (3N);
/// `what` names them in messages, `name` is the judgement's motion.
val judge_arrays(const val& json, const std::string& sha256, const val& t_js, const val& q_js,
                 const val& w_js, const std::string& what, const std::string& name) {
  return guarded([&] {
    const Scenario s = scenario_of(json);
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
val exact_motion(const val& json) {
  return guarded([&] {
    const bookspin::jobs::ExactMotion m = bookspin::jobs::exact_motion(scenario_of(json));
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
val export_files(const val& json) {
  return guarded([&] {
    const bookspin::jobs::ExportFiles files =
        bookspin::jobs::export_files(bookspin::jobs::exact_motion(scenario_of(json)));
    val out = val::object();
    out.set("json", files.json);
    out.set("csv", files.csv);
    return out;
  });
}

/// The bytes of OUT/<scenario>.json as `bookspin flipcheck export` writes them, without the exact
/// motion: what a judgement's scenario_sha256 is of (docs/flipcheck.md, "Versions").
val scenario_file(const val& json) {
  return guarded([&] { return val(bookspin::analysis::scenario_file(scenario_of(json))); });
}

std::string version() { return bookspin::version(); }

}  // namespace

EMSCRIPTEN_BINDINGS(flipcheck_npm) {
  emscripten::function("scenarioFile", &scenario_file);
  emscripten::function("version", &version);
  emscripten::function("judgeCsv", &judge_csv);
  emscripten::function("judgeArrays", &judge_arrays);
  emscripten::function("exactMotion", &exact_motion);
  emscripten::function("exportFiles", &export_files);
}
