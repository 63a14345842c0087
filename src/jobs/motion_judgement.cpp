#include "jobs/motion_judgement.hpp"

#include "analysis/scenario_file.hpp"
#include "common/errors.hpp"
#include "common/file_name.hpp"
#include "common/text_file.hpp"

namespace bookspin::jobs {

std::vector<MotionFile> read_motion_files(const analysis::Scenario& scenario,
                                          const std::vector<std::filesystem::path>& files) {
  std::vector<MotionFile> read;
  for (const std::filesystem::path& file : files)
    read.push_back(read_motion_csv(file, scenario.dt, scenario.steps));
  return read;
}

std::vector<analysis::JudgedMotion> judge_motions(
    const physics::ModelConfig& model, long long stride, const analysis::Scenario& scenario,
    const std::vector<std::filesystem::path>& files, const std::vector<MotionFile>& read,
    const std::vector<std::string>& names, const std::vector<analysis::Method>& methods,
    const StopPoll& stop) {
  // The methods run first, then every motion judged in the tables' order (files, methods).
  std::vector<std::vector<analysis::MotionSample>> runs;
  for (const analysis::Method& m : methods) {
    runs.push_back(analysis::simulated_motion(scenario, m, model, stride, stop));
    if (runs.back().empty()) throw InternalError("flipcheck: " + m.label + " gave no finite start");
  }
  // A judgement is tens of milliseconds (the exact motion at every row): asked between them,
  // a stop is answered within a second (docs/outputs.md, "Signals").
  // A motion too coarse to judge is refused naming its file (or method).
  const auto judge_one = [&](const std::string& what,
                             const std::vector<analysis::MotionSample>& rows) {
    stop_if_asked(stop, "flipcheck judge");
    try {
      return analysis::judge_motion(scenario, rows, {}, stop);
    } catch (const InputError& e) {
      throw InputError(what + ": " + e.what());
    }
  };
  std::vector<analysis::JudgedMotion> judged;
  for (std::size_t i = 0; i < files.size(); ++i)
    judged.push_back({files[i], names[i], judge_one(files[i].string(), read[i].rows)});
  for (std::size_t i = 0; i < methods.size(); ++i)
    judged.push_back(
        {{}, methods[i].label, judge_one(scenario.name + ": " + methods[i].label, runs[i])});
  return judged;
}

Judgement judge_scenario(const scene::Scene& scene, const std::filesystem::path& scenario_file,
                         const std::vector<std::filesystem::path>& motions,
                         const std::vector<std::string>& names,
                         const std::vector<analysis::Method>& methods, const StopPoll& stop) {
  const analysis::Scenario scenario =
      scenario_file.empty()
          ? analysis::scenario_of(scene)
          : analysis::scenario_from_json(read_text_file(scenario_file, "the scenario file"),
                                         scenario_file.string());
  // Each motion's name as valid UTF-8 (a name in bytes that are no UTF-8, "caf\xe9.csv", as
  // "caf\uFFFD.csv": common/file_name.hpp's utf8_replaced, the rule npx's names follow too), so
  // that the judgement CSV, its lines and the league are UTF-8.
  std::vector<std::string> shown;
  for (const std::string& name : names) shown.push_back(utf8_replaced(name));
  const std::string sha256 = analysis::scenario_sha256(scenario);
  const std::vector<MotionFile> read = read_motion_files(scenario, motions);
  std::vector<analysis::JudgedMotion> judged = judge_motions(
      scene.model, scene.steps_per_frame, scenario, motions, read, shown, methods, stop);
  CsvTable table = analysis::judgement_table(scenario, sha256, judged);
  return {scenario, sha256, std::move(judged), std::move(table)};
}

}  // namespace bookspin::jobs
