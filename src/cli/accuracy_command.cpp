// `bookspin accuracy`: builds the request and prints what the pipeline measures.
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "analysis/accuracy.hpp"
#include "cache/freshness.hpp"
#include "cli/commands.hpp"
#include "cli/interrupt.hpp"
#include "cli/subcommand.hpp"
#include "common/errors.hpp"
#include "products/accuracy.hpp"
#include "scene/scene.hpp"

namespace bookspin::cli {
namespace {

struct AccuracyOptions {
  std::string scene_path;
  std::vector<std::string> overrides;
  std::string out_dir = "out";
  double flips = 10.0;
  std::vector<double> dts{1.0 / 15, 1.0 / 30, 1.0 / 60, 1.0 / 120, 1.0 / 240};
  std::string methods = "all";  ///< analysis::parse_methods()
  bool force = false;
  bool verify = false;
};

/// A finite number in [low, high] ((low, high] when `low_open`), printed in short form.
CLI::Validator finite_range(double low, double high, bool low_open = false) {
  const char open = low_open ? '(' : '[';
  char description[64];
  std::snprintf(description, sizeof description, "FINITE in %c%g - %g]", open, low, high);
  return CLI::Validator(
      [low, high, low_open, open](std::string& text) -> std::string {
        double value = 0.0;
        if (CLI::detail::lexical_cast(text, value) && std::isfinite(value) && value >= low &&
            value <= high && !(low_open && value == low))
          return {};
        char message[128];
        std::snprintf(message, sizeof message, "Value %s not a finite number in %c%g, %g]",
                      text.c_str(), open, low, high);
        return message;
      },
      description);
}

/// The range of a scene key's limit (scene/limits.hpp), for an option that stands for it.
CLI::Validator finite_range(const scene::Limit& limit) {
  return finite_range(limit.min, limit.max, limit.min_open);
}

/// An engine among `methods` that cannot run the scene (scene::EngineRefusal: MuJoCo's mjMINVAL,
/// ODE's subnormal dt) refused before anything runs, as `simulate` and `render` refuse it: the
/// scene read again as that engine's (its model.kind and model.integrator set), and only its
/// engine refusal kept (other keys of the scene's own model were read already).
void refuse_what_the_engines_cannot_run(const AccuracyOptions& options, const scene::Scene& scene,
                                        const std::vector<analysis::Method>& methods) {
  for (const analysis::Method& m : methods) {
    if (!physics::is_engine(m.kind) || m.kind == scene.model.kind) continue;
    std::vector<std::string> overrides = options.overrides;
    overrides.push_back("model.kind=\"" + std::string(physics::to_string(m.kind)) + "\"");
    overrides.push_back("model.integrator=\"" + std::string(physics::to_string(m.integrator)) +
                        "\"");
    try {
      scene::parse_scene(options.scene_path, overrides);
    } catch (const scene::EngineRefusal& e) {
      throw InputError("--methods " + m.label + ": " + e.what());
    } catch (const InputError&) {
      // Not an engine limit: the scene's own model was read and checked already.
    }
  }
}

/// Every model × integrator × dt against the exact solution: table on stdout,
/// OUT/<scene>-accuracy.csv and a log-log plot OUT/<scene>-accuracy.png.
int accuracy_command(const AccuracyOptions& options) {
  products::AccuracyJob job;
  job.request.scene = scene::parse_scene(options.scene_path, options.overrides);
  job.request.flips = options.flips;
  job.request.dts = options.dts;
  job.request.methods = analysis::parse_methods(options.methods);
  refuse_what_the_engines_cannot_run(options, job.request.scene, job.request.methods);
  job.request.on_line = [](const std::string& line) {
    std::printf("%s\n", line.c_str());
    std::fflush(stdout);
  };
  job.request.stop_signal = stop_poll();
  job.out_dir = options.out_dir;
  job.freshness = {options.force, options.verify, remake_note};
  const cache::Outcome outcome = products::make_accuracy(job);
  if (outcome == cache::Outcome::up_to_date)
    std::printf("up to date: %s-accuracy\n", job.request.scene.name.c_str());
  if (outcome == cache::Outcome::made)
    for (const auto& path : products::accuracy_layout(job.out_dir, job.request.scene).outputs())
      std::printf("wrote %s\n", path.c_str());
  return kExitOk;
}

}  // namespace

Subcommand add_accuracy(CLI::App& cli) {
  const auto stored = std::make_shared<AccuracyOptions>();
  AccuracyOptions& options = *stored;
  CLI::App* cmd = cli.add_subcommand(
      "accuracy", "Compare every model and integrator with the exact solution over a range of dt");
  cmd->add_option("SCENE", options.scene_path, "Scene file (TOML): book, initial spin, toggles")
      ->required();
  cmd->add_option("--set", options.overrides, kSetHelp)->take_all()->allow_extra_args(false);
  add_out_option(cmd, options.out_dir, "Output directory for the CSV and the plot");
  cmd->add_option("--flips", options.flips, "Run length in exact flip periods")
      ->check(finite_range(1.0, 1000.0))
      ->capture_default_str();
  cmd->add_option("--dt", options.dts, "Time steps to try (time units)")
      ->check(finite_range(scene::limit("time.dt")))
      ->take_all();
  cmd->add_option("--methods", options.methods,
                  "Methods to measure, comma-separated: all, engines, rigid, a model kind "
                  "(every mode of it) or KIND:INTEGRATOR, e.g. engines,rigid-quaternion:rk4")
      ->capture_default_str();
  add_freshness_flags(cmd, options.force, options.verify, "OUT/<scene>/accuracy-manifest.json");
  return {cmd, [stored] { return accuracy_command(*stored); }};
}

}  // namespace bookspin::cli
