#include "products/plot.hpp"

#include "analysis/frame_source.hpp"
#include "cache/make_cached.hpp"
#include "charts/plot_sheet.hpp"
#include "output/output_dir.hpp"
#include "output/png_writer.hpp"

namespace bookspin::products {

PlotLayout plot_layout(const std::filesystem::path& out_dir, const scene::Scene& scene) {
  return {out_dir / (scene.name + "-plot.png"), out_dir / scene.name / "plot-manifest.json"};
}

namespace {

cache::CachedOutputs plot_cached(const PlotJob& job, const PlotLayout& layout) {
  const JsonObject options{{"width", {std::int64_t{job.width}}},
                           {"height", {std::int64_t{job.height}}}};
  return {job.scene.name + "-plot", layout.manifest, "plot", options, job.out_dir, &job.scene,
          /*all_or_nothing=*/true};  // one PNG, put in place whole or not at all
}

}  // namespace

std::string plot_manifest_head(const PlotJob& job) {
  return cache::cached_head(plot_cached(job, plot_layout(job.out_dir, job.scene)));
}

cache::Outcome make_plot(const PlotJob& job) {
  const PlotLayout layout = plot_layout(job.out_dir, job.scene);
  const cache::CachedOutputs cached{plot_cached(job, layout)};
  return cache::make_cached(cached, job.freshness, [&] {
    const std::vector<analysis::RunFrames> runs = analysis::run_frames(job.scene, job.stop);
    const RgbaImage sheet = charts::plot_sheet_image(job.scene, runs, job.width, job.height);
    stop_if_asked(job.stop, "plot files");  // the sheet drawn: a signal meanwhile still stops
    output::prepare_output_dir(layout.png.parent_path());
    output::write_png(layout.png, sheet);
    return cache::Made{{layout.png}};
  });
}

}  // namespace bookspin::products
