// The products' layouts name the files docs/outputs.md documents (the names are written out
// here, not taken from the code).
#include <gtest/gtest.h>

#include "products/accuracy.hpp"
#include "products/clip.hpp"
#include "products/explorer.hpp"
#include "products/gallery.hpp"
#include "products/gltf.hpp"
#include "products/plot.hpp"
#include "products/sweep.hpp"
#include "scene/scene.hpp"

namespace bookspin::products {
namespace {

scene::Scene named(const std::string& name, std::vector<std::string> formats = {"mp4"}) {
  scene::Scene s;
  s.name = name;
  s.render.formats = std::move(formats);
  return s;
}

TEST(ProductLayout, AClipNamesItsVideosFramesCsvAndManifest) {
  const ClipLayout layout = clip_layout("out", named("fig09", {"webm", "mp4", "gif"}));
  EXPECT_EQ(layout.manifest, "out/fig09/manifest.json");
  ASSERT_EQ(layout.videos.size(), 3u);
  EXPECT_EQ(layout.videos[0], "out/fig09.webm");
  EXPECT_EQ(layout.videos[1], "out/fig09.mp4");
  EXPECT_EQ(layout.videos[2], "out/fig09.gif");
  EXPECT_EQ(layout.frames_dir, "out/fig09/frames");
  ASSERT_EQ(layout.csvs.size(), 1u);
  EXPECT_EQ(layout.csvs[0], "out/fig09/diagnostics.csv");
  EXPECT_EQ(clip::frame_file_name(42), "frame_00042.png");
}

TEST(ProductLayout, AComparisonHasOneCsvPerTileAndTheRequestCarriesThem) {
  scene::Scene s = named("compare-methods-x");
  for (const char* tile : {"euler", "rk4", "exact"}) {
    scene::CompareTile t;
    t.name = tile;
    s.compare.push_back(t);
  }
  const ClipLayout layout = clip_layout("o", s);
  ASSERT_EQ(layout.csvs.size(), 3u);
  EXPECT_EQ(layout.csvs[2], "o/compare-methods-x/diagnostics-exact.csv");
  ClipJob job;
  job.scene = s;
  job.out_dir = "o";
  const clip::ClipRequest request = clip_request(job);
  EXPECT_EQ(request.paths.csv, "o/compare-methods-x/diagnostics-euler.csv");
  ASSERT_EQ(request.tile_csvs.size(), 2u);
  EXPECT_EQ(request.tile_csvs[0], "o/compare-methods-x/diagnostics-rk4.csv");
  EXPECT_EQ(request.paths.gif, "o/compare-methods-x.gif");
}

TEST(ProductLayout, PlotSweepAccuracyGltfExplorerAndGallery) {
  const scene::Scene s = named("fig05");
  EXPECT_EQ(plot_layout("out", s).png, "out/fig05-plot.png");
  EXPECT_EQ(plot_layout("out", s).manifest, "out/fig05/plot-manifest.json");
  const SweepPaths sweep = sweep_paths("out", "fig05");
  EXPECT_EQ(sweep.csv, "out/fig05-sweep.csv");
  EXPECT_EQ(sweep.png, "out/fig05-sweep.png");
  EXPECT_EQ(sweep.shard(2, 8), "out/fig05-sweep.shard-2-of-8.csv");
  EXPECT_EQ(sweep_manifest_path("out", "fig05"), "out/fig05/sweep-manifest.json");
  const AccuracyLayout accuracy = accuracy_layout("out", s);
  EXPECT_EQ(accuracy.outputs(),
            (std::vector<std::filesystem::path>{
                "out/fig05-accuracy.csv", "out/fig05-accuracy.png", "out/fig05-work-precision.png",
                "out/fig05-energy-vs-dt.png", "out/fig05-turnovers.png", "out/fig05-energy.png",
                "out/fig05-energy.csv"}));
  EXPECT_EQ(accuracy.energy_vs_dt_png, "out/fig05-energy-vs-dt.png");
  EXPECT_EQ(accuracy.manifest, "out/fig05/accuracy-manifest.json");
  EXPECT_EQ(gltf_layout("out", s).glb, "out/fig05.glb");
  EXPECT_EQ(gltf_layout("out", s).manifest, "out/fig05/gltf-manifest.json");
  EXPECT_EQ(explorer_page_path("out"), "out/explorer.html");
  EXPECT_EQ(gallery_layout("out").page, "out/index.html");
  EXPECT_EQ(gallery_layout("out").manifest, "out/gallery-manifest.json");
}

}  // namespace
}  // namespace bookspin::products
