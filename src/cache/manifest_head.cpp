#include "cache/manifest_head.hpp"

#include "common/errors.hpp"
#include "common/sha256.hpp"
#include "output/manifest.hpp"
#include "output/sha256.hpp"
#include "scene/canonical.hpp"

namespace bookspin::cache {

namespace fs = std::filesystem;

namespace {

std::string hash_of(const std::string& role, const std::string& path) {
  const auto hash = output::sha256_file(path);
  if (!hash) throw InputError(path + ": cannot read the " + role + " file");
  return "sha256:" + *hash;
}

/// "inputs": every file the scene reads as bytes (its textures, its mesh), by key, with their
/// SHA-256.
JsonValue inputs_json(const scene::Scene& scene) {
  std::vector<std::pair<std::string, std::string>> files;
  const auto& r = scene.render;
  for (const auto& [key, path] : {std::pair{"render.texture_front", &r.texture_front},
                                  {"render.texture_back", &r.texture_back},
                                  {"render.texture_spine", &r.texture_spine},
                                  {"render.texture_pages", &r.texture_pages}}) {
    if (!path->empty()) files.emplace_back(key, *path);
  }
  if (!scene.body_mesh.empty()) files.emplace_back("body.mesh", scene.body_mesh);
  if (!scene.measured.file.empty()) files.emplace_back("measured.omega", scene.measured.file);
  JsonObject inputs;
  for (const auto& [key, path] : files) inputs.push_back({key, {hash_of(key, path)}});
  const bool lines = !inputs.empty();  // "{}" when the scene reads no file
  return {std::move(inputs), lines};
}

/// SHA-256 of the body's surface as simulated and drawn (vertices, triangles, face colours in
/// the principal frame, docs/physics.md §12), "" for the book: a mesh file written again with
/// the same geometry is the same body.
std::string surface_hash(const physics::Body& body) {
  if (body.vertices.size() == 0) return "";
  std::string bytes;
  const auto add = [&bytes](const void* data, std::size_t size) {
    bytes.append(static_cast<const char*>(data), size);
  };
  add(body.vertices.data(), sizeof(double) * static_cast<std::size_t>(body.vertices.size()));
  add(body.triangles.data(), sizeof(int) * static_cast<std::size_t>(body.triangles.size()));
  add(body.face_colours.data(), sizeof(float) * static_cast<std::size_t>(body.face_colours.size()));
  return sha256_text(bytes);
}

}  // namespace

JsonValue input_files_json(const std::vector<std::filesystem::path>& files) {
  JsonArray entries;
  for (const fs::path& file : files) {
    entries.push_back({JsonObject{{"file", {file.filename().string()}},
                                  {"sha256", {hash_of("input", file.string())}}}});
  }
  return {std::move(entries), true};
}

std::string manifest_head(const std::string& command, const JsonObject& members) {
  JsonObject head{{"manifest", {std::int64_t{1}}}, {"command", {command}}};
  head.insert(head.end(), members.begin(), members.end());
  return json_member_lines(head, "manifest head", 2, false);
}

std::string manifest_head(const std::string& command, const JsonObject& options,
                          const scene::Scene& scene) {
  JsonObject head{{"bookspin",
                   {JsonObject{{"version", {output::program_version()}},
                               {"build_id", {"sha256:" + output::program_build_id()}}}}},
                  {"options", {options, true}},
                  {"scene", {scene::canonical_scene(scene), true}}};
  if (const std::string surface = surface_hash(scene.body); !surface.empty())
    head.push_back({"body_surface", {"sha256:" + surface}});
  head.push_back({"inputs", inputs_json(scene)});
  return manifest_head(command, head);
}

std::string manifest_note(const scene::Scene& scene) {
  std::error_code ec;
  const fs::path path = fs::weakly_canonical(scene.source, ec);
  const JsonObject file{{"path", {(ec ? scene.source : path).string()}},
                        {"sha256", {hash_of("scene", scene.source.string())}}};
  return json_member_lines({{"scene_file", {file}}}, "manifest note", 2, false);
}

}  // namespace bookspin::cache
