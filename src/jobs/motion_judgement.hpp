#pragma once
// The conformance kit's judgement of one scenario as a value (`bookspin flipcheck judge` and
// `league`, docs/flipcheck.md): the scenario (from its scene or the scenario JSON `flipcheck
// export` wrote), the motion files read, bookspin's own methods run from its start, every
// motion judged (analysis::judge_motion) and the judgement CSV's table, which the products
// only write.
#include <filesystem>
#include <string>
#include <vector>

#include "analysis/accuracy.hpp"
#include "analysis/conformance.hpp"
#include "analysis/judgement.hpp"
#include "common/csv_writer.hpp"
#include "common/stop.hpp"
#include "jobs/motion_csv.hpp"
#include "scene/scene.hpp"

namespace bookspin::jobs {

/// One scenario judged.
struct Judgement {
  analysis::Scenario scenario;
  std::string scenario_sha256;                 ///< analysis::scenario_sha256
  std::vector<analysis::JudgedMotion> judged;  ///< the files, then the methods, in order
  CsvTable table;                              ///< analysis::judgement_table of `judged`
};

/// The motion files of `scenario` read, in order (read_motion_csv: a bad one is its one line).
std::vector<MotionFile> read_motion_files(const analysis::Scenario& scenario,
                                          const std::vector<std::filesystem::path>& files);

/// Every motion of one scenario judged: the files' motions `read` (read_motion_files, so that a
/// bad file fails before any run), then the `methods` (bookspin's own and the engines' modes),
/// each run from the scenario's start (analysis::simulated_motion) a row every `stride` steps
/// with `model`'s other settings; in the tables' order (files, then methods), each file named
/// `names[i]`. A motion too coarse to judge is an InputError naming its file, or "SCENARIO:
/// METHOD"; `stop` is asked between judgements ("flipcheck judge") and inside each
/// (Interrupted).
std::vector<analysis::JudgedMotion> judge_motions(
    const physics::ModelConfig& model, long long stride, const analysis::Scenario& scenario,
    const std::vector<std::filesystem::path>& files, const std::vector<MotionFile>& read,
    const std::vector<std::string>& names, const std::vector<analysis::Method>& methods,
    const StopPoll& stop);

/// One scenario judged as `flipcheck judge` judges it: the scenario made from `scene`
/// (analysis::scenario_of) or, where `scenario_file` is given, read from the scenario JSON
/// `flipcheck export` wrote (analysis::scenario_from_json; `scene` then gives only the methods'
/// model settings and row spacing), its SHA-256, every motion file read (before any method
/// runs), the motions judged (judge_motions) and the judgement CSV's table. Throws InputError
/// (a scenario, motion file or motion that cannot be judged: one line naming it), Interrupted.
Judgement judge_scenario(const scene::Scene& scene, const std::filesystem::path& scenario_file,
                         const std::vector<std::filesystem::path>& motions,
                         const std::vector<std::string>& names,
                         const std::vector<analysis::Method>& methods, const StopPoll& stop = {});

}  // namespace bookspin::jobs
