#include "charts/sweep_plots.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <optional>

#include "charts/heat_map.hpp"
#include "charts/panel.hpp"
#include "overlay/sheet.hpp"

namespace bookspin::charts {

namespace {

constexpr int kSheetWidth = 1280;
/// The tallest sheet: shown whole on a 1366×768 screen, under a browser's bars and a taskbar
/// (about 120 pixels; docs/outputs.md, "Pictures").
constexpr int kMaxSheetHeight = 640;
constexpr int kHeaderHeight = 120;
constexpr int kPlotRowHeight = 300;    ///< a row of two line plots, at most
constexpr int kMapHeightPerRow = 560;  ///< a row of two heat maps, at most

/// Rows of `count` pictures two a row (one alone on its row), each at most `most` pixels tall,
/// under the header, within kMaxSheetHeight: the sheet's height, even.
int sheet_height(std::size_t count, int most) {
  const int rows = static_cast<int>((count + 1) / 2);
  const int row = rows == 0 ? 0 : std::min(most, (kMaxSheetHeight - kHeaderHeight) / rows);
  const int height = kHeaderHeight + row * rows;
  return height + height % 2;
}

/// A cell as a number: NaN where it is empty (a measure the run did not reach).
double number(const std::string& text) {
  if (text.empty()) return std::nan("");
  return std::strtod(text.c_str(), nullptr);
}

/// The header lines of the picture: the sweep, then its ranges.
std::vector<std::string> sheet_header(const SweepChart& chart) {
  // Points the engine refused (the `refused` column, jobs/sweep_csv.hpp): counted, the first
  // reason shown; their measures are gaps in the plots and maps.
  std::size_t refused = 0;
  std::string first_reason;
  const auto column = std::find(chart.header.begin(), chart.header.end(), "refused");
  if (column != chart.header.end()) {
    const auto c = static_cast<std::size_t>(column - chart.header.begin());
    for (const auto& row : chart.rows) {
      if (c >= row.size() || row[c].empty()) continue;
      if (refused++ == 0) first_reason = row[c];
    }
  }
  char text[320];
  // The scene's title leads, alone on its line; the sweep (its name, as in the files' names)
  // and its runs follow on the next.
  std::vector<std::string> lines;
  if (!chart.scene_title.empty()) lines.push_back(chart.scene_title);
  std::string head = (lines.empty() ? "Sweep of " : "sweep of ") + chart.scene_name;
  std::snprintf(text, sizeof text, ": %zu runs", chart.rows.size() - refused);
  head += text;
  if (refused > 0) {
    std::snprintf(text, sizeof text, ", %zu %s refused by the engine", refused,
                  refused == 1 ? "point" : "points");
    head += text;
  }
  lines.push_back(head);
  if (refused > 0)
    lines.push_back("refused" + std::string(refused > 1 ? " (the first)" : "") + ": " +
                    first_reason);
  for (const SweepAxis& a : chart.axes) {
    std::snprintf(text, sizeof text, "varied: %s, from %.6g to %.6g, %d values%s",
                  a.caption.c_str(), a.start, a.stop, static_cast<int>(a.values.size()),
                  a.log ? " (log spaced)" : "");
    lines.emplace_back(text);
  }
  return lines;
}

}  // namespace

std::vector<overlay::PlotSpec> sweep_plots(const SweepChart& chart) {
  const std::size_t keys = chart.axes.size();
  // Rows grouped by the values of the keys after the first (as written, so values that
  // print alike at 6 digits stay apart), groups in order of appearance.
  std::vector<std::string> group_names;
  std::vector<std::vector<std::size_t>> groups;
  std::map<std::string, std::size_t> group_of;
  for (std::size_t r = 0; r < chart.rows.size(); ++r) {
    std::string key, name;
    for (std::size_t k = 1; k < keys; ++k) {
      const std::string& cell_text = chart.rows[r][k];
      key += cell_text + ",";
      char value[40];
      std::snprintf(value, sizeof value, "%.6g", number(cell_text));
      if (k > 1) name += ", ";
      name += chart.axes[k].words + " = " + value;
    }
    const auto [it, added] = group_of.emplace(key, groups.size());
    if (added) {
      group_names.push_back(name);
      groups.emplace_back();
    }
    groups[it->second].push_back(r);
  }
  std::vector<overlay::PlotSpec> plots;
  for (std::size_t m = 0; m < chart.measures.size(); ++m) {
    const std::string column(chart.measures[m]->name);
    const std::size_t col = keys + m;
    std::optional<std::size_t> exact_col;
    for (std::size_t c = keys + chart.measures.size(); c < chart.header.size(); ++c)
      if (chart.header[c] == column + "_exact") exact_col = c;
    overlay::PlotSpec spec;
    // The measure in words (its axis label, unit and all), its CSV column second.
    // (The legend tells the measured line, solid, from the exact one, dashed.)
    spec.title = std::string(chart.measures[m]->axis_label) + " \u00b7 " + column;
    spec.x_label = chart.axes[0].caption + (chart.axes[0].log ? " (log scale)" : "");
    spec.y_label = std::string(chart.measures[m]->axis_label);
    spec.log_x = chart.axes[0].log;
    spec.log_y = chart.measures[m]->log_scale;
    spec.legend = true;
    // A third key's lines name two values each: their legend in rows above the plot, which
    // keeps the width of a plot two a row.
    if (keys > 1) spec.legend_placement = overlay::LegendPlacement::top;
    for (std::size_t g = 0; g < groups.size(); ++g) {
      overlay::Series measured, exact;
      measured.label = group_names[g].empty() ? "measured" : group_names[g];
      exact.label = group_names[g].empty() ? "exact model" : "exact, " + group_names[g];
      overlay::palette_colour(static_cast<int>(g), measured.r, measured.g, measured.b);
      exact.r = measured.r * 0.3;
      exact.g = measured.g * 0.3;
      exact.b = measured.b * 0.3;
      exact.dashed = true;
      for (std::size_t r : groups[g]) {
        const auto& cells = chart.rows[r];
        measured.x.push_back(number(cells[0]));
        measured.y.push_back(number(cells[col]));
        if (exact_col) {
          exact.x.push_back(number(cells[0]));
          exact.y.push_back(number(cells[*exact_col]));
        }
      }
      spec.series.push_back(std::move(measured));
      if (exact_col) spec.series.push_back(std::move(exact));  // dashed, on top
    }
    plots.push_back(std::move(spec));
  }
  return plots;
}

RgbaImage sweep_sheet(const SweepChart& chart) {
  // The sheet's description (its size from the measures, a plot or a map each), drawn by the
  // overlay stage in one call: for two keys one heat map per measure, the first key on x.
  const std::size_t pictures = chart.measures.size();
  const bool maps = chart.axes.size() == 2;
  overlay::SheetSpec sheet;
  sheet.width = kSheetWidth;
  sheet.height = sheet_height(pictures, maps ? kMapHeightPerRow : kPlotRowHeight);
  sheet.columns = pictures > 1 ? 2 : 1;
  sheet.header = sheet_header(chart);
  if (maps)
    sheet.maps = captioned_heat_maps(chart.axes[0].caption, chart.axes[1].caption, chart.rows,
                                     chart.axes[0].values, chart.axes[0].log, chart.axes[1].values,
                                     chart.axes[1].log, chart.measures);
  else
    sheet.plots = sweep_plots(chart);
  return overlay::draw_sheet(sheet);
}

}  // namespace bookspin::charts
