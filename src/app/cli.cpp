#include <CLI/CLI.hpp>
#include <iostream>

#include "app/commands.hpp"
#include "scene/scene.hpp"
#include "video/atomic_output.hpp"

namespace bookspin::app {

namespace {

constexpr const char* kSetHelp =
    "Override a scene key, value in TOML syntax (repeatable), e.g. --set time.dt=0.01 "
    "--set model.kind='\"rigid-matrix\"' --set book.size=[1,2,0.5]";

void add_simulate(CLI::App& cli, SimulateOptions& options) {
  CLI::App* cmd = cli.add_subcommand(
      "simulate", "Run a scene's simulation without rendering and write the diagnostics CSV");
  cmd->add_option("SCENE", options.scene_path, "Scene file (TOML)")->required();
  cmd->add_option("--set", options.overrides, kSetHelp)->take_all()->allow_extra_args(false);
  cmd->add_option("--csv", options.csv_path,
                  "Output CSV, one row per frame (frame 0 = initial state); '-' for stdout")
      ->capture_default_str();
}

int report(const std::string& message, int code) {
  std::cerr << "bookspin: error: " << message << '\n';
  return code;
}

}  // namespace

int run_cli(int argc, char** argv) {
  CLI::App cli{"bookspin: simulate and render the unstable rotation of a book", "bookspin"};
  cli.require_subcommand(1);
  SimulateOptions simulate;
  add_simulate(cli, simulate);
  try {
    cli.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return cli.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return cli.exit(e);
  } catch (const CLI::ParseError& e) {
    return report(std::string(e.what()) + " (see bookspin --help)", kExitUsage);
  }
  try {
    if (cli.got_subcommand("simulate")) return simulate_command(simulate);
  } catch (const scene::SceneError& e) {
    return report(e.what(), kExitUsage);
  } catch (const video::OutputError& e) {
    return report(e.what(), kExitFailure);
  } catch (const std::exception& e) {
    return report(e.what(), kExitFailure);
  }
  return kExitOk;
}

}  // namespace bookspin::app
