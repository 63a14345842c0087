#include "overlay/sheet.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "overlay/cairo_canvas.hpp"
#include "overlay/sheet_header.hpp"
#include "typeface/text_layout.hpp"

namespace bookspin::overlay {

RgbaImage plot_sheet(const std::vector<std::string>& header, const std::vector<PlotSpec>& plots,
                     int width, int height, int columns) {
  RgbaImage image(width, height);
  std::fill(image.pixels.begin(), image.pixels.end(), 255);
  CairoCanvas canvas(width, height);
  cairo_t* cr = canvas.cr();
  const double font = std::max(15.0, 0.024 * height);
  const SheetHeader head = lay_out_sheet_header(cr, header, font, width);
  for (std::size_t i = 0; i < head.lines.size(); ++i) {
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    cairo_move_to(cr, head.x, head.baselines[i]);
    typeface::show_laid_out(cr, head.lines[i]);
  }
  const double y = head.bottom + 0.6 * font;
  const std::size_t across = static_cast<std::size_t>(std::max(1, columns));
  const std::size_t rows = (plots.size() + across - 1) / across;
  const double each = rows == 0 ? 0 : (height - y) / static_cast<double>(rows);
  const double wide = static_cast<double>(width) / static_cast<double>(across);
  std::vector<PixelRect> rects;
  for (std::size_t i = 0; i < plots.size(); ++i)
    rects.push_back({wide * static_cast<double>(i % across),
                     y + each * static_cast<double>(i / across), wide, each});
  draw_aligned_plots(cr, plots, rects);
  canvas.composite_onto(image);
  return image;
}

RgbaImage draw_sheet(const SheetSpec& sheet) {
  if (!sheet.maps.empty())
    return heat_map_sheet(sheet.header, sheet.maps, sheet.width, sheet.height);
  return plot_sheet(sheet.header, sheet.plots, sheet.width, sheet.height, sheet.columns);
}

}  // namespace bookspin::overlay
