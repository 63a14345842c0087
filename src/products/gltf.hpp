#pragma once
// The glTF product (`bookspin export --gltf`): a scene's run as an animated glTF binary
// (docs/outputs.md, "glTF export"): the body's surface in its own frame and one animation of
// its pose. Not cached: every export writes it anew.
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "common/stop.hpp"
#include "scene/scene.hpp"

namespace bookspin::products {

struct GltfExportResult {
  std::filesystem::path path;         ///< OUT/<name>.glb
  int keyframes = 0;                  ///< one per frame produced (all of them unless it diverged)
  int vertices = 0;                   ///< vertices written, over every part
  std::optional<double> diverged_at;  ///< when the simulation diverged (keyframes stop there)
};

/// OUT/<name>.glb, the one file an export of `scene` into `out_dir` writes.
std::filesystem::path gltf_path(const std::filesystem::path& out_dir, const scene::Scene& scene);

/// Throws InputError when `scene` cannot be exported (a comparison scene: no single motion).
/// make_gltf() checks it first too; a command calls it before it prints anything about the
/// scene, so that no note comes before an error that makes it moot.
void check_gltf_scene(const scene::Scene& scene);

/// Runs `scene` frame by frame and writes gltf_path(out_dir, scene) with output::write_glb: the
/// book with its four face images (render::face_images, the scene's textures or the generated
/// covers), a preset or mesh body with one material per colour; keyframe k at k / render.fps
/// seconds with the rotation of Simulator::orientation() (unit quaternion, body→world, signs
/// kept continuous from frame to frame) and the centre of mass as translation. A deforming
/// model (particle, lattice) exports its best-fit rigid motion: `on_note` is told so.
/// `stop` is polled before each frame ("export frames") and once more before the file is
/// written ("export write"): a signal throws Interrupted, and the previous file stays.
/// Throws InputError for a comparison scene (no single motion), render::RenderError for a
/// missing texture or font, OutputError if the file cannot be written.
GltfExportResult make_gltf(const scene::Scene& scene, const std::filesystem::path& out_dir,
                           const std::function<void(const std::string&)>& on_note = {},
                           const StopPoll& stop = {});

}  // namespace bookspin::products
