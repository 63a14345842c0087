// embind bindings of the conformance kit's judgement for the explorer page's "Judge a motion"
// panel (docs/explorer.md, docs/flipcheck.md): `bookspin flipcheck judge` and `export` with the
// same code compiled unchanged: the motion CSV's parser (src/jobs/motion_csv.cpp), the judgement
// and its table (src/analysis/judgement.cpp), the scenario file (src/analysis/scenario_file.cpp)
// and the exact motion (src/jobs/exact_motion.cpp). This file only translates between them and
// JavaScript.
//
// A scenario comes from the page's data of one scene (src/products/explorer.hpp), as the page
// hands it in: {name, book: {size, mass}, body (optional: the body whole), w (ω0, body frame,
// rad per time unit), jiggle, seed, dt (time units), steps}.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "analysis/judgement.hpp"
#include "analysis/scenario_file.hpp"
#include "body_spec.hpp"
#include "common/errors.hpp"
#include "common/version.hpp"
#include "guarded.hpp"
#include "jobs/exact_motion.hpp"
#include "jobs/motion_csv.hpp"
#include "judgement_value.hpp"
#include "physics/exact_solution.hpp"

namespace {

using bookspin::InputError;
using bookspin::analysis::Scenario;
using bookspin::web::guarded;
using emscripten::val;

/// The scenario of `spec` (see the head of this file). Throws InputError where it is none
/// (as analysis::scenario_of: a body at rest; a run of no step).
Scenario scenario_of(const val& spec) {
  Scenario s;
  s.name = spec["name"].as<std::string>();
  if (spec["body"].isUndefined() || spec["body"].isNull()) {
    const val book = spec["book"];
    const std::vector<double> size = emscripten::vecFromJSArray<double>(book["size"]);
    if (size.size() != 3) throw std::invalid_argument("book.size: expected 3 numbers");
    s.body =
        bookspin::web::make_body("book", book["mass"].as<double>(), 1.0, size[0], size[1], size[2]);
  } else {
    s.body = bookspin::web::body_of(spec["body"]);
  }
  const std::vector<double> w = emscripten::vecFromJSArray<double>(spec["w"]);
  if (w.size() != 3) throw std::invalid_argument("w: expected 3 numbers");
  s.initial.omega0_body = {w[0], w[1], w[2]};
  s.initial.jiggle = spec["jiggle"].as<double>();
  s.initial.seed = static_cast<std::uint64_t>(spec["seed"].as<double>());
  s.dt = spec["dt"].as<double>();
  const double steps = spec["steps"].as<double>();
  if (!(std::floor(steps) == steps && steps >= 1.0 &&
        steps <= static_cast<double>(bookspin::analysis::ScenarioLimits::max_steps)))
    throw InputError(s.name + ": steps: must be a whole number from 1 to 10^7");
  s.steps = static_cast<long long>(steps);
  // Every field as every door takes it (docs/flipcheck.md, "What a scenario may be").
  bookspin::analysis::check_scenario(s);
  return s;
}

/// The motion CSV `text` (named `file`, as `judge` names it: the file's name) judged against
/// the exact motion of the scenario `spec`, whose scenario_sha256 is `sha256` (of
/// scenario_file()'s text, hashed by the page, web/src/judge.js): {columns, cells (the judgement
/// CSV's row, as text: analysis::judgement_table), line (analysis::verdict_line), failures}, or
/// {error}.
val judge_motion(const val& spec, const std::string& sha256, const std::string& text,
                 const std::string& file) {
  return guarded([&] {
    const Scenario s = scenario_of(spec);
    const bookspin::jobs::MotionFile motion =
        bookspin::jobs::parse_motion_csv(text, file, s.dt, s.steps);
    return bookspin::web::judgement_value(
        bookspin::analysis::judgement_row(s, sha256, motion.rows, file));
  });
}

/// The motion of `text` and the exact one at its rows, for replaying them side by side:
/// {t (time units), q (4×N: w, x, y, z of each row, body → world, normalized), qExact (4×N,
/// the exact motion's at the same t)}, or {error}.
val motion_poses(const val& spec, const std::string& text, const std::string& file) {
  return guarded([&] {
    const Scenario s = scenario_of(spec);
    const bookspin::jobs::MotionFile motion =
        bookspin::jobs::parse_motion_csv(text, file, s.dt, s.steps);
    const bookspin::physics::ExactRotation exact(s.body.moments,
                                                 bookspin::analysis::start_omega(s));
    std::vector<double> t, q, q_exact;
    for (const bookspin::analysis::MotionSample& row : motion.rows) {
      const double time = static_cast<double>(row.step) * s.dt;
      t.push_back(time);
      const Eigen::Quaterniond a = row.q.normalized();
      const Eigen::Quaterniond b(exact.orientation(time));
      q.insert(q.end(), {a.w(), a.x(), a.y(), a.z()});
      q_exact.insert(q_exact.end(), {b.w(), b.x(), b.y(), b.z()});
    }
    val out = val::object();
    out.set("t", val::array(t));
    out.set("q", val::array(q));
    out.set("qExact", val::array(q_exact));
    return out;
  });
}

/// The files `bookspin flipcheck export` writes for the scenario `spec`, byte for byte:
/// {json: OUT/<scenario>.json, csv: OUT/<scenario>-exact.csv}, or {error}.
val export_files(const val& spec) {
  return guarded([&] {
    const bookspin::jobs::ExactMotion m = bookspin::jobs::exact_motion(scenario_of(spec));
    val out = val::object();
    const bookspin::jobs::ExportFiles files = bookspin::jobs::export_files(m);
    out.set("json", files.json);
    out.set("csv", files.csv);
    return out;
  });
}

/// The bytes of OUT/<scenario>.json as `bookspin flipcheck export` writes them (without the
/// exact motion), or {error}: what a judgement's scenario_sha256 is of.
val scenario_file(const val& spec) {
  return guarded([&] { return val(bookspin::analysis::scenario_file(scenario_of(spec))); });
}

std::string version() { return bookspin::version(); }

/// The judge's rules as `flipcheck` hashes them (analysis::judge_rules): a line "name value"
/// per limit, then the columns; the panel shows a measure's limit beside it.
std::string judge_rules() { return bookspin::analysis::judge_rules(); }

}  // namespace

EMSCRIPTEN_BINDINGS(bookspin_judge) {
  emscripten::function("flipcheckScenarioFile", &scenario_file);
  emscripten::function("version", &version);
  emscripten::function("judgeRules", &judge_rules);
  emscripten::function("judgeMotion", &judge_motion);
  emscripten::function("motionPoses", &motion_poses);
  emscripten::function("flipcheckExport", &export_files);
}
