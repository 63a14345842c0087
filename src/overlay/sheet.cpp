#include "overlay/sheet.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "overlay/cairo_canvas.hpp"
#include "overlay/sheet_header.hpp"

namespace bookspin::overlay {

RgbaImage plot_sheet(const std::vector<std::string>& header, const std::vector<PlotSpec>& plots,
                     int width, int height, int columns) {
  RgbaImage image(width, height);
  std::fill(image.pixels.begin(), image.pixels.end(), 255);
  CairoCanvas canvas(width, height);
  cairo_t* cr = canvas.cr();
  const double font = std::max(15.0, 0.024 * height);
  double y = draw_sheet_header(cr, wrap_sheet_header(cr, header, font, width), font);
  y += 0.6 * font;
  const std::size_t across = static_cast<std::size_t>(std::max(1, columns));
  const std::size_t rows = (plots.size() + across - 1) / across;
  const double each = rows == 0 ? 0 : (height - y) / static_cast<double>(rows);
  const double wide = static_cast<double>(width) / static_cast<double>(across);
  std::vector<PlotSpec> aligned = plots;
  align_left_margins(cr, each, aligned);
  for (std::size_t i = 0; i < aligned.size(); ++i)
    draw_plot(cr, wide * static_cast<double>(i % across),
              y + each * static_cast<double>(i / across), wide, each, aligned[i]);
  canvas.composite_onto(image);
  return image;
}

RgbaImage draw_sheet(const SheetSpec& sheet) {
  if (!sheet.maps.empty())
    return heat_map_sheet(sheet.header, sheet.maps, sheet.width, sheet.height);
  return plot_sheet(sheet.header, sheet.plots, sheet.width, sheet.height, sheet.columns);
}

}  // namespace bookspin::overlay
