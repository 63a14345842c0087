#include "products/flipcheck.hpp"

#include "cache/make_cached.hpp"
#include "common/errors.hpp"
#include "jobs/motion_csv.hpp"
#include "output/atomic_output.hpp"
#include "output/output_dir.hpp"

namespace bookspin::products {

namespace {

JsonValue vector_json(const Eigen::Vector3d& v) { return {JsonArray{{v.x()}, {v.y()}, {v.z()}}}; }

}  // namespace

FlipcheckExportLayout flipcheck_export_layout(const std::filesystem::path& out_dir,
                                              const scene::Scene& scene) {
  return {out_dir / (scene.name + ".json"), out_dir / (scene.name + "-exact.csv"),
          out_dir / scene.name / "flipcheck-export-manifest.json"};
}

JsonValue scenario_json(const jobs::ExactMotion& m) {
  const analysis::Scenario& s = m.scenario;
  JsonObject units{{"time", {std::string("time unit (any: the motion scales with 1/time)")}},
                   {"length", {std::string("length unit")}},
                   {"mass", {std::string("mass unit")}},
                   {"angle", {std::string("radian")}},
                   {"angular_velocity", {std::string("rad per time unit")}},
                   {"moments", {std::string("mass * length^2")}}};
  JsonObject object{
      {"scenario", {s.name}},
      {"units", {std::move(units), true}},
      {"mass", {m.mass}},
      {"principal_moments", vector_json(s.body.moments)},
      {"principal_axes", {std::string("body x, y, z (the moments are about these axes)")}},
      {"q0", {JsonArray{{1.0}, {0.0}, {0.0}, {0.0}}}},
      {"q_convention", {std::string("w, x, y, z; body to world")}},
      {"omega0_body", vector_json(m.omega0_body)},
      {"omega0_world", vector_json(m.omega0_world)},
      {"dt", {JsonNumber{s.dt, NumberStyle::shortest}}},
      {"steps", {static_cast<std::int64_t>(s.steps)}},
      {"gravity", {std::string("none; no damping, no contacts")}},
      {"exact_motion", {s.name + "-exact.csv"}},
  };
  return {std::move(object), true};
}

CsvTable exact_motion_csv(const jobs::ExactMotion& m) {
  CsvTable table;
  table.columns = {"t",        "qw",       "qx",       "qy", "qz", "wx", "wy", "wz",
                   "wx_world", "wy_world", "wz_world", "Lx", "Ly", "Lz", "E"};
  table.rows.reserve(m.rows.size());
  for (const jobs::ExactMotionRow& r : m.rows) {
    table.rows.push_back(
        {shortest_cell(r.t), shortest_cell(r.q[0]), shortest_cell(r.q[1]), shortest_cell(r.q[2]),
         shortest_cell(r.q[3]), shortest_cell(r.omega_body.x()), shortest_cell(r.omega_body.y()),
         shortest_cell(r.omega_body.z()), shortest_cell(r.omega_world.x()),
         shortest_cell(r.omega_world.y()), shortest_cell(r.omega_world.z()), shortest_cell(r.L.x()),
         shortest_cell(r.L.y()), shortest_cell(r.L.z()), shortest_cell(r.E)});
  }
  return table;
}

cache::Outcome make_flipcheck_export(const FlipcheckExportJob& job) {
  const FlipcheckExportLayout layout = flipcheck_export_layout(job.out_dir, job.scene);
  const analysis::Scenario scenario = analysis::scenario_of(job.scene);
  const cache::CachedOutputs cached{job.scene.name + "-flipcheck",
                                    layout.manifest,
                                    "flipcheck export",
                                    {},
                                    job.out_dir,
                                    &job.scene};
  return cache::make_cached(cached, job.freshness, [&] {
    const jobs::ExactMotion motion = jobs::exact_motion(scenario, job.stop);
    const JsonValue start = scenario_json(motion);
    const CsvTable table = exact_motion_csv(motion);
    const std::string json = json_text(start, "flipcheck scenario", JsonLayout::indented) + "\n";
    const std::string csv = csv_text(table, "flipcheck exact motion CSV");
    output::prepare_output_dir(layout.json.parent_path());
    output::write_text_file(layout.json, json);
    output::write_text_file(layout.csv, csv);
    return cache::Made{{layout.json, layout.csv}};
  });
}

FlipcheckJudgeLayout flipcheck_judge_layout(const std::filesystem::path& out_dir,
                                            const scene::Scene& scene) {
  return {out_dir / (scene.name + "-judge.csv"),
          out_dir / scene.name / "flipcheck-judge-manifest.json"};
}

FlipcheckJudgeResult make_flipcheck_judge(const FlipcheckJudgeJob& job) {
  const FlipcheckJudgeLayout layout = flipcheck_judge_layout(job.out_dir, job.scene);
  const analysis::Scenario scenario = analysis::scenario_of(job.scene);
  FlipcheckJudgeResult result;
  for (const std::filesystem::path& file : job.motions) {
    const jobs::MotionFile motion = jobs::read_motion_csv(file, scenario.dt, scenario.steps);
    result.judged.push_back({file, analysis::judge_motion(scenario, motion.rows)});
  }
  const CsvTable table = analysis::judgement_table(scenario, result.judged);
  const cache::CachedOutputs cached{
      job.scene.name + "-judge", layout.manifest, "flipcheck judge", {}, job.out_dir, &job.scene,
      /*all_or_nothing=*/false,  job.motions};
  result.outcome = cache::make_cached(cached, job.freshness, [&] {
    output::prepare_output_dir(layout.csv.parent_path());
    output::write_text_file(layout.csv, csv_text(table, "flipcheck judge CSV"));
    return cache::Made{{layout.csv}};
  });
  return result;
}

}  // namespace bookspin::products
