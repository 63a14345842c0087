#include "pipeline/plot_sheet_run.hpp"

#include "output/output_dir.hpp"
#include "output/png_writer.hpp"
#include "pipeline/decoration.hpp"
#include "pipeline/frame_source.hpp"
#include "pipeline/panel.hpp"

namespace bookspin::pipeline {

namespace {

/// One simulated run, start to end (or divergence).
struct Run {
  scene::Scene scene;
  DiagnosticsHistory history;
  std::optional<double> diverged_at;
};

Run simulate(const scene::Scene& scene) {
  Run run{scene, {}, std::nullopt};
  FrameSource source(run.scene);
  physics::BookPose pose;
  while (source.next(pose)) run.history.add(pose.diagnostics);
  run.diverged_at = source.diverged_at();
  return run;
}

std::vector<Run> simulate_all(const scene::Scene& scene) {
  std::vector<Run> runs;
  if (scene.compare.empty()) runs.push_back(simulate(scene));
  for (const auto& panel : scene.compare) runs.push_back(simulate(scene::tile_scene(scene, panel)));
  return runs;
}

/// Title, then what was run: the model line (or the panels), and any divergence.
std::vector<std::string> header(const scene::Scene& scene, const std::vector<Run>& runs) {
  std::vector<std::string> lines{scene.title};
  if (scene.compare.empty()) {
    lines.push_back(model_line(scene));
  } else {
    std::string panels = "comparison:";
    for (const auto& run : runs) panels += (&run == &runs.front() ? " " : " · ") + run.scene.title;
    lines.push_back(panels);
  }
  for (const auto& run : runs) {
    if (!run.diverged_at) continue;
    lines.push_back((scene.compare.empty() ? "" : run.scene.title + ": ") +
                    divergence_text(*run.diverged_at) + " (the curves end there)");
  }
  return lines;
}

}  // namespace

std::filesystem::path write_plot_sheet(const PlotRequest& request) {
  const scene::Scene& scene = request.scene;
  const std::vector<Run> runs = simulate_all(scene);
  std::vector<PanelRun> panel_runs;
  for (const auto& run : runs)
    panel_runs.push_back({run.scene.title, run.scene.model.kind, &run.history});
  const auto plots = panel_plots(panel_runs, clip_end_time(scene), std::nullopt);
  const auto path = request.out_dir / (scene.name + "-plot.png");
  output::prepare_output_dir(request.out_dir);
  output::write_png(path, plot_sheet(header(scene, runs), plots, request.width, request.height));
  return path;
}

}  // namespace bookspin::pipeline
