#pragma once
// A scene in canonical form: every key of the resolved Scene (after --set overrides and
// defaults), one per line, in a fixed order, numbers printed so that they read back to the
// same double. Two scene files that differ only in comments, layout, key order, number
// spelling (1.0 vs 1) or keys set to their default value give the same text.
#include <string>

#include "common/json_writer.hpp"
#include "scene/scene.hpp"

namespace bookspin::scene {

/// The scene as the members of a JSON object, in a fixed order. Keys are the scene
/// file's dotted keys (scenes/README.md) as resolved: initial.spin_axis and spin_rate appear
/// as initial.angular_velocity, body.mass and body.scale as the body's moments, volume and
/// cage (book.size, book.mass); comparison tiles are `compare[i].key`. Texture and mesh
/// paths are written relative to the scene file's folder, so the text does not depend on
/// where the checkout lives. Numbers: the first of %.15g, %.16g, %.17g that reads back
/// (NumberStyle::fewest_g), JSON-valid.
/// model.normalize_every is listed only where it is not 1 (normalizing every step), so that
/// the manifests written before the key existed still match, and measured.omega only where
/// given (the file's bytes are the manifests' inputs), model.drag and model.drag_rate only
/// with drag, time.unit only where given; time.duration appears as the time.frames it gives.
JsonObject canonical_scene(const Scene& scene);

/// canonical_scene() as text: one `"key": value` per line, each line indented by `indent`
/// spaces and all but the last ending in ',' (json_member_lines: the lines of a manifest's
/// "scene" object, or with indent 0 what a sweep shard hashes).
std::string canonical_json(const Scene& scene, int indent = 4);

}  // namespace bookspin::scene
