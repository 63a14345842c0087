#include "products/plot.hpp"

#include <sstream>

#include "cache/manifest_head.hpp"
#include "charts/plot_sheet.hpp"

namespace bookspin::products {

PlotLayout plot_layout(const std::filesystem::path& out_dir, const scene::Scene& scene) {
  return {out_dir / (scene.name + "-plot.png"), out_dir / scene.name / "plot-manifest.json"};
}

std::string plot_manifest_head(const PlotJob& job) {
  std::ostringstream options;
  options << "    \"width\": " << job.width << ",\n"
          << "    \"height\": " << job.height << "\n";
  return cache::manifest_head("plot", options.str(), job.scene);
}

Outcome make_plot(const PlotJob& job) {
  const PlotLayout layout = plot_layout(job.out_dir, job.scene);
  const std::string head = plot_manifest_head(job);
  return cache::run_cached(
      {layout.manifest, head, job.out_dir, job.force, job.verify,
       [&]() -> std::optional<cache::JobOutputs> {
         charts::write_plot_sheet({job.scene, layout.png, job.width, job.height});
         return cache::JobOutputs{cache::manifest_note(job.scene),
                                  {layout.png.lexically_relative(job.out_dir).generic_string()}};
       }},
      remake_note_for(job.on_remake, job.scene.name + "-plot"));
}

}  // namespace bookspin::products
