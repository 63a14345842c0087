#include "overlay/heat_map.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <optional>
#include <stdexcept>

#include "overlay/cairo_canvas.hpp"
#include "overlay/sheet_header.hpp"
#include "typeface/text_layout.hpp"

namespace bookspin::overlay {

namespace {

/// The sheet's header font and the maps' font (pixels), from the sheet's height.
double header_font(int height) { return std::clamp(0.024 * height, 15.0, 22.0); }
/// The maps' text: its smallest (ticks, 0.8 of it) at least 12 pixels.
double map_font(int height) { return std::max(15.0, 0.8 * header_font(height)); }

double header_height(int height, std::size_t lines) {
  const double font = header_font(height);
  double y = 0.4 * font;
  for (std::size_t i = 0; i < lines; ++i) y += 1.35 * (i == 0 ? font : 0.8 * font);
  return y + 0.6 * font;
}

/// The region of map `index` (title, legend, axes, colour bar and cells).
MapRect map_region(int width, int height, std::size_t header_lines, std::size_t count,
                   std::size_t index) {
  const std::size_t columns = count >= 2 ? 2 : 1;
  const std::size_t rows = (count + columns - 1) / columns;
  const double top = header_height(height, header_lines);
  const double w = static_cast<double>(width) / columns;
  const double h = (height - top) / static_cast<double>(std::max<std::size_t>(rows, 1));
  return {w * static_cast<double>(index % columns), top + h * static_cast<double>(index / columns),
          w, h};
}

std::string short_number(double v, int digits = 3) {
  char text[40];
  std::snprintf(text, sizeof text, "%.*g", digits, v);
  return text;
}

void text_at(cairo_t* cr, double x, double y, const std::string& text, double align_x,
             double align_y) {
  cairo_text_extents_t e;
  typeface::text_extents(cr, text.c_str(), &e);
  cairo_move_to(cr, x - align_x * e.width - e.x_bearing, y - align_y * e.height - e.y_bearing);
  typeface::show_text(cr, text.c_str());
}

/// The range of the finite (and, on a log scale, positive) values, in log10 where log.
bool value_range(const HeatMapSpec& map, double& lo, double& hi) {
  lo = std::numeric_limits<double>::infinity();
  hi = -lo;
  for (double v : map.value) {
    if (!std::isfinite(v) || (map.log_value && v <= 0.0)) continue;
    const double s = map.log_value ? std::log10(v) : v;
    lo = std::min(lo, s);
    hi = std::max(hi, s);
  }
  return lo <= hi;
}

double scaled(const HeatMapSpec& map, double v) {
  if (map.log_value) return v > 0.0 ? std::log10(v) : -std::numeric_limits<double>::infinity();
  return v;
}

void draw_map(cairo_t* cr, const HeatMapSpec& map, const MapRect& region, const MapRect& cells,
              double font) {
  const std::size_t nx = map.x.size(), ny = map.y.size();
  double lo = 0.0, hi = 1.0;
  const bool any = value_range(map, lo, hi);
  int diverged = 0, empty = 0;
  for (std::size_t c = 0; c < map.value.size(); ++c) {
    if (map.diverged[c])
      ++diverged;
    else if (!std::isfinite(map.value[c]))
      ++empty;
  }
  // Title and legend.
  cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
  select_overlay_font(cr, true, font);
  text_at(cr, region.left + 0.5 * region.width, region.top + 0.5 * font, map.title, 0.5, 0.0);
  select_overlay_font(cr, false, 0.85 * font);
  char legend[200];
  std::snprintf(legend, sizeof legend, "\u00d7 diverged: %d of %zu cells    grey: %s, %d", diverged,
                map.value.size(), map.empty_meaning.c_str(), empty);
  text_at(cr, region.left + 0.5 * region.width, region.top + 1.9 * font, legend, 0.5, 0.0);
  // Cells.
  const double cw = cells.width / static_cast<double>(nx),
               ch = cells.height / static_cast<double>(ny);
  for (std::size_t j = 0; j < ny; ++j) {
    for (std::size_t i = 0; i < nx; ++i) {
      const std::size_t c = j * nx + i;
      const double v = map.value[c];
      const double x0 = cells.left + static_cast<double>(i) * cw;
      const double y0 = cells.top + cells.height - static_cast<double>(j + 1) * ch;
      if (std::isfinite(v) && any) {
        const double f = hi > lo ? (scaled(map, v) - lo) / (hi - lo) : 0.5;
        const auto rgb = heat_colour(f);
        cairo_set_source_rgb(cr, rgb[0] / 255.0, rgb[1] / 255.0, rgb[2] / 255.0);
      } else {
        cairo_set_source_rgb(cr, 0.82, 0.82, 0.82);
      }
      cairo_rectangle(cr, x0, y0, cw, ch);
      cairo_fill(cr);
      if (map.diverged[c]) {
        cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
        cairo_set_line_width(cr, std::max(1.5, 0.06 * std::min(cw, ch)));
        const double m = 0.2 * std::min(cw, ch);
        cairo_move_to(cr, x0 + m, y0 + m);
        cairo_line_to(cr, x0 + cw - m, y0 + ch - m);
        cairo_move_to(cr, x0 + cw - m, y0 + m);
        cairo_line_to(cr, x0 + m, y0 + ch - m);
        cairo_stroke(cr);
      }
    }
  }
  cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
  cairo_set_line_width(cr, 1.0);
  cairo_rectangle(cr, cells.left, cells.top, cells.width, cells.height);
  cairo_stroke(cr);
  // Axes: every grid value at its cell's centre (every k-th where they would crowd).
  select_overlay_font(cr, false, 0.8 * font);
  cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
  const std::size_t x_step = std::max<std::size_t>(1, (nx + 9) / 10);
  for (std::size_t i = 0; i < nx; i += x_step)
    text_at(cr, cells.left + (static_cast<double>(i) + 0.5) * cw,
            cells.top + cells.height + 0.4 * font, short_number(map.x[i]), 0.5, 0.0);
  const std::size_t y_step = std::max<std::size_t>(1, (ny + 9) / 10);
  for (std::size_t j = 0; j < ny; j += y_step)
    text_at(cr, cells.left - 0.4 * font,
            cells.top + cells.height - (static_cast<double>(j) + 0.5) * ch, short_number(map.y[j]),
            1.0, 0.5);
  select_overlay_font(cr, false, 0.85 * font);
  text_at(cr, cells.left + 0.5 * cells.width, cells.top + cells.height + 1.7 * font,
          map.x_label + (map.log_x ? " (log scale)" : ""), 0.5, 0.0);
  cairo_save(cr);
  cairo_translate(cr, region.left + 0.6 * font, cells.top + 0.5 * cells.height);
  cairo_rotate(cr, -M_PI / 2);
  text_at(cr, 0, 0, map.y_label + (map.log_y ? " (log scale)" : ""), 0.5, 0.0);
  cairo_restore(cr);
  // Colour bar: the scale from its smallest value (bottom) to its largest (top).
  const double bar_left = cells.left + cells.width + 1.2 * font, bar_width = 1.2 * font;
  const int stripes = 64;
  for (int s = 0; s < stripes; ++s) {
    const auto rgb = heat_colour((s + 0.5) / stripes);
    cairo_set_source_rgb(cr, rgb[0] / 255.0, rgb[1] / 255.0, rgb[2] / 255.0);
    const double y1 = cells.top + cells.height * (1.0 - static_cast<double>(s + 1) / stripes);
    cairo_rectangle(cr, bar_left, y1, bar_width, cells.height / stripes + 0.5);
    cairo_fill(cr);
  }
  cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
  select_overlay_font(cr, false, 0.8 * font);
  // The bar's label goes right of its widest tick label, so that it never runs into them, nor
  // into the next map's rotated key at the region's far edge.
  const double ticks_left = bar_left + bar_width + 0.3 * font;
  double ticks_right = ticks_left;
  const auto tick = [&](double fraction, const std::string& text) {
    cairo_text_extents_t e;
    typeface::text_extents(cr, text.c_str(), &e);
    ticks_right = std::max(ticks_right, ticks_left + e.x_advance);
    text_at(cr, ticks_left, cells.top + cells.height * (1.0 - fraction), text, 0.0, 0.5);
  };
  if (any) {
    const auto unscaled = [&](double s) { return map.log_value ? std::pow(10.0, s) : s; };
    for (const auto& [fraction, text] : colour_bar_ticks(unscaled(lo), unscaled(hi), map.log_value))
      tick(fraction, text);
  } else {
    tick(0.5, "no values");
  }
  cairo_save(cr);
  const double label_x =
      std::min(ticks_right + 1.0 * font, region.left + region.width - 0.9 * font);
  cairo_translate(cr, label_x, cells.top + 0.5 * cells.height);
  cairo_rotate(cr, -M_PI / 2);
  select_overlay_font(cr, false, 0.85 * font);
  text_at(cr, 0, 0, map.value_label + (map.log_value ? " (log scale)" : ""), 0.5, 0.5);
  cairo_restore(cr);
}

}  // namespace

std::vector<std::pair<double, std::string>> colour_bar_ticks(double lo, double hi, bool log) {
  if (!(lo < hi)) return {{0.5, short_number(lo)}};
  const double mid = log ? std::sqrt(lo) * std::sqrt(hi) : 0.5 * (lo + hi);
  const std::array<double, 3> values{lo, mid, hi};
  // A linear bar: the three at one decimal place, that of half the range or the largest
  // value's third significant digit, whichever is finer (0.28, 1.68, 3.08; 813.94, 814.01,
  // 814.08), where that stays short.
  const double largest = std::max(std::abs(lo), std::abs(hi));
  const int decimals =
      std::max({0, -static_cast<int>(std::floor(std::log10(0.5 * (hi - lo)))),
                2 - static_cast<int>(std::floor(std::log10(std::max(largest, 1e-300))))});
  if (!log && largest < 1e6 && decimals <= 6) {
    std::vector<std::pair<double, std::string>> ticks;
    for (std::size_t k = 0; k < 3; ++k) {
      char text[40];
      std::snprintf(text, sizeof text, "%.*f", decimals, values[k]);
      ticks.emplace_back(0.5 * static_cast<double>(k), text);
    }
    return ticks;
  }
  // A log bar, or numbers too large or small for decimals: significant digits, as few as
  // tell them apart.
  for (int digits = 3; digits < 17; ++digits) {
    std::array<std::string, 3> texts;
    for (std::size_t k = 0; k < 3; ++k) texts[k] = short_number(values[k], digits);
    if (texts[0] != texts[1] && texts[1] != texts[2])
      return {{0.0, texts[0]}, {0.5, texts[1]}, {1.0, texts[2]}};
  }
  return {{0.0, short_number(lo, 17)}, {0.5, short_number(mid, 17)}, {1.0, short_number(hi, 17)}};
}

MapRect heat_map_cells(int width, int height, std::size_t header_lines, std::size_t count,
                       std::size_t index) {
  const MapRect r = map_region(width, height, header_lines, count, index);
  const double font = map_font(height);
  const double left = r.left + 7.0 * font, top = r.top + 3.2 * font;
  const double right = r.left + r.width - 8.0 * font, bottom = r.top + r.height - 3.0 * font;
  return {left, top, std::max(1.0, right - left), std::max(1.0, bottom - top)};
}

std::array<unsigned char, 3> heat_colour(double fraction) {
  // Six stops of a dark-blue → teal → green → yellow ramp, lightness rising throughout.
  static constexpr std::array<std::array<double, 3>, 6> kStops{
      {{68, 1, 84}, {65, 68, 135}, {42, 120, 142}, {34, 168, 132}, {122, 209, 81}, {253, 231, 37}}};
  const double f = std::clamp(std::isfinite(fraction) ? fraction : 0.0, 0.0, 1.0) * 5.0;
  const int k = std::min(4, static_cast<int>(f));
  const double t = f - k;
  std::array<unsigned char, 3> rgb{};
  for (int c = 0; c < 3; ++c)
    rgb[c] = static_cast<unsigned char>(
        std::lround(kStops[k][c] + t * (kStops[k + 1][c] - kStops[k][c])));
  return rgb;
}

RgbaImage heat_map_sheet(const std::vector<std::string>& header,
                         const std::vector<HeatMapSpec>& maps, int width, int height) {
  RgbaImage image(width, height);
  std::fill(image.pixels.begin(), image.pixels.end(), 255);
  CairoCanvas canvas(width, height);
  cairo_t* cr = canvas.cr();
  const std::vector<std::string> lines = wrap_sheet_header(cr, header, header_font(height), width);
  draw_sheet_header(cr, lines, header_font(height));
  for (std::size_t m = 0; m < maps.size(); ++m) {
    draw_map(cr, maps[m], map_region(width, height, lines.size(), maps.size(), m),
             heat_map_cells(width, height, lines.size(), maps.size(), m), map_font(height));
  }
  canvas.composite_onto(image);
  return image;
}

}  // namespace bookspin::overlay
