#pragma once
// The conformance kit's products (`bookspin flipcheck`, docs/flipcheck.md): a scenario
// exported for any engine (its start as JSON, the exact motion at every step as CSV) and the
// judgement of motions an engine wrote (a CSV, one row per motion), each with its manifest.
// Every path they write is named here; the measuring is jobs' (jobs/exact_motion.hpp,
// jobs/motion_csv.hpp) and analysis' (analysis/conformance.hpp).
#include <filesystem>
#include <string>
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

/// The scenario file's JSON (docs/flipcheck.md, "The scenario file"): units, mass, principal
/// moments, q0, ω0 in the body and the world frame, dt, steps.
JsonValue scenario_json(const jobs::ExactMotion& motion);

/// The exact motion's CSV: t,qw,qx,qy,qz,wx,wy,wz (ω body frame), then
/// wx_world,wy_world,wz_world,Lx,Ly,Lz (world frame) and E; shortest round-trip numbers.
CsvTable exact_motion_csv(const jobs::ExactMotion& motion);

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

/// Every path a judgement of one scenario into OUT writes.
struct FlipcheckJudgeLayout {
  std::filesystem::path csv;       ///< OUT/<scenario>-judge.csv: one row per motion file
  std::filesystem::path manifest;  ///< OUT/<scenario>/flipcheck-judge-manifest.json
};

FlipcheckJudgeLayout flipcheck_judge_layout(const std::filesystem::path& out_dir,
                                            const scene::Scene& scene);

struct FlipcheckJudgeJob {
  scene::Scene scene;                          ///< the scenario
  std::vector<std::filesystem::path> motions;  ///< motion CSVs (jobs/motion_csv.hpp)
  std::filesystem::path out_dir;
  cache::Freshness freshness;
};

struct FlipcheckJudgeResult {
  cache::Outcome outcome = cache::Outcome::made;
  std::vector<analysis::JudgedMotion> judged;  ///< in the order given (also when up to date)
};

/// (scenario, motions) => OUT/<scenario>-judge.csv + manifest.
/// Reads every motion file (jobs::read_motion_csv, before anything is written: a bad file is
/// an InputError naming its file, line and column) and judges it (analysis::judge_motion);
/// writes the CSV unless its manifest, whose head holds every motion file's SHA-256, says it
/// is up to date. Throws InputError, OutputError.
FlipcheckJudgeResult make_flipcheck_judge(const FlipcheckJudgeJob& job);

}  // namespace bookspin::products
