#include "charts/plot_sheet.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <map>
#include <sstream>

#include "charts/decoration.hpp"
#include "charts/panel.hpp"

namespace bookspin::charts {

namespace {

/// One run, start to end (or divergence), as the panel's curves.
struct Run {
  const scene::Scene& scene;
  DiagnosticsHistory history;
  std::optional<double> diverged_at;
  const std::string& model_line;  ///< analysis::RunFrames::model_line
};

std::vector<Run> histories_of(const std::vector<analysis::RunFrames>& runs) {
  std::vector<Run> histories;
  for (const auto& run : runs) {
    histories.push_back({run.scene, {}, run.diverged_at, run.model_line});
    for (const physics::Diagnostics& d : run.frames) histories.back().history.add(d);
  }
  return histories;
}

/// Title, then what was run: the model line (or the tiles), and any divergence.
std::vector<std::string> header(const scene::Scene& scene, const std::vector<Run>& runs) {
  std::vector<std::string> lines{scene.title};
  if (scene.compare.empty()) {
    lines.push_back(runs.front().model_line);
  } else {
    std::string tiles = "comparison:";
    for (const auto& run : runs) tiles += (&run == &runs.front() ? " " : " · ") + run.scene.title;
    lines.push_back(tiles);
  }
  for (const auto& run : runs) {
    if (!run.diverged_at) continue;
    lines.push_back((scene.compare.empty() ? "" : run.scene.title + ": ") +
                    divergence_text(*run.diverged_at) + " (the curves end there)");
  }
  return lines;
}

/// When a diverged run blew up: its first sample with |E/E0 − 1| ≥ 1 (the energy doubled or
/// vanished; E is conserved by the exact motion, docs/physics.md §9), else where it diverged.
/// std::nullopt for a run that did not diverge.
std::optional<double> blow_up_time(const Run& run) {
  if (!run.diverged_at) return std::nullopt;
  return charts::blow_up_time(run.history).value_or(*run.diverged_at);
}

}  // namespace

PlotSheet plot_sheet_for(const scene::Scene& scene,
                         const std::vector<analysis::RunFrames>& frames) {
  const std::vector<Run> runs = histories_of(frames);
  std::vector<PanelRun> panel_runs;
  for (const auto& run : runs) panel_runs.emplace_back(run.scene, run.history, run.scene.title);
  auto plots = panel_plots(panel_runs, clip_end_time(scene), std::nullopt);
  // A comparison's series are labelled with their run's title (panel.cpp).
  std::map<std::string, double> blow_ups;
  std::optional<double> first;
  for (const auto& run : runs) {
    const auto t = blow_up_time(run);
    blow_ups[run.scene.title] = t.value_or(std::numeric_limits<double>::infinity());
    if (t && (!first || *t < *first)) first = t;
  }
  const auto t_blow = [&](const overlay::Series& s) {
    if (runs.size() == 1) return blow_ups.begin()->second;
    const auto it = blow_ups.find(s.label);
    return it == blow_ups.end() ? std::numeric_limits<double>::infinity() : it->second;
  };
  auto lines = header(scene, runs);
  if (first && clip_to_range_before(plots, t_blow)) {
    std::ostringstream note;
    note << "the y axes show the range before the blow-up (|E/E\u2080 \u2212 1| \u2265 1, "
         << (runs.size() == 1 ? "" : "first ") << "at t = " << std::setprecision(4) << *first
         << "); \u25B2 \u25BC mark where a curve leaves it";
    lines.push_back(note.str());
  }
  return {std::move(lines), std::move(plots)};
}

RgbaImage plot_sheet_image(const scene::Scene& scene, const std::vector<analysis::RunFrames>& runs,
                           int width, int height) {
  const PlotSheet sheet = plot_sheet_for(scene, runs);
  return plot_sheet(sheet.lines, sheet.plots, width, height);
}

}  // namespace bookspin::charts
