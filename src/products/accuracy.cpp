#include "products/accuracy.hpp"

#include <cstdio>
#include <sstream>

#include "cache/make_cached.hpp"
#include "cache/manifest_head.hpp"
#include "charts/accuracy_plots.hpp"
#include "output/atomic_output.hpp"
#include "output/csv_writer.hpp"
#include "output/output_dir.hpp"
#include "output/png_writer.hpp"

namespace bookspin::products {

std::vector<std::filesystem::path> AccuracyLayout::outputs() const {
  return {csv, png, work_precision_png, energy_vs_dt_png, energy_png, energy_csv};
}

AccuracyLayout accuracy_layout(const std::filesystem::path& out_dir, const scene::Scene& scene) {
  const auto file = [&](const char* suffix) { return out_dir / (scene.name + suffix); };
  return {file("-accuracy.csv"),
          file("-accuracy.png"),
          file("-work-precision.png"),
          file("-energy-vs-dt.png"),
          file("-energy.png"),
          file("-energy.csv"),
          out_dir / scene.name / "accuracy-manifest.json"};
}

std::string accuracy_manifest_head(const AccuracyJob& job) {
  const jobs::AccuracyRequest& r = job.request;
  std::ostringstream options;
  char number[32];
  std::snprintf(number, sizeof number, "%.17g", r.flips);
  options << "    \"flips\": " << number << ",\n    \"dt\": [";
  for (std::size_t i = 0; i < r.dts.size(); ++i) {
    std::snprintf(number, sizeof number, "%.17g", r.dts[i]);
    options << (i ? ", " : "") << number;
  }
  options << "],\n    \"methods\": [";
  const auto methods = r.methods.empty() ? analysis::accuracy_methods() : r.methods;
  for (std::size_t i = 0; i < methods.size(); ++i)
    options << (i ? ", " : "") << '"' << charts::method_label(methods[i]) << '"';
  options << "]\n";
  return cache::manifest_head("accuracy", options.str(), r.scene);
}

cache::Outcome make_accuracy(const AccuracyJob& job) {
  const AccuracyLayout layout = accuracy_layout(job.out_dir, job.request.scene);
  const cache::CachedOutputs cached{job.request.scene.name + "-accuracy", layout.manifest,
                                    accuracy_manifest_head(job), job.out_dir, &job.request.scene};
  return cache::make_cached(cached, job.freshness, [&] {
    const jobs::AccuracyReport report = jobs::measure_accuracy(job.request);
    const output::CsvTable table = jobs::accuracy_csv(report);
    const output::CsvTable energy = jobs::energy_csv(report);
    const charts::AccuracyImages plots = charts::accuracy_images(
        report.rows, report.methods, report.flips, report.energy, jobs::kLongTimeFlips);
    output::prepare_output_dir(layout.csv.parent_path());
    output::write_text_file(layout.csv, output::csv_text(table, "accuracy CSV"));
    output::write_png(layout.png, plots.orientation_error_vs_dt);
    output::write_png(layout.work_precision_png, plots.work_precision);
    output::write_png(layout.energy_vs_dt_png, plots.energy_vs_dt);
    output::write_png(layout.energy_png, plots.long_time_energy);
    output::write_text_file(layout.energy_csv, output::csv_text(energy, "energy CSV"));
    return cache::Made{layout.outputs()};
  });
}

}  // namespace bookspin::products
