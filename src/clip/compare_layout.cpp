#include "clip/compare_layout.hpp"

#include <algorithm>
#include <cstring>

namespace bookspin::clip {

namespace {

int even_floor(double v) { return std::max(16, static_cast<int>(v) / 2 * 2); }

struct Grid {
  int columns, rows;
};

Grid best_grid(int tiles, double width, double height) {
  Grid best{tiles, 1};
  double best_side = -1;
  for (int columns = 1; columns <= tiles; ++columns) {
    const int rows = (tiles + columns - 1) / columns;
    const double side = std::min(width / columns, height / rows);
    if (side > best_side + 0.5) best = {columns, rows}, best_side = side;
  }
  return best;
}

}  // namespace

CompareLayout compare_layout(int tiles, int width, int height, bool with_plots) {
  CompareLayout layout;
  const double header = std::max(14.0, 0.05 * height);
  layout.header = {0, 0, static_cast<double>(width), header};
  const double gap = std::max(2.0, 0.004 * height);
  const double grid_width = with_plots ? charts::kBookShare * width : width;
  const double grid_height = height - header;
  const Grid grid = best_grid(tiles, grid_width, grid_height);
  layout.columns = grid.columns, layout.rows = grid.rows;
  layout.tile_width = even_floor((grid_width - gap * (grid.columns - 1)) / grid.columns);
  layout.tile_height = even_floor((grid_height - gap * (grid.rows - 1)) / grid.rows);
  for (int i = 0; i < tiles; ++i) {
    const int c = i % grid.columns, r = i / grid.columns;
    layout.tiles.push_back({c * (layout.tile_width + gap), header + r * (layout.tile_height + gap),
                            static_cast<double>(layout.tile_width),
                            static_cast<double>(layout.tile_height)});
  }
  if (with_plots) {
    const double margin = 0.012 * std::min(width, height);
    layout.plots = PixelRect{grid_width + margin, header + margin, width - grid_width - 2 * margin,
                             height - header - 2 * margin};
  }
  return layout;
}

void blit(RgbaImage& frame, const RgbaImage& tile, int x, int y) {
  const int width = std::min(tile.width, frame.width - x);
  if (width <= 0 || x < 0 || y < 0) return;
  for (int row = 0; row < tile.height && y + row < frame.height; ++row) {
    std::memcpy(frame.row(y + row) + 4 * static_cast<std::size_t>(x), tile.row(row),
                4 * static_cast<std::size_t>(width));
  }
}

RgbaImage blank_frame(int width, int height) {
  RgbaImage frame(width, height);
  for (std::size_t i = 0; i < frame.pixels.size(); i += 4) {
    frame.pixels[i] = 18, frame.pixels[i + 1] = 20, frame.pixels[i + 2] = 26,
    frame.pixels[i + 3] = 255;
  }
  return frame;
}

}  // namespace bookspin::clip
