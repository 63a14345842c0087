#pragma once
// The door of the mesh stage: a mesh file (OBJ, STL ASCII or binary, glTF 2.0) read into a
// plain triangle mesh. Knows nothing of physics; docs/architecture.md.
#include <Eigen/Core>
#include <filesystem>

namespace bookspin::mesh {

/// Triangles over welded vertices, in the file's units times the scale passed to load_mesh.
struct TriangleMesh {
  Eigen::Matrix3Xd vertices;   ///< 3×V positions, file axes
  Eigen::Matrix3Xi triangles;  ///< 3×N indices into vertices, the file's winding
  /// 3×N linear RGB in [0, 1] per triangle: the diffuse colour of its part's material
  /// (OBJ `Kd`, glTF base colour; assimp's grey default where the file names none).
  Eigen::Matrix3Xf face_colours;
  /// True when most triangles carry per-vertex normals that differ across the triangle
  /// (a surface the file means to look smooth); false for faceted files (STL's face normals).
  bool smooth = false;
};

/// Reads `path` (by its extension: .obj, .stl, .gltf, .glb; any case) and returns its
/// triangles: polygons triangulated, node transforms applied, points and lines dropped, and
/// vertices at the same position welded into one (also across faces and parts, so a closed
/// surface shares its edges): exactly equal, or within 2⁻²² of the bounding box's longest
/// side in each coordinate (a tolerance relative to the mesh's size, so the same at any
/// scale; a triangle smaller than that collapses and mass_properties reports it as
/// degenerate). Each coordinate is then multiplied by `scale` (> 0).
/// Throws InputError "FILE: reason" for a missing file, a directory, an unknown extension, a
/// binary STL whose header's triangle count does not match the file size (checked before
/// parsing: truncated files and absurd counts), a file assimp cannot read, no triangles, a
/// NaN coordinate, a coordinate that overflows single precision (beyond ±3.4e38, which
/// assimp reads as infinite) or a mesh whose size underflows it (bounding box under 1.2e-38
/// across, FLT_MIN: its coordinates read as 0 or subnormal).
TriangleMesh load_mesh(const std::filesystem::path& path, double scale = 1.0);

}  // namespace bookspin::mesh
