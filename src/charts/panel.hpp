#pragma once
// The physics panel: three stacked plots of a run's diagnostics (body-frame ω, relative
// energy drift, shape error) against time, drawn live beside the book in a clip
// (render.panel) and over the whole run by `bookspin plot`.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "charts/diagnostics_history.hpp"
#include "common/colour.hpp"
#include "common/pixel_rect.hpp"
#include "common/rgba_image.hpp"
#include "overlay/plot.hpp"
#include "overlay/sheet.hpp"
#include "scene/scene.hpp"

namespace bookspin::charts {

/// Share of the frame width the book keeps when the panel is shown (the panel has the rest).
inline constexpr double kBookShare = 0.6;

/// How run `index` of a comparison is drawn in the panel's plots: its palette colour, dashed
/// when odd, so that runs in lockstep (one curve) still show both colours.
struct RunStyle {
  Rgb colour;
  bool dashed = false;
};
RunStyle run_style(std::size_t index);

/// The three plots for `runs`: one run shows ω_x, ω_y, ω_z, E/E0 − 1 and its model's shape
/// measures (strain; plus ‖RᵀR − I‖ for a matrix, |q| − 1 for a quaternion); several runs
/// (a comparison) show ω_x, E/E0 − 1 and strain for each, labelled by run. The x axis spans
/// [0, t_end] time units; `cursor` marks the current time.
std::vector<overlay::PlotSpec> panel_plots(const std::vector<PanelRun>& runs, double t_end,
                                           std::optional<double> cursor);

/// The panel column of a width×height frame: the right (1 − kBookShare) of it, inset.
PixelRect panel_rect(int width, int height);

/// The plots of a panel as drawn in its rectangle: one text size for all, at least
/// overlay::kMinFont (12 px) in a panel 360 px wide or wider (a 960 × 540 frame's), scaled
/// down with a narrower panel's width to 9 px; one time axis, named under the lowest plot only;
/// each plot area at least kPanelMinPlotFonts text sizes high and all of them equally high. Plots
/// that would not fit so are left out from the last (the first, ω, is the one a panel is for).
struct PanelLayout {
  std::vector<overlay::PlotSpec> plots;  ///< those kept, their font and left margins set
  std::vector<PixelRect> rects;          ///< where each is drawn (pixels of the frame)
  double font = 0;                       ///< their text size, pixels
};

/// The least height of a panel's plot area, in text sizes.
inline constexpr double kPanelMinPlotFonts = 3.0;

/// Lays `plots` out stacked in `rect` (pixels); no plots where not even the first fits.
PanelLayout panel_layout(const PixelRect& rect, const std::vector<overlay::PlotSpec>& plots);

/// Draws the plots stacked in `rect` of `image` as panel_layout lays them out, on a light
/// translucent background.
void draw_panel(RgbaImage& image, const PixelRect& rect,
                const std::vector<overlay::PlotSpec>& plots);

/// The runs of a single scene, for panel_plots.
std::vector<PanelRun> single_run(const scene::Scene& scene, const DiagnosticsHistory& history);

/// Time of the scene's last frame: (frames − 1) × steps_per_frame × dt, time units.
double clip_end_time(const scene::Scene& scene);

/// Keeps plots of a blow-up readable: each linear y axis spans the values of every run up to
/// its blow-up (`t_blow(series)`, infinite for a run that did not diverge), padded by a
/// tenth, where some curve leaves that range; the overlay marks where it does
/// (overlay::PlotSpec::y_range). Returns whether any axis was clipped.
bool clip_to_range_before(std::vector<overlay::PlotSpec>& plots,
                          const std::function<double(const overlay::Series&)>& t_blow);

/// When the run of `history` blew up: its first sample with |E/E0 − 1| ≥ 1 (the energy
/// doubled or vanished; E is conserved by the exact motion, docs/physics.md §9), or
/// std::nullopt.
std::optional<double> blow_up_time(const DiagnosticsHistory& history);

// A sheet's header and a sheet of plots are drawn by the overlay stage (overlay/sheet.hpp).
using overlay::draw_sheet_header;
using overlay::plot_sheet;
using overlay::wrap_sheet_header;

}  // namespace bookspin::charts
