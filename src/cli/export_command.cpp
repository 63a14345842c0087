// `bookspin export --gltf`: a scene's body and its motion as an animated glTF binary.
#include <iostream>

#include "analysis/frame_source.hpp"
#include "cache/freshness.hpp"
#include "cli/commands.hpp"
#include "cli/interrupt.hpp"
#include "jobs/lattice_note.hpp"
#include "products/gltf.hpp"

namespace bookspin::cli {

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

}  // namespace bookspin::cli
