#include "products/accuracy.hpp"

#include <cstdio>
#include <sstream>

#include "cache/manifest_head.hpp"
#include "charts/accuracy_plots.hpp"

namespace bookspin::products {

std::vector<std::filesystem::path> AccuracyLayout::outputs() const {
  return {report.csv,        report.png,       report.work_precision_png, report.energy_vs_dt_png,
          report.energy_png, report.energy_csv};
}

AccuracyLayout accuracy_layout(const std::filesystem::path& out_dir, const scene::Scene& scene) {
  const auto file = [&](const char* suffix) { return out_dir / (scene.name + suffix); };
  return {{file("-accuracy.csv"), file("-accuracy.png"), file("-work-precision.png"),
           file("-energy-vs-dt.png"), file("-energy.png"), file("-energy.csv")},
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

Outcome make_accuracy(const AccuracyJob& job) {
  const AccuracyLayout layout = accuracy_layout(job.out_dir, job.request.scene);
  jobs::AccuracyRequest request = job.request;
  request.paths = layout.report;
  const CachedOutputs cached{request.scene.name + "-accuracy", layout.manifest,
                             accuracy_manifest_head(job), job.out_dir, &request.scene};
  const CachedOutcome done = make_cached(cached, job.freshness, [&]() -> std::optional<Made> {
    return Made{jobs::run_accuracy(request)};
  });
  if (done.signal != 0) throw Interrupted(done.signal);  // the earlier report and manifest stay
  return done.outcome;
}

}  // namespace bookspin::products
