#include "mesh/mesh.hpp"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <array>
#include <assimp/Importer.hpp>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "common/errors.hpp"

namespace bookspin::mesh {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void reject(const fs::path& path, const std::string& reason) {
  throw InputError(path.string() + ": " + reason);
}

/// The lower-case extension without its dot, or "".
std::string extension_of(const fs::path& path) {
  std::string ext = path.extension().string();
  if (!ext.empty()) ext.erase(0, 1);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
  return ext;
}

void check_file(const fs::path& path) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (status.type() == fs::file_type::not_found) reject(path, "mesh file not found");
  if (status.type() == fs::file_type::directory) reject(path, "is a directory, not a mesh file");
  if (ec || status.type() != fs::file_type::regular) reject(path, "not a regular file");
  if (fs::file_size(path, ec) == 0) reject(path, "empty mesh: the file is empty");
  const std::string ext = extension_of(path);
  if (ext != "obj" && ext != "stl" && ext != "gltf" && ext != "glb") {
    reject(path, (ext.empty() ? std::string("unknown mesh format (no extension)")
                              : "unknown mesh format \"." + ext + "\"") +
                     "; expected .obj, .stl, .gltf or .glb");
  }
}

/// An ASCII STL starts with "solid" and is text; binary files may start with "solid" too,
/// so the first bytes must also be free of control and high bytes.
bool looks_like_ascii_stl(const std::string& head) {
  const auto start = head.find_first_not_of(" \t\r\n");
  if (start == std::string::npos || head.compare(start, 5, "solid") != 0) return false;
  return std::all_of(head.begin(), head.end(), [](unsigned char ch) {
    return ch == '\n' || ch == '\r' || ch == '\t' || (ch >= 32 && ch < 127);
  });
}

/// A binary STL is an 80-byte header, a little-endian uint32 triangle count and 50 bytes
/// per triangle. The count is checked against the file size here, before assimp sees the
/// file: a truncated file or a header claiming gigabytes is bad input, not an allocation.
void check_binary_stl_size(const fs::path& path) {
  const std::uintmax_t size = fs::file_size(path);
  std::ifstream in(path, std::ios::binary);
  std::string head(static_cast<std::size_t>(std::min<std::uintmax_t>(size, 512)), '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  if (!in) reject(path, "cannot read the file");
  constexpr std::uintmax_t kHeader = 84, kPerTriangle = 50;
  std::uint64_t count = 0;
  if (size >= kHeader) {
    for (int i = 3; i >= 0; --i) count = (count << 8) | static_cast<unsigned char>(head[80 + i]);
    if (kHeader + kPerTriangle * count == size) return;  // a well-formed binary STL
  }
  if (looks_like_ascii_stl(head)) return;
  if (size < kHeader)
    reject(path, "truncated binary STL: " + std::to_string(size) +
                     " bytes, shorter than the 84-byte header");
  reject(path, "binary STL header claims " + std::to_string(count) + " triangles (" +
                   std::to_string(kHeader + kPerTriangle * count) + " bytes) but the file has " +
                   std::to_string(size) + " bytes");
}

/// assimp's message on one line.
std::string one_line(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  std::replace(text.begin(), text.end(), '\r', ' ');
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text.empty() ? "unknown reason" : text;
}

/// Welding tolerance relative to the bounding box's longest side: 2⁻²², about four float32
/// roundings of the largest coordinate.
constexpr double kWeldTolerance = 0x1p-22;

/// Every triangle of every part placed by the node tree, with vertices welded by position:
/// exactly equal first, then within kWeldTolerance of the mesh's size (assimp's
/// JoinIdenticalVertices keeps apart vertices whose normals differ, as STL's do at every
/// edge, and its tolerance is absolute).
class Welder {
 public:
  Welder(const fs::path& path, const aiScene& scene) : path_(path), scene_(scene) {}

  /// Adds the meshes of `node` and its children, `to_file` taking node to file coordinates.
  void add_node(const aiNode& node, const aiMatrix4x4& parent_to_file) {
    const aiMatrix4x4 to_file = parent_to_file * node.mTransformation;
    for (unsigned i = 0; i < node.mNumMeshes; ++i)
      add_part(*scene_.mMeshes[node.mMeshes[i]], to_file);
    for (unsigned i = 0; i < node.mNumChildren; ++i) add_node(*node.mChildren[i], to_file);
  }

  TriangleMesh mesh(double scale) {
    if (triangles_.empty()) reject(path_, "empty mesh: no triangles");
    check_extent();
    weld_near();
    TriangleMesh mesh;
    mesh.vertices.resize(3, static_cast<Eigen::Index>(positions_.size()));
    for (std::size_t i = 0; i < positions_.size(); ++i) {
      for (int k = 0; k < 3; ++k)
        mesh.vertices(k, static_cast<Eigen::Index>(i)) =
            scale * static_cast<double>(positions_[i][k]);
    }
    mesh.triangles.resize(3, static_cast<Eigen::Index>(triangles_.size()));
    mesh.face_colours.resize(3, static_cast<Eigen::Index>(triangles_.size()));
    for (std::size_t i = 0; i < triangles_.size(); ++i) {
      mesh.triangles.col(static_cast<Eigen::Index>(i)) = triangles_[i];
      mesh.face_colours.col(static_cast<Eigen::Index>(i)) = colours_[i];
    }
    mesh.smooth = 2 * smooth_triangles_ > triangles_.size();
    if (!mesh.vertices.allFinite()) reject(path_, "non-finite vertex coordinate after scaling");
    return mesh;
  }

 private:
  /// Rejects a mesh whose size underflows single precision, in which assimp reads it: the
  /// longest side of its bounding box must be a normal float (at least FLT_MIN, 1.2e-38).
  /// Smaller coordinates read as 0 or as subnormals with a few bits left, so the triangles
  /// collapse: that is the file's units, not its shape, and it is said so.
  void check_extent() const {
    float extent = 0.0f;
    for (int k = 0; k < 3; ++k) {
      float low = positions_[0][k], high = low;
      for (const auto& p : positions_) {
        low = std::min(low, p[k]);
        high = std::max(high, p[k]);
      }
      extent = std::max(extent, high - low);
    }
    if (extent >= std::numeric_limits<float>::min()) return;
    char size[64];
    std::snprintf(size, sizeof size, "%g", static_cast<double>(extent));
    reject(path_, std::string("vertex coordinates underflow: the mesh is ") + size +
                      " across in single precision, in which meshes are read (numbers below "
                      "1.2e-38 lose their digits or become 0); write it in larger units");
  }

  /// Welds vertices closer than kWeldTolerance × the bounding box's longest side (in each
  /// coordinate) into the first of them: corners that a file means to be one but wrote with
  /// a rounding apart. Relative to the mesh's size, so a mesh welds the same at any scale
  /// (docs/physics.md §11, "Welding").
  void weld_near() {
    std::array<float, 3> low = positions_[0], high = low;
    for (const auto& p : positions_) {
      for (int k = 0; k < 3; ++k) {
        low[k] = std::min(low[k], p[k]);
        high[k] = std::max(high[k], p[k]);
      }
    }
    double extent = 0.0;
    for (int k = 0; k < 3; ++k)
      extent = std::max(extent, static_cast<double>(high[k]) - static_cast<double>(low[k]));
    const double tolerance = kWeldTolerance * extent;
    if (!(tolerance > 0.0)) return;
    using Cell = std::array<std::int64_t, 3>;
    const auto cell_of = [&](const std::array<float, 3>& p) {
      Cell cell;
      for (int k = 0; k < 3; ++k)
        cell[k] = static_cast<std::int64_t>(
            std::floor((static_cast<double>(p[k]) - static_cast<double>(low[k])) / tolerance));
      return cell;
    };
    std::map<Cell, std::vector<int>> kept_in_cell;
    std::vector<int> target(positions_.size());
    std::vector<std::array<float, 3>> kept;
    for (std::size_t i = 0; i < positions_.size(); ++i) {
      const std::array<float, 3>& p = positions_[i];
      const Cell cell = cell_of(p);
      int found = -1;
      for (int dx = -1; dx <= 1 && found < 0; ++dx)
        for (int dy = -1; dy <= 1 && found < 0; ++dy)
          for (int dz = -1; dz <= 1 && found < 0; ++dz) {
            const auto it = kept_in_cell.find({cell[0] + dx, cell[1] + dy, cell[2] + dz});
            if (it == kept_in_cell.end()) continue;
            for (const int j : it->second) {
              const auto& q = kept[static_cast<std::size_t>(j)];
              bool near = true;
              for (int k = 0; k < 3; ++k)
                near = near && std::abs(static_cast<double>(p[k]) - q[k]) <= tolerance;
              if (near) {
                found = j;
                break;
              }
            }
          }
      if (found < 0) {
        found = static_cast<int>(kept.size());
        kept.push_back(p);
        kept_in_cell[cell].push_back(found);
      }
      target[i] = found;
    }
    if (kept.size() == positions_.size()) return;
    for (auto& t : triangles_)
      for (int k = 0; k < 3; ++k) t[k] = target[static_cast<std::size_t>(t[k])];
    positions_ = std::move(kept);
  }

  void add_part(const aiMesh& part, const aiMatrix4x4& to_file) {
    std::vector<int> welded(part.mNumVertices);
    for (unsigned v = 0; v < part.mNumVertices; ++v) {
      const aiVector3D& raw = part.mVertices[v];
      // assimp renumbers vertices, so the message shows the coordinates, not an index.
      if (!std::isfinite(raw.x) || !std::isfinite(raw.y) || !std::isfinite(raw.z)) {
        char where[96];
        std::snprintf(where, sizeof where, " (%g, %g, %g)", raw.x, raw.y, raw.z);
        if (std::isnan(raw.x) || std::isnan(raw.y) || std::isnan(raw.z))
          reject(path_, std::string("non-finite vertex coordinate") + where);
        reject(path_, std::string("vertex coordinate overflows") + where +
                          ": single precision, in which meshes are read, holds at most 3.4e38; "
                          "write it in smaller units");
      }
      const aiVector3D p = to_file * raw;
      // The map below needs ordered keys: no NaN from a node transform either.
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        reject(path_, "non-finite vertex coordinate after the node transforms");
      const std::array<float, 3> key{p.x, p.y, p.z};
      const auto [it, added] = index_of_.emplace(key, static_cast<int>(positions_.size()));
      if (added) positions_.push_back(key);
      welded[v] = it->second;
    }
    const Eigen::Vector3f colour = diffuse_colour(part);
    for (unsigned f = 0; f < part.mNumFaces; ++f) {
      const aiFace& face = part.mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines bound no volume
      triangles_.emplace_back(welded[face.mIndices[0]], welded[face.mIndices[1]],
                              welded[face.mIndices[2]]);
      colours_.push_back(colour);
      if (part.HasNormals() && normals_differ(part, face)) ++smooth_triangles_;
    }
  }

  /// The part's material diffuse colour, clamped to [0, 1]; grey without one.
  Eigen::Vector3f diffuse_colour(const aiMesh& part) const {
    aiColor4D c(0.6f, 0.6f, 0.6f, 1.0f);
    if (part.mMaterialIndex < scene_.mNumMaterials)
      scene_.mMaterials[part.mMaterialIndex]->Get(AI_MATKEY_COLOR_DIFFUSE, c);
    const auto unit = [](float v) { return std::isfinite(v) ? std::clamp(v, 0.0f, 1.0f) : 0.6f; };
    return {unit(c.r), unit(c.g), unit(c.b)};
  }

  /// Whether a triangle's three vertex normals point different ways (more than about 0.5°).
  static bool normals_differ(const aiMesh& part, const aiFace& face) {
    const aiVector3D& a = part.mNormals[face.mIndices[0]];
    for (int k = 1; k < 3; ++k) {
      const aiVector3D& b = part.mNormals[face.mIndices[k]];
      const float dot = a * b, len = a.Length() * b.Length();
      if (!(len > 0.0f) || dot < 0.99996f * len) return len > 0.0f;
    }
    return false;
  }

  const fs::path& path_;
  const aiScene& scene_;
  std::map<std::array<float, 3>, int> index_of_;
  std::vector<std::array<float, 3>> positions_;
  std::vector<Eigen::Vector3i> triangles_;
  std::vector<Eigen::Vector3f> colours_;  ///< one per triangle
  std::size_t smooth_triangles_ = 0;
};

}  // namespace

TriangleMesh load_mesh(const fs::path& path, double scale) {
  if (!(std::isfinite(scale) && scale > 0.0)) {
    char text[64];
    std::snprintf(text, sizeof text, "scale must be a positive number, not %g", scale);
    reject(path, text);
  }
  check_file(path);
  if (extension_of(path) == "stl") check_binary_stl_size(path);
  Assimp::Importer importer;
  // Triangulate polygons only: assimp's JoinIdenticalVertices welds with an absolute
  // tolerance (it collapses the corners of a small mesh); the Welder welds relative to the
  // mesh's size. The node transforms (glTF) are applied while collecting, so a file without
  // meshes is "empty", not an assimp error.
  const aiScene* scene = importer.ReadFile(path.string(), aiProcess_Triangulate);
  if (scene == nullptr) reject(path, "cannot read mesh: " + one_line(importer.GetErrorString()));
  Welder welder(path, *scene);
  if (scene->mRootNode != nullptr) welder.add_node(*scene->mRootNode, aiMatrix4x4());
  return welder.mesh(scale);
}

}  // namespace bookspin::mesh
