// `bookspin plot`: the panel's curves over a whole run, as a PNG for papers and slides.
#include <iostream>
#include <memory>

#include "app/commands.hpp"
#include "app/frame_source.hpp"
#include "app/frame_view.hpp"
#include "app/panel_plots.hpp"
#include "video/atomic_output.hpp"
#include "video/png_writer.hpp"

namespace bookspin::app {

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
  for (const auto& panel : scene.compare)
    runs.push_back(simulate(scene::panel_scene(scene, panel)));
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

int plot_command(const PlotOptions& options) {
  const scene::Scene scene = scene::parse_scene(options.scene_path, options.overrides);
  const std::vector<Run> runs = simulate_all(scene);
  std::vector<PanelRun> panel_runs;
  for (const auto& run : runs)
    panel_runs.push_back({run.scene.title, run.scene.model.kind, &run.history});
  const auto plots = panel_plots(panel_runs, clip_end_time(scene), std::nullopt);
  const auto path = std::filesystem::path(options.out_dir) / (scene.name + "-plot.png");
  std::error_code ec;
  std::filesystem::create_directories(options.out_dir, ec);
  if (ec) video::throw_output_error("cannot create output directory", options.out_dir, ec.value());
  video::write_png(path, plot_sheet(header(scene, runs), plots, options.width, options.height));
  std::cout << "wrote " << path.string() << '\n';
  return kExitOk;
}

}  // namespace bookspin::app
