#pragma once
// A run's diagnostics over its whole length as one picture (`bookspin plot`): the panel's
// curves without the cursor, for papers and slides.
#include <string>
#include <vector>

#include "analysis/frame_source.hpp"
#include "common/rgba_image.hpp"
#include "overlay/plot.hpp"
#include "scene/scene.hpp"

namespace bookspin::charts {

/// What a plot sheet shows: its header lines and its plots.
struct PlotSheet {
  std::vector<std::string> lines;        ///< title, model line or tiles, divergences, notes
  std::vector<overlay::PlotSpec> plots;  ///< body-frame ω (a comparison: ω about the
                                         ///< intermediate axis), E/E0 − 1, shape error
};

/// The sheet of `scene` from its runs (analysis::run_frames: one, or one per tile of a
/// comparison): a header (title, model line or tiles, divergences) and the panel's plots
/// (body-frame ω, E/E0 − 1, shape error) against time. No drawing, no files.
PlotSheet plot_sheet_for(const scene::Scene& scene, const std::vector<analysis::RunFrames>& runs);

/// (scene, runs) => the sheet of plot_sheet_for() drawn, `width` × `height` pixels. No files.
RgbaImage plot_sheet_image(const scene::Scene& scene, const std::vector<analysis::RunFrames>& runs,
                           int width, int height);

}  // namespace bookspin::charts
