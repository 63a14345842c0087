#pragma once
// A sheet: a white picture with a header of lines on top (the first bold) and, under it, plots
// (plot_sheet) or heat maps (heat_map.hpp), each drawn from its description in one call.
#include <cairo.h>

#include <string>
#include <vector>

#include "common/rgba_image.hpp"
#include "overlay/heat_map.hpp"
#include "overlay/plot.hpp"
#include "overlay/sheet_header.hpp"

namespace bookspin::overlay {

/// A white width×height image: `header` lines on top (the first bold), the plots below in
/// `columns` columns (1: stacked), row by row, each row an equal share of the height left.
RgbaImage plot_sheet(const std::vector<std::string>& header, const std::vector<PlotSpec>& plots,
                     int width, int height, int columns = 1);

/// What a sheet shows: its header lines, then heat maps (two a row: heat_map_sheet) where it
/// has any, else its plots in `columns` columns (plot_sheet); width × height pixels.
struct SheetSpec {
  std::vector<std::string> header;
  std::vector<HeatMapSpec> maps;
  std::vector<PlotSpec> plots;
  int columns = 1;
  int width = 0, height = 0;
};

/// The sheet `sheet` describes, drawn in one call.
RgbaImage draw_sheet(const SheetSpec& sheet);

}  // namespace bookspin::overlay
