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

/// `header` as a sheet `width` pixels wide draws it: the first line (the bold title, at `font`)
/// whole where it fits in width − 2·font, else as many of its words as fit, the rest leading
/// the next line; each line after it broken at spaces where it would run past width − 2·font
/// (drawn at 0.8·font from x = font): a list ("a · b · c") between its items, the dot kept at
/// the line's end, other text between words; an item or word longer than that on a line of
/// its own.
std::vector<std::string> wrap_sheet_header(cairo_t* cr, const std::vector<std::string>& header,
                                           double font, double width);

/// Draws a sheet's `header` lines on `cr` from its top, the first bold at `font` pixels, the
/// others regular at 0.8·font, 1.35 line heights apart; returns the last line's baseline (y,
/// pixels).
double draw_sheet_header(cairo_t* cr, const std::vector<std::string>& header, double font);

/// A white width×height image: `header` lines on top (the first bold), the plots below in
/// `columns` columns (1: stacked), row by row, each row an equal share of the height left.
RgbaImage plot_sheet(const std::vector<std::string>& header,
                     const std::vector<overlay::PlotSpec>& plots, int width, int height,
                     int columns = 1);

}  // namespace bookspin::charts
