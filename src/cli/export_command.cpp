#include <iostream>

#include "cli/commands.hpp"
#include "cli/interrupt.hpp"
#include "jobs/lattice_note.hpp"
#include "products/gltf.hpp"

namespace bookspin::cli {

int export_command(const ExportOptions& options) {
  scene::Scene scene = scene::parse_scene(options.scene_path, options.overrides);
  products::check_gltf_scene(scene);  // before any note or warning about the scene
  for (const std::string& warning : scene.warnings)
    std::cerr << "bookspin: warning: " << warning << '\n';
  if (const std::string note = jobs::lattice_note(scene); !note.empty())
    std::cerr << "bookspin: " << note << '\n';
  const products::GltfExportResult result = products::make_gltf(
      scene, options.out_dir,
      [](const std::string& note) { std::cerr << "bookspin: note: " << note << '\n'; },
      stop_poll());
  if (result.diverged_at) {
    std::cerr << "bookspin: warning: " << scene.name
              << ": simulation diverged at t = " << *result.diverged_at
              << "; the animation stops at the last finite frame\n";
  }
  std::cout << "exported: " << result.path.string() << " (" << result.keyframes << " keyframes, "
            << result.vertices << " vertices)" << std::endl;
  return kExitOk;
}

}  // namespace bookspin::cli
