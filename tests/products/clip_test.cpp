// The clip product without a GL context: the frame loop's request carries the layout's paths
// and the job's options; the manifest head holds the PNG options (the scene's compression
// where the job gives none); and a clip found up to date draws nothing and repeats the
// divergence warnings its manifest recorded (rendering itself: tests/cli/, tests/picture/).
#include "products/clip.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "output/manifest.hpp"
#include "support/scratch.hpp"

namespace bookspin::products {
namespace {

namespace fs = std::filesystem;

ClipJob tiny_job(const fs::path& out) {
  ClipJob job;
  job.scene = scene::parse_scene_text("[scene]\nname = \"tiny\"\n", "clip_test.toml",
                                      {"time.frames=3", "render.png_compression=5"});
  job.out_dir = out;
  return job;
}

TEST(ClipProduct, TheRequestCarriesTheLayoutsPathsAndTheJobsOptions) {
  ClipJob job = tiny_job("out");
  job.write_png = false;
  job.png_compression = 2;
  job.jobs = 3;
  const clip::ClipRequest request = clip_request(job);
  EXPECT_EQ(request.paths.mp4, "out/tiny.mp4");
  EXPECT_EQ(request.paths.webm, "out/tiny.webm");
  EXPECT_EQ(request.paths.gif, "out/tiny.gif");
  EXPECT_EQ(request.paths.frames_dir, "out/tiny/frames");
  EXPECT_EQ(request.paths.csv, "out/tiny/diagnostics.csv");
  EXPECT_TRUE(request.tile_csvs.empty());
  EXPECT_FALSE(request.write_png);
  EXPECT_EQ(request.png_compression, 2);
  EXPECT_EQ(request.jobs, 3);
  EXPECT_EQ(request.scene.frames, 3);
}

TEST(ClipProduct, TheHeadHoldsThePngOptions) {
  ClipJob job = tiny_job("out");
  const std::string head = clip_manifest_head(job);
  EXPECT_NE(head.find("\"command\": \"render\""), std::string::npos) << head;
  // png_compression −1: the scene's render.png_compression.
  EXPECT_NE(head.find("\"options\": {\n    \"png\": true,\n    \"png_compression\": 5\n  }"),
            std::string::npos)
      << head;
  job.write_png = false;
  job.png_compression = 0;
  EXPECT_NE(clip_manifest_head(job).find(
                "\"options\": {\n    \"png\": false,\n    \"png_compression\": 0\n  }"),
            std::string::npos);
}

TEST(ClipProduct, UpToDateItDrawsNothingAndRepeatsTheRecordedWarnings) {
  test::ScratchDir dir;
  const ClipJob job = tiny_job(dir.path());
  const std::vector<std::string> outputs{"tiny.mp4", "tiny/frames/frame_00000.png",
                                         "tiny/frames/frame_00001.png",
                                         "tiny/frames/frame_00002.png", "tiny/diagnostics.csv"};
  for (const std::string& file : outputs) {
    fs::create_directories((dir / file).parent_path());
    std::ofstream(dir / file) << file;
  }
  const std::string note =
      "  \"warnings\": [\"tiny: simulation diverged at t = 1.5; the \\\"held\\\" frame\", "
      "\"back\\\\slash\"],\n";
  output::write_manifest(dir / "tiny" / "manifest.json", clip_manifest_head(job), note, dir.path(),
                         outputs);
  const ClipOutcome done = make_clip(job);
  EXPECT_EQ(done.outcome, cache::Outcome::up_to_date);
  EXPECT_EQ(done.result.frames, 0);  // nothing rendered
  EXPECT_EQ(done.warnings,
            (std::vector<std::string>{"tiny: simulation diverged at t = 1.5; the \"held\" frame",
                                      "back\\slash"}));
}

}  // namespace
}  // namespace bookspin::products
