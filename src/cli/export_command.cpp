// `bookspin export --gltf`: a scene's body and its motion as an animated glTF binary.
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "analysis/frame_source.hpp"
#include "cache/freshness.hpp"
#include "cli/commands.hpp"
#include "cli/interrupt.hpp"
#include "cli/subcommand.hpp"
#include "jobs/lattice_note.hpp"
#include "products/gltf.hpp"
#include "scene/scene.hpp"

namespace bookspin::cli {
namespace {

struct ExportOptions {
  std::string scene_path;
  std::vector<std::string> overrides;
  std::string out_dir = "out";
  int frames = 0;       ///< --frames: > 0 is appended to `overrides` as time.frames before the run
  bool gltf = false;    ///< --gltf: the only format so far, and required
  bool force = false;   ///< export even when OUT/<scene>/gltf-manifest.json says up to date
  bool verify = false;  ///< up-to-date check hashes the .glb (else its size only)
};

/// Writes OUT/<scene>.glb (products::make_gltf): the body and its motion as animated glTF,
/// unless its manifest says it is up to date.
int export_command(const ExportOptions& options) {
  products::GltfJob job;
  job.scene = scene::parse_scene(options.scene_path, options.overrides);
  const scene::Scene& scene = job.scene;
  products::check_gltf_scene(scene);  // before any note or warning about the scene
  for (const std::string& warning : scene.warnings)
    std::cerr << "bookspin: warning: " << warning << '\n';
  if (const std::string note = jobs::lattice_note(scene); !note.empty())
    std::cerr << "bookspin: " << note << '\n';
  job.out_dir = options.out_dir;
  job.freshness = {options.force, options.verify, remake_note};
  job.on_note = [](const std::string& note) { std::cerr << "bookspin: note: " << note << '\n'; };
  job.stop = stop_poll();
  const products::GltfExportResult result = products::make_gltf(job);
  if (result.outcome == cache::Outcome::up_to_date) {
    std::cout << "up to date: " << scene.name << ".glb" << std::endl;
    return kExitOk;
  }
  if (result.diverged_at) {
    std::cerr << "bookspin: warning: "
              << analysis::divergence_warning(scene.name + ": simulation", *result.diverged_at, "",
                                              "the animation stops at the last finite frame")
              << '\n';
  }
  std::cout << "exported: " << result.path.string() << " (" << result.keyframes << " keyframes, "
            << result.vertices << " vertices)" << std::endl;
  return kExitOk;
}

}  // namespace

Subcommand add_export(CLI::App& cli) {
  const auto stored = std::make_shared<ExportOptions>();
  ExportOptions& options = *stored;
  CLI::App* cmd = cli.add_subcommand(
      "export",
      "Export a scene's body and its motion for other programs: --gltf writes "
      "OUT/<scene>.glb (glTF 2.0 binary, one animation, keyframes at render.fps)");
  cmd->add_option("SCENE", options.scene_path, "Scene file (TOML), one model (no [[compare]])")
      ->required();
  cmd->add_flag("--gltf", options.gltf, "Write OUT/<scene>.glb")->required();
  add_out_option(cmd, options.out_dir, "Output directory");
  cmd->add_option("--set", options.overrides, kSetHelp)->take_all()->allow_extra_args(false);
  cmd->add_option("--frames", options.frames,
                  "Export only the first N frames (overrides time.frames)")
      ->check(CLI::Range(1, scene::kMaxFrames));
  add_freshness_flags(cmd, options.force, options.verify, "OUT/<scene>/gltf-manifest.json");
  return {cmd, [stored] {
            frames_as_override(stored->frames, stored->overrides);
            return export_command(*stored);
          }};
}

}  // namespace bookspin::cli
