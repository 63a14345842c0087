#pragma once
// Where the tiles of a comparison frame go: a title strip on top, a grid of equal tiles
// (one per [[compare]] tile) below, and with render.panel the plots on the right.
#include <optional>
#include <vector>

#include "charts/panel.hpp"
#include "common/rgba_image.hpp"

namespace bookspin::clip {

struct CompareLayout {
  PixelRect header;  ///< the title strip across the top
  int columns = 1, rows = 1;
  int tile_width = 0, tile_height = 0;  ///< pixels, even (the renderer needs even sizes)
  std::vector<PixelRect> tiles;         ///< one per tile, in row-major order
  std::optional<PixelRect> plots;       ///< the plot column, with render.panel
};

/// The layout for `tiles` tiles in a width×height frame. The grid is the one whose tiles
/// have the largest smaller side (the book is framed by its bounding sphere), preferring
/// fewer empty cells on a tie.
CompareLayout compare_layout(int tiles, int width, int height, bool with_plots);

/// Copies `tile` into `frame` with its top-left corner at pixel (x, y), clipped to `frame`.
void blit(RgbaImage& frame, const RgbaImage& tile, int x, int y);

/// A width×height frame filled with the dark colour of the gaps between tiles.
RgbaImage blank_frame(int width, int height);

}  // namespace bookspin::clip
