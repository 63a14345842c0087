#include "products/accuracy.hpp"

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
  JsonArray dts, labels;
  for (const double dt : r.dts) dts.push_back({JsonNumber{dt, NumberStyle::digits17}});
  for (const auto& m : r.methods.empty() ? analysis::accuracy_methods() : r.methods)
    labels.push_back({charts::method_label(m)});
  const JsonObject options{{"flips", {JsonNumber{r.flips, NumberStyle::digits17}}},
                           {"dt", {std::move(dts)}},
                           {"methods", {std::move(labels)}}};
  return cache::manifest_head("accuracy", options, r.scene);
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
