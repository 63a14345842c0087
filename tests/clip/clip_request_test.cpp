// A clip's request turned into the encoder's and the sinks' settings (the scene's render.*
// keys and the request's options), and the end of a clip: everything in place, or nothing
// when a signal asks to stop.
#include "clip/clip_request.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "common/stop.hpp"
#include "output/atomic_output.hpp"
#include "support/scratch.hpp"

namespace bookspin::clip {
namespace {

namespace fs = std::filesystem;

scene::Scene scene_with_render_keys() {
  scene::Scene s;
  s.render.width = 640;
  s.render.height = 360;
  s.render.fps = 24;
  s.render.codec = "h264_nvenc";
  s.render.crf = 21;
  s.render.preset = "slow";
  s.render.png_compression = 7;
  s.render.formats = {"gif", "webm"};
  s.render.webm_crf = 40;
  s.render.gif_width = 320;
  s.render.gif_fps = 10;
  return s;
}

TEST(ClipRequest, TheEncoderSettingsAreTheScenesRenderKeys) {
  const auto e = encoder_settings(scene_with_render_keys(), 3);
  EXPECT_EQ(e.width, 640);
  EXPECT_EQ(e.height, 360);
  EXPECT_EQ(e.fps, 24);
  EXPECT_EQ(e.codec, "h264_nvenc");
  EXPECT_EQ(e.crf, 21);
  EXPECT_EQ(e.preset, "slow");
  EXPECT_EQ(e.threads, 3);
}

TEST(ClipRequest, TheSinkOptionsAreTheScenesKeysAndTheRequestsOptions) {
  ClipRequest request;
  request.scene = scene_with_render_keys();
  request.jobs = 4;
  request.write_png = false;
  const auto s = sink_options(request);
  EXPECT_FALSE(s.write_png);
  EXPECT_EQ(s.png_compression, 7);  // −1: the scene's render.png_compression
  EXPECT_EQ(s.png_workers, 3);      // one thread of the four is the loop's
  EXPECT_EQ(s.encoder.threads, 4);
  EXPECT_EQ(s.encoder.crf, 21);
  EXPECT_EQ(s.formats, (std::vector<std::string>{"gif", "webm"}));
  EXPECT_EQ(s.webm_crf, 40);
  EXPECT_EQ(s.gif_width, 320);
  EXPECT_EQ(s.gif_fps, 10);
  EXPECT_FALSE(s.stop);

  request.png_compression = 0;  // given: it wins over the scene's
  request.jobs = 1;             // one thread: still one PNG worker
  const auto one = sink_options(request);
  EXPECT_EQ(one.png_compression, 0);
  EXPECT_EQ(one.png_workers, 1);
  EXPECT_EQ(one.encoder.threads, 1);
}

/// A complete output under its temporary name, holding `text`.
void write_temporary(output::AtomicFile& file, const std::string& text) {
  std::ofstream(file.temp_path()) << text;
}

TEST(ClipRequest, TheOutputsGoInPlaceUnlessASignalAsksToStop) {
  test::ScratchDir dir;
  ClipRequest request;
  int polls = 0;
  std::string asked;
  request.stop_signal = [&](std::string_view stage) {
    ++polls;
    asked = stage;
    return 15;  // SIGTERM
  };
  {
    output::AtomicFile file(dir / "stopped.csv");
    write_temporary(file, "t\n");
    output::OutputSet outputs;
    outputs.add(file);
    try {
      commit_unless_stopped(request, outputs);
      ADD_FAILURE() << "no Interrupted";
    } catch (const Interrupted& stopped) {
      EXPECT_EQ(stopped.signal(), 15);
    }
    EXPECT_FALSE(file.committed());
  }
  EXPECT_EQ(polls, 1);
  EXPECT_EQ(asked, "commit outputs");
  EXPECT_TRUE(dir.entries().empty());  // nothing in place, the temporary gone

  request.stop_signal = [](std::string_view) { return 0; };
  output::AtomicFile file(dir / "done.csv");
  write_temporary(file, "t\n");
  output::OutputSet outputs;
  outputs.add(file);
  commit_unless_stopped(request, outputs);
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"done.csv"}));

  request.stop_signal = nullptr;  // no poll at all: committed
  output::AtomicFile other(dir / "other.csv");
  write_temporary(other, "t\n");
  output::OutputSet more;
  more.add(other);
  commit_unless_stopped(request, more);
  EXPECT_TRUE(fs::is_regular_file(dir / "other.csv"));
}

}  // namespace
}  // namespace bookspin::clip
