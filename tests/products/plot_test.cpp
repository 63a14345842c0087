// The plot product: OUT/<name>-plot.png of the requested size with its manifest
// OUT/<name>/plot-manifest.json (docs/outputs.md), whose head names the command and the
// image size; up to date the second time, made again with --force or another size.
#include "products/plot.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "output/manifest.hpp"
#include "output/png_writer.hpp"
#include "support/scratch.hpp"

namespace bookspin::products {
namespace {

namespace fs = std::filesystem;

/// The scene "tiny" of 6 frames, its file in `out` (its path and hash go in the manifest's note).
PlotJob small_plot(const fs::path& out) {
  fs::create_directories(out);
  std::ofstream(out / "tiny.toml") << "[scene]\nname = \"tiny\"\n[time]\nframes = 6\n";
  PlotJob job;
  job.scene = scene::parse_scene(out / "tiny.toml");
  job.out_dir = out;
  job.width = 320;
  job.height = 200;
  return job;
}

TEST(Plot, TheHeadNamesTheCommandAndTheImageSize) {
  const std::string head = plot_manifest_head(small_plot(test::fresh_dir("products/plot-head")));
  EXPECT_NE(head.find("\"command\": \"plot\""), std::string::npos) << head;
  EXPECT_NE(head.find("\"options\": {\n    \"width\": 320,\n    \"height\": 200\n  }"),
            std::string::npos)
      << head;
  EXPECT_NE(head.find("\"scene.name\": \"tiny\""), std::string::npos)
      << head;  // the resolved scene
}

TEST(Plot, WritesThePngOfTheSizeAndItsManifestThenIsUpToDate) {
  test::ScratchDir dir;
  PlotJob job = small_plot(dir.path());
  EXPECT_EQ(make_plot(job), cache::Outcome::made);
  const RgbaImage png = output::read_png(dir / "tiny-plot.png");
  EXPECT_EQ(png.width, 320);
  EXPECT_EQ(png.height, 200);
  EXPECT_EQ(output::read_manifest(dir / "tiny" / "plot-manifest.json").outputs,
            (std::vector<std::string>{"tiny-plot.png"}));
  EXPECT_EQ(make_plot(job), cache::Outcome::up_to_date);
  job.freshness.force = true;
  EXPECT_EQ(make_plot(job), cache::Outcome::made);
  job.freshness.force = false;
  job.height = 240;
  std::string reason;
  job.freshness.on_remake = [&](const std::string& name, const std::string&) { reason = name; };
  EXPECT_EQ(make_plot(job), cache::Outcome::made);
  EXPECT_EQ(reason, "tiny-plot");
  EXPECT_EQ(output::read_png(dir / "tiny-plot.png").height, 240);
}

}  // namespace
}  // namespace bookspin::products
