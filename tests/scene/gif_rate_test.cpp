// render.gif_fps: a GIF stores each frame's delay in whole centiseconds, at least 2 for a
// browser, so it plays at most 50 frames/s; a rate it cannot store is bad input naming the
// key and what it allows (docs/outputs.md, "Video formats").
#include <gtest/gtest.h>

#include <string>

#include "scene_text.hpp"

namespace bookspin::scene {
namespace {

using testing::error_of;
using testing::parse;

std::string render(int fps, int gif_fps) {
  return "[render]\nfps = " + std::to_string(fps) + "\ngif_fps = " + std::to_string(gif_fps) + "\n";
}

// The played rate fps / round(fps / gif_fps), worked out by hand for each case.
TEST(GifRate, RatesAGifCanPlayAreAccepted) {
  // 30/15 → every 2nd: 15; 50/50 → every frame: 50; 240/50 → round(4.8) = 5: 48;
  // 120/48 → round(2.5) = 3: 40; 60/40 → round(1.5) = 2: 30; 100/50 → 2: 50.
  for (const auto& [fps, gif_fps] :
       {std::pair{30, 15}, {50, 50}, {240, 50}, {120, 48}, {60, 40}, {100, 50}}) {
    EXPECT_EQ(error_of(render(fps, gif_fps)), "") << fps << " " << gif_fps;
    EXPECT_EQ(parse(render(fps, gif_fps)).render.gif_fps, gif_fps);
  }
  // The default, 15 (at most render.fps), at every rate of the limits table's ends.
  for (int fps : {1, 30, 51, 120, 240})
    EXPECT_EQ(error_of("[render]\nfps = " + std::to_string(fps) + "\n"), "") << fps;
}

TEST(GifRate, ARateAGifCannotStoreNamesTheKeyAndTheLargestAllowed) {
  // 120/50 → round(2.4) = 2: 60 frames/s. The largest allowed with 120 is 48 (round(2.5) = 3:
  // 40); 49 → round(2.45) = 2: 60.
  EXPECT_EQ(error_of(render(120, 50)),
            "test.toml:3: render.gif_fps: the GIF would play at 60 frames/s; a GIF plays at most "
            "50 (its frame delays are whole centiseconds, at least 2): at most 48 with "
            "render.fps = 120, got 50");
  EXPECT_NE(error_of(render(120, 49)).find("at most 48 with render.fps = 120, got 49"),
            std::string::npos);
  // 55/37 → round(1.486) = 1: every frame, 55 frames/s; 55/36 = 1.53 rounds to 2 (27.5
  // frames/s), so 36 is the largest allowed.
  EXPECT_NE(error_of(render(55, 37)).find("would play at 55 frames/s"), std::string::npos);
  EXPECT_NE(error_of(render(55, 37)).find("at most 36 with render.fps = 55"), std::string::npos);
  // Above the limits table's 50: the range message.
  EXPECT_EQ(error_of(render(240, 240)),
            "test.toml:3: render.gif_fps: must be >= 1 and <= 50, got 240");
}

}  // namespace
}  // namespace bookspin::scene
