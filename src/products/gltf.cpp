#include "products/gltf.hpp"

#include <map>
#include <tuple>
#include <utility>

#include "analysis/frame_source.hpp"
#include "cache/make_cached.hpp"
#include "common/errors.hpp"
#include "output/diagnostics_csv.hpp"
#include "output/gltf_writer.hpp"
#include "render/book_faces.hpp"
#include "render/book_mesh.hpp"
#include "render/face_images.hpp"
#include "render/surface.hpp"

namespace bookspin::products {
namespace {

/// The book: one part per face image, each face's vertices as the renderer builds them at
/// rest (body frame), with their normals and texture coordinates.
std::vector<output::GltfPart> book_parts(const scene::Scene& scene) {
  const scene::RenderOptions& r = scene.render;
  render::FaceImages images =
      render::face_images(r.texture_front, r.texture_back, r.texture_spine, r.texture_pages);
  const std::vector<render::BookVertex> mesh =
      render::build_book_mesh(scene.body.cage.body_corners());
  static constexpr const char* kNames[4] = {"front cover", "back cover", "spine", "pages"};
  std::vector<output::GltfPart> parts;
  for (int image = 0; image < 4; ++image) {
    output::GltfPart part;
    part.name = kNames[image];
    std::vector<int> faces;
    for (int f = 0; f < static_cast<int>(render::book_faces.size()); ++f)
      if (static_cast<int>(render::book_faces[f].image) == image) faces.push_back(f);
    const int n = static_cast<int>(faces.size()) * render::vertices_per_face;
    part.positions.resize(3, n);
    part.normals.resize(3, n);
    part.uvs.resize(2, n);
    int v = 0;
    for (const int f : faces) {
      for (int i = 0; i < render::vertices_per_face; ++i, ++v) {
        const render::BookVertex& bv =
            mesh[static_cast<std::size_t>(f * render::vertices_per_face + i)];
        part.positions.col(v) = Eigen::Vector3f(bv.position[0], bv.position[1], bv.position[2]);
        part.normals.col(v) = Eigen::Vector3f(bv.normal[0], bv.normal[1], bv.normal[2]);
        part.uvs.col(v) = Eigen::Vector2f(bv.uv[0], bv.uv[1]);
        part.indices.push_back(static_cast<std::uint32_t>(v));
      }
    }
    // glTF's front faces wind counter-clockwise seen from outside (viewers cull the back
    // faces); the renderer's triangles need not, so each is turned to face along its normal.
    for (std::size_t t = 0; t + 2 < part.indices.size(); t += 3) {
      const Eigen::Vector3f a = part.positions.col(part.indices[t]);
      const Eigen::Vector3f b = part.positions.col(part.indices[t + 1]);
      const Eigen::Vector3f c = part.positions.col(part.indices[t + 2]);
      if ((b - a).cross(c - a).dot(part.normals.col(part.indices[t])) < 0.0f)
        std::swap(part.indices[t + 1], part.indices[t + 2]);
    }
    part.colour = Eigen::Vector3f::Ones();
    part.texture = std::move(images[static_cast<std::size_t>(image)]);
    parts.push_back(std::move(part));
  }
  return parts;
}

/// Any other body: its rest surface (principal frame), one part per distinct face colour,
/// each with the vertices its triangles use; smooth bodies carry area-weighted vertex normals
/// (as the renderer lights them), flat ones none (glTF viewers then shade flat).
std::vector<output::GltfPart> surface_parts(const physics::Body& body) {
  const Eigen::Index n = body.triangles.cols();
  Eigen::Matrix3Xf colours = body.face_colours;
  if (colours.cols() != n) colours = Eigen::Matrix3Xf::Constant(3, n, 0.7f);
  const Eigen::Matrix3Xf normals =
      body.smooth ? render::vertex_normals(body.vertices, body.triangles) : Eigen::Matrix3Xf(3, 0);
  std::map<std::tuple<float, float, float>, std::vector<Eigen::Index>> by_colour;
  for (Eigen::Index t = 0; t < n; ++t)
    by_colour[{colours(0, t), colours(1, t), colours(2, t)}].push_back(t);
  std::vector<output::GltfPart> parts;
  for (const auto& [colour, triangles] : by_colour) {
    output::GltfPart part;
    part.name = "material " + std::to_string(parts.size());
    part.colour = Eigen::Vector3f(std::get<0>(colour), std::get<1>(colour), std::get<2>(colour));
    std::map<int, std::uint32_t> remap;
    std::vector<int> used;
    for (const Eigen::Index t : triangles) {
      for (int c = 0; c < 3; ++c) {
        const int vertex = body.triangles(c, t);
        auto [it, fresh] = remap.emplace(vertex, static_cast<std::uint32_t>(used.size()));
        if (fresh) used.push_back(vertex);
        part.indices.push_back(it->second);
      }
    }
    part.positions.resize(3, static_cast<Eigen::Index>(used.size()));
    if (body.smooth) part.normals.resize(3, static_cast<Eigen::Index>(used.size()));
    for (std::size_t i = 0; i < used.size(); ++i) {
      part.positions.col(static_cast<Eigen::Index>(i)) = body.vertices.col(used[i]).cast<float>();
      if (body.smooth) part.normals.col(static_cast<Eigen::Index>(i)) = normals.col(used[i]);
    }
    parts.push_back(std::move(part));
  }
  return parts;
}

/// Runs the scene and writes `glb` (make_gltf's work, without the manifest).
GltfExportResult export_glb(const scene::Scene& scene, const std::filesystem::path& glb,
                            const std::function<void(const std::string&)>& on_note,
                            const StopPoll& stop) {
  // The particle model of the book, and of any other body (the lattice, docs/physics.md §13).
  const bool deforms = scene.model.kind == physics::ModelKind::particle;
  if (deforms && on_note) {
    on_note(scene.name + ": the " +
            std::string(scene.body.shape == physics::BodyShape::book ? "particle" : "lattice") +
            " model deforms; the glTF carries its best-fit rigid motion (the rotation that best "
            "fits its particles and their centre of mass), not the deformation");
  }
  std::vector<output::GltfPart> parts =
      scene.body.shape == physics::BodyShape::book ? book_parts(scene) : surface_parts(scene.body);

  output::GltfAnimation animation;
  std::vector<Eigen::Vector4f> rotations;
  std::vector<Eigen::Vector3f> translations;
  analysis::FrameSource source(scene);
  physics::Pose pose;
  Eigen::Vector4d previous(0, 0, 0, 1);
  for (;;) {
    stop_if_asked(stop, "export frames");
    if (!source.next(pose)) break;
    // (w, x, y, z) with w ≥ 0, then the sign nearest the previous keyframe's: q and −q are the
    // same rotation, and interpolating between keyframes of opposite sign would spin the long way.
    const Eigen::Vector4d wxyz = output::pose_quaternion(pose.diagnostics.orientation);
    Eigen::Vector4d xyzw(wxyz[1], wxyz[2], wxyz[3], wxyz[0]);
    if (xyzw.dot(previous) < 0.0) xyzw = -xyzw;
    previous = xyzw;
    animation.times.push_back(static_cast<float>(source.frame()) /
                              static_cast<float>(scene.render.fps));
    rotations.push_back(xyzw.cast<float>());
    translations.push_back(pose.diagnostics.center_of_mass.cast<float>());
  }
  const auto k = static_cast<Eigen::Index>(rotations.size());
  animation.rotations.resize(4, k);
  animation.translations.resize(3, k);
  for (Eigen::Index i = 0; i < k; ++i) {
    animation.rotations.col(i) = rotations[static_cast<std::size_t>(i)];
    animation.translations.col(i) = translations[static_cast<std::size_t>(i)];
  }
  GltfExportResult result;
  result.path = glb;
  result.keyframes = static_cast<int>(k);
  for (const auto& part : parts) result.vertices += static_cast<int>(part.positions.cols());
  result.diverged_at = source.diverged_at();
  std::error_code ec;
  std::filesystem::create_directories(glb.parent_path(), ec);
  if (ec) throw_output_error("cannot create directory", glb.parent_path(), ec.value());
  stop_if_asked(stop, "export write");
  // Polled again once the file is whole, before it replaces the earlier one: a signal while
  // the GLB was formed (a random moment's test found it written and exit 0) leaves it as it was.
  output::write_glb(result.path, scene.name, parts, animation,
                    [&stop] { stop_if_asked(stop, "export commit"); });
  return result;
}

}  // namespace

GltfLayout gltf_layout(const std::filesystem::path& out_dir, const scene::Scene& scene) {
  return {out_dir / (scene.name + ".glb"), out_dir / scene.name / "gltf-manifest.json"};
}

void check_gltf_scene(const scene::Scene& scene) {
  if (!scene.compare.empty()) {
    throw InputError(scene.source.string() +
                     ": --gltf: a comparison scene ([[compare]]) has no single motion to export; "
                     "export one model's scene at a time");
  }
}

namespace {

cache::CachedOutputs gltf_cached(const GltfJob& job, const GltfLayout& layout) {
  return {job.scene.name + ".glb",
          layout.manifest,
          "export",
          {{"format", {std::string("glb")}}},
          job.out_dir,
          &job.scene,
          /*all_or_nothing=*/true};  // one GLB, put in place whole or not at all
}

}  // namespace

std::string gltf_manifest_head(const GltfJob& job) {
  return cache::cached_head(gltf_cached(job, gltf_layout(job.out_dir, job.scene)));
}

GltfExportResult make_gltf(const GltfJob& job) {
  check_gltf_scene(job.scene);
  const GltfLayout layout = gltf_layout(job.out_dir, job.scene);
  const cache::CachedOutputs cached{gltf_cached(job, layout)};
  GltfExportResult result;
  result.path = layout.glb;
  result.outcome = cache::make_cached(cached, job.freshness, [&] {
    result = export_glb(job.scene, layout.glb, job.on_note, job.stop);
    return cache::Made{{layout.glb}};
  });
  return result;
}

}  // namespace bookspin::products
