#include "scene/canonical.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <utility>
#include <vector>

namespace bookspin::scene {

namespace {

/// A double that reads back to itself; JSON has no inf/nan (validation rules them out).
std::string number(double value) {
  char buffer[32];
  for (int digits = 15; digits <= 17; ++digits) {
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
    if (std::strtod(buffer, nullptr) == value) break;
  }
  return buffer;
}

std::string vector3(const Eigen::Vector3d& v) {
  // Built with append: GCC 12 warns falsely (-Wrestrict) on "literal" + std::string.
  std::string out(1, '[');
  out.append(number(v.x())).append(", ").append(number(v.y())).append(", ");
  return out.append(number(v.z())).append(1, ']');
}

std::string boolean(bool value) { return value ? "true" : "false"; }

/// A file the scene names (texture, mesh), relative to the scene file's folder.
std::string texture(const std::string& path, const std::filesystem::path& source) {
  if (path.empty()) return json_string("");
  const std::filesystem::path folder = source.parent_path().empty() ? "." : source.parent_path();
  return json_string(std::filesystem::path(path).lexically_relative(folder).generic_string());
}

using Members = std::vector<std::pair<std::string, std::string>>;

void add_model(Members& m, const std::string& prefix, const physics::ModelConfig& model) {
  m.emplace_back(prefix + "kind", json_string(std::string(physics::to_string(model.kind))));
  m.emplace_back(prefix + "integrator",
                 json_string(std::string(physics::to_string(model.integrator))));
  m.emplace_back(prefix + "normalize", boolean(model.normalize));
  // Listed only where it is not 1, so that the manifests written before the key existed
  // (normalize every step, today's runs) still describe the same scenes.
  if (model.normalize_every != 1)
    m.emplace_back(prefix + "normalize_every", std::to_string(model.normalize_every));
  m.emplace_back(prefix + "damping", boolean(model.damping));
  m.emplace_back(prefix + "spring_constant", number(model.spring_constant));
  m.emplace_back(prefix + "lattice_cells", std::to_string(model.lattice_cells));
}

void add_render(Members& m, const RenderOptions& r, const std::filesystem::path& source) {
  m.emplace_back("render.width", std::to_string(r.width));
  m.emplace_back("render.height", std::to_string(r.height));
  m.emplace_back("render.fps", std::to_string(r.fps));
  m.emplace_back("render.fov_y", number(r.fov_y_deg));
  m.emplace_back("render.camera_distance", number(r.camera_distance));
  m.emplace_back("render.camera_direction", vector3(r.camera_direction));
  m.emplace_back("render.show_angular_momentum", boolean(r.show_angular_momentum));
  m.emplace_back("render.show_body_axes", boolean(r.show_body_axes));
  m.emplace_back("render.texture_front", texture(r.texture_front, source));
  m.emplace_back("render.texture_back", texture(r.texture_back, source));
  m.emplace_back("render.texture_spine", texture(r.texture_spine, source));
  m.emplace_back("render.texture_pages", texture(r.texture_pages, source));
  m.emplace_back("render.codec", json_string(r.codec));
  m.emplace_back("render.crf", std::to_string(r.crf));
  m.emplace_back("render.preset", json_string(r.preset));
  m.emplace_back("render.png_compression", std::to_string(r.png_compression));
  m.emplace_back("render.anisotropy", std::to_string(r.anisotropy));
  m.emplace_back("render.msaa", std::to_string(r.msaa));
  m.emplace_back("render.panel", boolean(r.panel));
  m.emplace_back("render.sphere", boolean(r.sphere));
  std::string formats = "[";
  for (const auto& f : r.formats) formats += (formats.size() > 1 ? ", " : "") + json_string(f);
  m.emplace_back("render.formats", formats + "]");
  m.emplace_back("render.gif_width", std::to_string(r.gif_width));
  m.emplace_back("render.gif_fps", std::to_string(r.gif_fps));
  m.emplace_back("render.webm_crf", std::to_string(r.webm_crf));
  m.emplace_back("render.poinsot", boolean(r.poinsot));
  m.emplace_back("render.caption_twist", boolean(r.caption_twist));
}

}  // namespace

std::string canonical_json(const Scene& s, int indent) {
  Members m;
  m.emplace_back("scene.name", json_string(s.name));
  m.emplace_back("scene.title", json_string(s.title));
  m.emplace_back("scene.description", json_string(s.description));
  add_model(m, "model.", s.model);
  // The body as simulated (docs/physics.md §12): body.mass and body.scale are in its moments,
  // cage and volume; its surface's geometry is hashed by the manifests (cache/manifests).
  m.emplace_back("body.shape", json_string(std::string(physics::to_string(s.body.shape))));
  m.emplace_back("body.mesh", texture(s.body_mesh, s.source));
  m.emplace_back("body.moments", vector3(s.body.moments));
  m.emplace_back("body.volume", number(s.body.volume));
  m.emplace_back("body.surface",
                 json_string(std::to_string(s.body.vertices.cols()) + " vertices, " +
                             std::to_string(s.body.triangles.cols()) + " triangles, " +
                             (s.body.smooth ? "smooth" : "flat")));
  m.emplace_back("book.size", vector3(s.body.cage.size));  // the body's cage for a non-book body
  m.emplace_back("book.mass", number(s.body.cage.mass));
  m.emplace_back("initial.angular_velocity", vector3(s.initial.omega0_body));
  m.emplace_back("initial.jiggle", number(s.initial.jiggle));
  m.emplace_back("initial.seed", std::to_string(s.initial.seed));
  m.emplace_back("time.dt", number(s.dt));
  m.emplace_back("time.steps_per_frame", std::to_string(s.steps_per_frame));
  m.emplace_back("time.frames", std::to_string(s.frames));
  add_render(m, s.render, s.source);
  for (std::size_t i = 0; i < s.compare.size(); ++i) {
    std::string prefix("compare[");  // numbered from 1, as in the scene reader's messages
    prefix.append(std::to_string(i + 1)).append("].");
    m.emplace_back(prefix + "label", json_string(s.compare[i].label));
    add_model(m, prefix + "model.", s.compare[i].model);
  }
  std::ostringstream out;
  const std::string pad(static_cast<std::size_t>(indent), ' ');
  for (std::size_t i = 0; i < m.size(); ++i) {
    out << pad << json_string(m[i].first) << ": " << m[i].second
        << (i + 1 < m.size() ? ",\n" : "\n");
  }
  return out.str();
}

}  // namespace bookspin::scene
