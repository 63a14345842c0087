#include "products/accuracy.hpp"

#include "cache/make_cached.hpp"
#include "charts/accuracy_plots.hpp"
#include "common/csv_writer.hpp"
#include "output/atomic_output.hpp"
#include "output/output_dir.hpp"
#include "output/png_writer.hpp"
#include "output/staged_files.hpp"

namespace bookspin::products {

std::vector<std::filesystem::path> AccuracyLayout::outputs() const {
  return {csv, png, work_precision_png, energy_vs_dt_png, turnovers_png, energy_png, energy_csv};
}

AccuracyLayout accuracy_layout(const std::filesystem::path& out_dir, const scene::Scene& scene) {
  const auto file = [&](const char* suffix) { return out_dir / (scene.name + suffix); };
  return {file("-accuracy.csv"),       file("-accuracy.png"),
          file("-work-precision.png"), file("-energy-vs-dt.png"),
          file("-turnovers.png"),      file("-energy.png"),
          file("-energy.csv"),         out_dir / scene.name / "accuracy-manifest.json"};
}

namespace {

cache::CachedOutputs accuracy_cached(const AccuracyJob& job, const AccuracyLayout& layout) {
  const jobs::AccuracyRequest& r = job.request;
  JsonArray dts, labels;
  for (const double dt : r.dts) dts.push_back({JsonNumber{dt, NumberStyle::digits17}});
  for (const auto& m : r.methods.empty() ? analysis::accuracy_methods() : r.methods)
    labels.push_back({m.label});
  const JsonObject options{{"flips", {JsonNumber{r.flips, NumberStyle::digits17}}},
                           {"dt", {std::move(dts)}},
                           {"methods", {std::move(labels)}}};
  return {r.scene.name + "-accuracy", layout.manifest, "accuracy", options, job.out_dir, &r.scene,
          /*all_or_nothing=*/true};
}

}  // namespace

std::string accuracy_manifest_head(const AccuracyJob& job) {
  return cache::cached_head(accuracy_cached(job, accuracy_layout(job.out_dir, job.request.scene)));
}

cache::Outcome make_accuracy(const AccuracyJob& job) {
  const AccuracyLayout layout = accuracy_layout(job.out_dir, job.request.scene);
  const cache::CachedOutputs cached{accuracy_cached(job, layout)};
  return cache::make_cached(cached, job.freshness, [&] {
    const jobs::AccuracyReport report = jobs::measure_accuracy(job.request);
    const std::string table = csv_text(report.table, "accuracy CSV");
    const std::string energy = csv_text(report.energy_table, "energy CSV");
    const charts::AccuracyImages plots =
        charts::accuracy_images(report.rows, report.methods, report.flips, report.spin_rate,
                                report.energy, jobs::kLongTimeFlips);
    output::prepare_output_dir(layout.csv.parent_path());
    output::StagedFiles files;  // all seven in place together, or none
    files.png(layout.png, plots.orientation_error_vs_dt);
    files.png(layout.work_precision_png, plots.work_precision);
    files.png(layout.energy_vs_dt_png, plots.energy_vs_dt);
    files.png(layout.turnovers_png, plots.turnovers_vs_dt);
    files.png(layout.energy_png, plots.long_time_energy);
    files.text(layout.csv, table);
    files.text(layout.energy_csv, energy);
    files.commit();
    return cache::Made{layout.outputs()};
  });
}

}  // namespace bookspin::products
