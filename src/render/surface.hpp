#pragma once
// A triangle surface drawn instead of the book (any body, a deformed lattice): its constant
// part (triangles, colours), shared by every frame of a clip and uploaded to GL once, and the
// per-frame world positions. Also the normals the renderer lights it with.
#include <Eigen/Dense>
#include <memory>

namespace bookspin::render {

/// The per-clip constant part of a surface: which vertices make each triangle, and its colour.
/// Share one instance (std::shared_ptr) across the frames of a clip: the renderer uploads it
/// to GL when it first sees it and again only when a frame brings a different instance.
struct SurfaceTopology {
  /// 3×N vertex indices (columns of SurfaceFrame::positions), counter-clockwise seen from
  /// outside: the outward normal of triangle (a, b, c) is (b − a) × (c − a).
  Eigen::Matrix3Xi triangles;
  /// 3×N linear RGB in [0, 1], one colour per triangle (lit as the book's textures are).
  Eigen::Matrix3Xf face_colours;
  /// false: flat, every triangle its own normal; true: smooth, per-vertex normals (the
  /// area-weighted mean of the adjacent triangles' normals), interpolated across triangles.
  bool smooth = false;
};

/// One frame's surface. With no topology the book is drawn from FrameInput::corners.
struct SurfaceFrame {
  std::shared_ptr<const SurfaceTopology> topology;
  /// 3×V, world, V > every index in topology->triangles. Drawn exactly as given (stretched,
  /// sheared, exploded); any position not finite in single precision → no surface is drawn
  /// (as for the book's corners).
  Eigen::Matrix3Xd positions;
};

/// Throws std::invalid_argument (a caller's bug, not a machine's lack) unless `topology` has
/// N ≥ 1 triangles, N colours, no negative index, and colours finite in [0, 1]. Returns the
/// number of vertices the triangles use (largest index + 1).
int validate_topology(const SurfaceTopology& topology);

/// 3×N unit outward normals ((b − a) × (c − a), normalized), world, computed in double from
/// `positions` (3×V world); a degenerate (zero-area) triangle gets (0, 0, 0). Indices must be
/// valid (validate_topology).
Eigen::Matrix3Xf face_normals(const Eigen::Matrix3Xd& positions, const Eigen::Matrix3Xi& triangles);

/// 3×V unit vertex normals: the sum of (b − a) × (c − a) (twice the area times the unit
/// normal) over the triangles using each vertex, normalized ("area-weighted" vertex normals);
/// (0, 0, 0) where that sum vanishes (an unused vertex, a cusp).
Eigen::Matrix3Xf vertex_normals(const Eigen::Matrix3Xd& positions,
                                const Eigen::Matrix3Xi& triangles);

/// True if every position is finite once converted to float (what GL will see).
bool positions_drawable(const Eigen::Matrix3Xd& positions);

}  // namespace bookspin::render
