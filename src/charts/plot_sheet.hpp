#pragma once
// A run's diagnostics over its whole length as one picture (`bookspin plot`): the panel's
// curves without the cursor, for papers and slides.
#include <filesystem>
#include <string>
#include <vector>

#include "overlay/plot.hpp"
#include "scene/scene.hpp"

namespace bookspin::charts {

struct PlotRequest {
  scene::Scene scene;         ///< a single or a comparison scene (every tile is plotted)
  std::filesystem::path png;  ///< the sheet's file (the plot product names it)
  int width = 1600;           ///< pixels
  int height = 1000;          ///< pixels
};

/// What a plot sheet shows: its header lines and its plots.
struct PlotSheet {
  std::vector<std::string> lines;        ///< title, model line or tiles, divergences, notes
  std::vector<overlay::PlotSpec> plots;  ///< body-frame ω (a comparison: ω about the
                                         ///< intermediate axis), E/E0 − 1, shape error
};

/// Simulates the scene (every tile of a comparison) to its end or divergence and lays out
/// its sheet (no drawing, no files).
PlotSheet plot_sheet_for(const scene::Scene& scene);

/// Simulates the scene (every tile of a comparison) to its end or divergence and writes
/// request.png: a header (title, model line, divergences) and the panel's plots
/// (body-frame ω, E/E0 − 1, shape error) against time. Throws OutputError.
void write_plot_sheet(const PlotRequest& request);

}  // namespace bookspin::charts
