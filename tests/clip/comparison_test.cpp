// The comparison composer without a GL context: the tiles' pictures are given (flat colours
// here), and it lays them out under the title strip (compare_layout's rectangles, worked out
// by hand below), fills the gaps with the dark background and writes a caption on each tile.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <memory>
#include <vector>

#include "clip/compare_layout.hpp"
#include "clip/composer.hpp"
#include "overlay/caption.hpp"

namespace bookspin::clip {
namespace {

using Rgb = std::array<int, 3>;

Rgb at(const RgbaImage& image, int x, int y) {
  const std::uint8_t* p = image.row(y) + 4 * x;
  return {p[0], p[1], p[2]};
}

RgbaImage flat(int width, int height, const Rgb& colour) {
  RgbaImage image(width, height);
  for (std::size_t i = 0; i < image.pixels.size(); i += 4) {
    for (int c = 0; c < 3; ++c) image.pixels[i + c] = static_cast<std::uint8_t>(colour[c]);
    image.pixels[i + 3] = 255;
  }
  return image;
}

/// compare-methods-x (four tiles) at 640×360, without the plot column and the sphere.
scene::Scene four_tiles() {
  return scene::parse_scene(
      std::filesystem::path(BOOKSPIN_SOURCE_DIR) / "scenes" / "compare-methods-x.toml",
      {"render.width=640", "render.height=360", "render.panel=false", "render.sphere=false",
       "time.frames=3"});
}

// 640×360: header max(14, 18) = 18, gap max(2, 1.44) = 2, grid 640 × 342. Four tiles: 2×2
// (sides 171; 4×1 gives 160), each (640 − 2) / 2 = 319 → 318 wide, (342 − 2) / 2 = 170 high,
// at x = 0 and 320, y = 18 and 190.
constexpr int kTileWidth = 318, kTileHeight = 170;
constexpr int kTileX[4] = {0, 320, 0, 320}, kTileY[4] = {18, 18, 190, 190};

TEST(Comparison, ThePicturesAreTheSizeOfATile) {
  const scene::Scene scene = four_tiles();
  const auto composer = comparison_composer(scene);
  const render::RenderSettings settings =
      composer->picture_settings(tile_scene(scene, scene.compare.front()));
  EXPECT_EQ(settings.width, kTileWidth);
  EXPECT_EQ(settings.height, kTileHeight);
}

TEST(Comparison, EachPictureGoesToItsTileUnderTheStripWithACaption) {
  const scene::Scene scene = four_tiles();
  Tiles tiles;
  for (const auto& tile : scene.compare)
    tiles.push_back(std::make_unique<TileRun>(tile_scene(scene, tile)));
  const Rgb colours[4] = {{200, 0, 0}, {0, 200, 0}, {0, 0, 200}, {200, 200, 0}};
  std::vector<RgbaImage> pictures;
  for (const Rgb& c : colours) pictures.push_back(flat(kTileWidth, kTileHeight, c));
  const auto composer = comparison_composer(scene);
  const RgbaImage frame = composer->compose(pictures, tiles);
  ASSERT_EQ(frame.width, 640);
  ASSERT_EQ(frame.height, 360);
  const Rgb gap = at(blank_frame(1, 1), 0, 0);
  for (int i = 0; i < 4; ++i) {
    SCOPED_TRACE(i);
    const int x = kTileX[i], y = kTileY[i];
    // The tile's lower right part is its picture, untouched; its corners too.
    EXPECT_EQ(at(frame, x + kTileWidth - 1, y + kTileHeight - 1), colours[i]);
    EXPECT_EQ(at(frame, x + kTileWidth / 2, y + kTileHeight - 2), colours[i]);
    EXPECT_EQ(at(frame, x + kTileWidth - 1, y), colours[i]);
    // Just right of it and just below it: the gap.
    if (x + kTileWidth < 640) {
      EXPECT_EQ(at(frame, x + kTileWidth, y + kTileHeight / 2), gap);
    }
    if (y + kTileHeight < 360) {
      EXPECT_EQ(at(frame, x + kTileWidth / 2, y + kTileHeight), gap);
    }
    // The caption: in the tile's top left quarter some pixels are no longer the picture's.
    int written = 0;
    for (int yy = y; yy < y + kTileHeight / 4; ++yy)
      for (int xx = x; xx < x + kTileWidth / 2; ++xx) written += at(frame, xx, yy) != colours[i];
    EXPECT_GT(written, 100);
  }
  // The title strip across the top holds no tile's colour, and its text is drawn.
  int text = 0;
  for (int y = 0; y < 18; ++y) {
    for (int x = 0; x < 640; ++x) {
      const Rgb p = at(frame, x, y);
      for (const Rgb& c : colours) EXPECT_NE(p, c) << x << ',' << y;
      text += p != at(frame, 639, 0);
    }
  }
  EXPECT_GT(text, 100);
}

// No caption covers a tile's body: in every comparison scene of the gallery, each tile's
// caption (composed over white pictures, the rows it darkens) ends above the rows where the
// tile's camera sees the body's bounding sphere, whatever its orientation.
TEST(Comparison, EachTilesBodyIsFramedBelowItsCaption) {
  int checked = 0;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::filesystem::path(BOOKSPIN_SOURCE_DIR) / "scenes")) {
    if (entry.path().extension() != ".toml") continue;
    const scene::Scene scene = scene::parse_scene(entry.path(), {"time.frames=3"});
    if (scene.compare.empty()) continue;
    SCOPED_TRACE(entry.path().filename().string());
    const auto composer = comparison_composer(scene);
    const scene::Scene first = tile_scene(scene, scene.compare.front());
    const render::RenderSettings settings = composer->picture_settings(first);
    const CompareLayout layout =
        compare_layout(static_cast<int>(scene.compare.size()), scene.render.width,
                       scene.render.height, scene.render.panel);
    Tiles tiles;
    std::vector<RgbaImage> pictures;
    for (const auto& tile : scene.compare) {
      tiles.push_back(std::make_unique<TileRun>(tile_scene(scene, tile)));
      pictures.push_back(flat(settings.width, settings.height, {255, 255, 255}));
    }
    const RgbaImage frame = composer->compose(pictures, tiles);
    const PixelRect& tile = layout.tiles.front();
    int caption_bottom = 0;  // rows from the tile's top
    for (int y = 0; y < settings.height; ++y)
      for (int x = 0; x < settings.width; ++x)
        if (at(frame, static_cast<int>(tile.x) + x, static_cast<int>(tile.y) + y) !=
            Rgb{255, 255, 255})
          caption_bottom = y + 1;
    ASSERT_GT(caption_bottom, 0);
    ASSERT_LT(caption_bottom, settings.height);
    // Readable: 12 px text or more from a 960 × 540 frame up. The font from the box as drawn:
    // n lines are n × 1.35 + 0.6 font sizes high, and 0.5 more with the key under the title
    // (overlay/caption.cpp's box, by hand); n counted as the bands of light rows in the box
    // (the text's and the key's strip, over the box's grey on these white pictures).
    if (scene.render.height >= 540) {
      int top = -1, bands = 0;
      bool in_band = false;
      const Rgb white{255, 255, 255};
      const auto pixel = [&](int x, int y) {
        return at(frame, static_cast<int>(tile.x) + x, static_cast<int>(tile.y) + y);
      };
      for (int y = 0; y < caption_bottom; ++y) {
        bool box = false, grey = false, light = false;
        for (int x = 1; x + 1 < settings.width; ++x) {
          const Rgb p = pixel(x, y);
          if (p == white) continue;
          box = true;
          grey |= p[0] < 150;
          // Light inside the box, not on its antialiased edge (a white neighbour).
          light |= p[0] > 200 && p[1] > 200 && p[2] > 200 && pixel(x - 1, y) != white &&
                   pixel(x + 1, y) != white;
        }
        if (box && top < 0) top = y;
        light &= grey;  // a row of the box's inside, not its partly covered first or last
        if (light && !in_band) ++bands;
        in_band = light;
      }
      const bool keyed = scene.render.panel || scene.render.sphere;
      const int lines = bands - (keyed ? 1 : 0);
      ASSERT_GE(lines, 2);
      const double font = (caption_bottom - top) / (1.35 * lines + 0.6 + (keyed ? 0.5 : 0.0));
      EXPECT_GE(font, 12.0 - 0.3) << lines << " lines in rows " << top << " to " << caption_bottom;
    }
    // The sphere's highest row: its centre's row less its angular radius, seen from the eye.
    const render::Camera& c = settings.camera;
    const Eigen::Vector3d forward = (c.target - c.eye).normalized();
    const Eigen::Vector3d right = forward.cross(c.up).normalized();
    const Eigen::Vector3d up = right.cross(forward);
    const Eigen::Vector3d v = -c.eye;  // the body's centre is the origin
    const double radius = 0.5 * first.body.cage.size.norm();
    const double centre = std::atan2(v.dot(up), v.dot(forward));
    const double half = std::asin(std::min(1.0, radius / v.norm()));
    const double top_ndc = std::tan(centre + half) / std::tan(c.fov_y_deg * M_PI / 360.0);
    const double top_row = (1.0 - top_ndc) / 2.0 * settings.height;
    EXPECT_GE(top_row, caption_bottom) << "the body reaches row " << top_row;
    ++checked;
  }
  EXPECT_GE(checked, 4);
}

// The header's "t = …" is the time of the frame shown (TileRun::shown: the composer shows the
// tiles as shown holds them, composer.hpp), not of the simulation side, which runs up to the
// renderer's pipeline depth ahead. The strip (the top 18 rows, worked out above) is compared
// pixel for pixel with overlay's title strip drawn directly on the background with the shown
// time, and told apart from the one drawn with the simulation's.
TEST(Comparison, TheHeaderTimeIsTheShownFramesNotTheSimulations) {
  const scene::Scene scene = four_tiles();
  Tiles tiles;
  for (const auto& tile : scene.compare) {
    tiles.push_back(std::make_unique<TileRun>(tile_scene(scene, tile)));
    tiles.back()->shown.t = 12.5;  // the frame composed now
    tiles.back()->frame.t = 57.4;  // the simulation, frames ahead
  }
  std::vector<RgbaImage> pictures(4, flat(kTileWidth, kTileHeight, {90, 90, 90}));
  const RgbaImage frame = comparison_composer(scene)->compose(pictures, tiles);
  const auto strip_with = [&](double t) {
    RgbaImage image = blank_frame(640, 360);
    overlay::draw_title_strip(image, PixelRect{0, 0, 640, 18}, scene.title, t);
    return image;
  };
  const RgbaImage shown = strip_with(12.5), simulated = strip_with(57.4);
  int differ_from_shown = 0, differ_from_simulated = 0;
  for (int y = 0; y < 18; ++y)
    for (int x = 0; x < 640; ++x) {
      differ_from_shown += at(frame, x, y) != at(shown, x, y);
      differ_from_simulated += at(frame, x, y) != at(simulated, x, y);
    }
  EXPECT_EQ(differ_from_shown, 0);
  EXPECT_GT(differ_from_simulated, 20);  // "t = 57.4" is not "t = 12.5"
}

}  // namespace
}  // namespace bookspin::clip
