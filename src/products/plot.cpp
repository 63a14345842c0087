#include "products/plot.hpp"

#include "cache/manifest_head.hpp"
#include "charts/plot_sheet.hpp"

namespace bookspin::products {

PlotLayout plot_layout(const std::filesystem::path& out_dir, const scene::Scene& scene) {
  return {out_dir / (scene.name + "-plot.png"), out_dir / scene.name / "plot-manifest.json"};
}

std::string plot_manifest_head(const PlotJob& job) {
  const JsonObject options{{"width", {std::int64_t{job.width}}},
                           {"height", {std::int64_t{job.height}}}};
  return cache::manifest_head("plot", options, job.scene);
}

Outcome make_plot(const PlotJob& job) {
  const PlotLayout layout = plot_layout(job.out_dir, job.scene);
  const CachedOutputs cached{job.scene.name + "-plot", layout.manifest, plot_manifest_head(job),
                             job.out_dir, &job.scene};
  return make_cached(cached, job.freshness,
                     [&]() -> std::optional<Made> {
                       charts::write_plot_sheet({job.scene, layout.png, job.width, job.height});
                       return Made{{layout.png}};
                     })
      .outcome;
}

}  // namespace bookspin::products
