#pragma once
// The glTF product (`bookspin export --gltf`): a scene's run as an animated glTF binary
// (docs/outputs.md, "glTF export"): the body's surface in its own frame and one animation of
// its pose, with its manifest, so that an unchanged export is not made again. Every path it
// writes is named here.
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "cache/freshness.hpp"
#include "common/stop.hpp"
#include "scene/scene.hpp"

namespace bookspin::products {

/// Every path an export of one scene into OUT writes.
struct GltfLayout {
  std::filesystem::path glb;       ///< OUT/<name>.glb
  std::filesystem::path manifest;  ///< OUT/<name>/gltf-manifest.json
};

/// The layout of `scene`'s export in `out_dir`. No I/O.
GltfLayout gltf_layout(const std::filesystem::path& out_dir, const scene::Scene& scene);

/// What `bookspin export --gltf` asks for.
struct GltfJob {
  scene::Scene scene;  ///< one model (no [[compare]]); --frames is its time.frames
  std::filesystem::path out_dir;
  cache::Freshness freshness;  ///< --force, --verify (the .glb's hash) and the remake note
  /// Told that a deforming model exports its best-fit rigid motion (may be empty).
  std::function<void(const std::string&)> on_note;
  /// Polled before each frame ("export frames") and before the file is written ("export
  /// write"). May be empty.
  StopPoll stop;
};

struct GltfExportResult {
  cache::Outcome outcome = cache::Outcome::made;  ///< up to date: nothing below is measured
  std::filesystem::path path;                     ///< OUT/<name>.glb
  int keyframes = 0;                  ///< one per frame produced (all of them unless it diverged)
  int vertices = 0;                   ///< vertices written, over every part
  std::optional<double> diverged_at;  ///< when the simulation diverged (keyframes stop there)
};

/// Throws InputError when `scene` cannot be exported (a comparison scene: no single motion).
/// make_gltf() checks it first too; a command calls it before it prints anything about the
/// scene, so that no note comes before an error that makes it moot.
void check_gltf_scene(const scene::Scene& scene);

/// The manifest head of `job` ("export", the format "glb", the scene). Throws InputError.
std::string gltf_manifest_head(const GltfJob& job);

/// (scene) => OUT/<scene>.glb + manifest.
/// Unless its manifest says it is up to date, runs the scene frame by frame and writes
/// gltf_layout(out_dir, scene).glb with output::write_glb, then the manifest: the book with
/// its four face images (render::face_images, the scene's textures or the generated covers),
/// a preset or mesh body with one material per colour; keyframe k at k / render.fps seconds
/// with the rotation of Simulator::orientation() (unit quaternion, body→world, signs kept
/// continuous from frame to frame) and the centre of mass as translation. A deforming model
/// (particle, lattice) exports its best-fit rigid motion: `on_note` is told so. A signal
/// seen by `stop` throws Interrupted, and the previous file and its manifest stay. Throws
/// InputError for a comparison scene (no single motion), render::RenderError for a missing
/// texture or font, OutputError if the file cannot be written.
GltfExportResult make_gltf(const GltfJob& job);

}  // namespace bookspin::products
