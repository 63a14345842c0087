#include "cache/manifest_head.hpp"

#include <sstream>

#include "common/errors.hpp"
#include "common/json_string.hpp"
#include "output/manifest.hpp"
#include "output/sha256.hpp"
#include "scene/canonical.hpp"

namespace bookspin::cache {

namespace fs = std::filesystem;

namespace {

std::string hash_of(const std::string& role, const std::string& path) {
  const auto hash = output::sha256_file(path);
  if (!hash) throw InputError(path + ": cannot read the " + role + " file");
  return "\"sha256:" + *hash + "\"";
}

/// "inputs": every file the scene reads as bytes (its textures, its mesh), by key, with their
/// SHA-256.
std::string inputs_json(const scene::Scene& scene) {
  std::vector<std::pair<std::string, std::string>> files;
  const auto& r = scene.render;
  for (const auto& [key, path] : {std::pair{"render.texture_front", &r.texture_front},
                                  {"render.texture_back", &r.texture_back},
                                  {"render.texture_spine", &r.texture_spine},
                                  {"render.texture_pages", &r.texture_pages}}) {
    if (!path->empty()) files.emplace_back(key, *path);
  }
  if (!scene.body_mesh.empty()) files.emplace_back("body.mesh", scene.body_mesh);
  std::ostringstream out;
  out << "  \"inputs\": {";
  for (std::size_t i = 0; i < files.size(); ++i) {
    out << (i == 0 ? "\n" : ",\n") << "    " << json_string(files[i].first) << ": "
        << hash_of(files[i].first, files[i].second);
  }
  out << (files.empty() ? "},\n" : "\n  },\n");
  return out.str();
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
  return output::sha256_text(bytes);
}

}  // namespace

std::string manifest_head(const std::string& command, const std::string& options,
                          const scene::Scene& scene) {
  std::ostringstream out;
  out << "  \"manifest\": 1,\n"
      << "  \"command\": " << json_string(command) << ",\n"
      << "  \"bookspin\": {\"version\": " << json_string(output::program_version())
      << ", \"build_id\": \"sha256:" << output::program_build_id() << "\"},\n"
      << "  \"options\": {\n"
      << options << "  },\n"
      << "  \"scene\": {\n"
      << scene::canonical_json(scene, 4) << "  },\n";
  if (const std::string surface = surface_hash(scene.body); !surface.empty())
    out << "  \"body_surface\": \"sha256:" << surface << "\",\n";
  out << inputs_json(scene);
  return out.str();
}

std::string manifest_note(const scene::Scene& scene) {
  std::error_code ec;
  const fs::path path = fs::weakly_canonical(scene.source, ec);
  return "  \"scene_file\": {\"path\": " + json_string((ec ? scene.source : path).string()) +
         ", \"sha256\": " + hash_of("scene", scene.source.string()) + "},\n";
}

}  // namespace bookspin::cache
