#include "scene/canonical.hpp"

#include <cstdint>

namespace bookspin::scene {

namespace {

/// A double that reads back to itself, in the canonical style ("%.15g" where it reads back).
JsonValue number(double value) { return {JsonNumber{value, NumberStyle::fewest_g}}; }

JsonValue integer(std::int64_t value) { return {value}; }

JsonValue text(const std::string& value) { return {value}; }

JsonValue vector3(const Eigen::Vector3d& v) {
  return {JsonArray{number(v.x()), number(v.y()), number(v.z())}};
}

/// A file the scene names (texture, mesh), relative to the scene file's folder.
JsonValue texture(const std::string& path, const std::filesystem::path& source) {
  if (path.empty()) return text("");
  const std::filesystem::path folder = source.parent_path().empty() ? "." : source.parent_path();
  return text(std::filesystem::path(path).lexically_relative(folder).generic_string());
}

void add_model(JsonObject& m, const std::string& prefix, const physics::ModelConfig& model) {
  m.push_back({prefix + "kind", text(std::string(physics::to_string(model.kind)))});
  m.push_back({prefix + "integrator", text(std::string(physics::to_string(model.integrator)))});
  m.push_back({prefix + "normalize", {model.normalize}});
  // Listed only where it is not 1, so that the manifests written before the key existed
  // (normalize every step, today's runs) still describe the same scenes.
  if (model.normalize_every != 1)
    m.push_back({prefix + "normalize_every", integer(model.normalize_every)});
  m.push_back({prefix + "damping", {model.damping}});
  m.push_back({prefix + "spring_constant", number(model.spring_constant)});
  m.push_back({prefix + "lattice_cells", integer(model.lattice_cells)});
  // Listed only with drag, so that the manifests written before the keys existed still
  // describe the same (drag-free) scenes.
  if (model.drag.law != physics::DragLaw::none) {
    m.push_back({prefix + "drag", text(std::string(physics::to_string(model.drag.law)))});
    m.push_back({prefix + "drag_rate", number(model.drag.rate)});
  }
}

void add_render(JsonObject& m, const RenderOptions& r, const std::filesystem::path& source) {
  m.push_back({"render.width", integer(r.width)});
  m.push_back({"render.height", integer(r.height)});
  m.push_back({"render.fps", integer(r.fps)});
  m.push_back({"render.fov_y", number(r.fov_y_deg)});
  m.push_back({"render.camera_distance", number(r.camera_distance)});
  m.push_back({"render.camera_direction", vector3(r.camera_direction)});
  m.push_back({"render.show_angular_momentum", {r.show_angular_momentum}});
  m.push_back({"render.show_body_axes", {r.show_body_axes}});
  m.push_back({"render.texture_front", texture(r.texture_front, source)});
  m.push_back({"render.texture_back", texture(r.texture_back, source)});
  m.push_back({"render.texture_spine", texture(r.texture_spine, source)});
  m.push_back({"render.texture_pages", texture(r.texture_pages, source)});
  m.push_back({"render.codec", text(r.codec)});
  m.push_back({"render.crf", integer(r.crf)});
  m.push_back({"render.preset", text(r.preset)});
  m.push_back({"render.png_compression", integer(r.png_compression)});
  m.push_back({"render.anisotropy", integer(r.anisotropy)});
  m.push_back({"render.msaa", integer(r.msaa)});
  m.push_back({"render.panel", {r.panel}});
  m.push_back({"render.sphere", {r.sphere}});
  JsonArray formats;
  for (const auto& f : r.formats) formats.push_back(text(f));
  m.push_back({"render.formats", {std::move(formats)}});
  m.push_back({"render.gif_width", integer(r.gif_width)});
  m.push_back({"render.gif_fps", integer(r.gif_fps)});
  m.push_back({"render.webm_crf", integer(r.webm_crf)});
  m.push_back({"render.poinsot", {r.poinsot}});
  m.push_back({"render.caption_twist", {r.caption_twist}});
}

}  // namespace

JsonObject canonical_scene(const Scene& s) {
  JsonObject m;
  m.push_back({"scene.name", text(s.name)});
  m.push_back({"scene.title", text(s.title)});
  m.push_back({"scene.description", text(s.description)});
  add_model(m, "model.", s.model);
  // The body as simulated (docs/physics.md §12): body.mass and body.scale are in its moments,
  // cage and volume; its surface's geometry is hashed by the manifests (cache/manifests).
  m.push_back({"body.shape", text(std::string(physics::to_string(s.body.shape)))});
  m.push_back({"body.mesh", texture(s.body_mesh, s.source)});
  m.push_back({"body.moments", vector3(s.body.moments)});
  m.push_back({"body.volume", number(s.body.volume)});
  m.push_back({"body.surface", text(std::to_string(s.body.vertices.cols()) + " vertices, " +
                                    std::to_string(s.body.triangles.cols()) + " triangles, " +
                                    (s.body.smooth ? "smooth" : "flat"))});
  m.push_back({"book.size", vector3(s.body.cage.size)});  // the body's cage for a non-book body
  m.push_back({"book.mass", number(s.body.cage.mass)});
  m.push_back({"initial.angular_velocity", vector3(s.initial.omega0_body)});
  m.push_back({"initial.jiggle", number(s.initial.jiggle)});
  m.push_back({"initial.seed", integer(static_cast<std::int64_t>(s.initial.seed))});
  m.push_back({"time.dt", number(s.dt)});
  m.push_back({"time.steps_per_frame", integer(s.steps_per_frame)});
  m.push_back({"time.frames", integer(s.frames)});
  // Listed only where given, so that the manifests written before the key existed still
  // describe the same scenes.
  if (!s.time_unit.empty()) m.push_back({"time.unit", text(s.time_unit)});
  add_render(m, s.render, s.source);
  // Listed only when given, so that the manifests of the scenes without one stay as they were;
  // its bytes are hashed by the manifests (cache/manifest_head.cpp, "inputs").
  if (!s.measured.file.empty()) m.push_back({"measured.omega", texture(s.measured.file, s.source)});
  for (std::size_t i = 0; i < s.compare.size(); ++i) {
    std::string prefix("compare[");  // numbered from 1, as in the scene reader's messages
    prefix.append(std::to_string(i + 1)).append("].");
    m.push_back({prefix + "label", text(s.compare[i].label)});
    add_model(m, prefix + "model.", s.compare[i].model);
  }
  return m;
}

std::string canonical_json(const Scene& s, int indent) {
  return json_member_lines(canonical_scene(s), "canonical scene", indent, true);
}

}  // namespace bookspin::scene
