#pragma once
// Animated glTF 2.0 binaries (.glb) written with tinygltf: one rigid body (its surface in its
// own frame, in parts that each have a material) and one animation that moves it
// (docs/outputs.md, "glTF export").
#include <Eigen/Dense>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "common/rgba_image.hpp"

namespace bookspin::output {

/// Triangles sharing one material. Positions etc. are in the body frame (length units; glTF
/// calls them metres).
struct GltfPart {
  std::string name;
  Eigen::Matrix3Xf positions;          ///< 3×V, body frame
  Eigen::Matrix3Xf normals;            ///< 3×V unit, body frame; or 3×0 (viewers then shade flat)
  Eigen::Matrix2Xf uvs;                ///< 2×V, u right, v down (0 = the image's top row); or 2×0
  std::vector<std::uint32_t> indices;  ///< 3 per triangle, counter-clockwise from outside
  Eigen::Vector3f colour{0.8f, 0.8f, 0.8f};  ///< linear RGB base colour in [0, 1]
  RgbaImage texture;  ///< base colour image (needs uvs); empty (0×0): the colour alone
};

/// The animation: at times[k] (seconds, strictly increasing, first 0) the body's node has
/// rotation rotations.col(k) (unit quaternion x, y, z, w as glTF stores it, body→world) and
/// translation translations.col(k) (world); linear interpolation (glTF's slerp for rotations).
struct GltfAnimation {
  std::vector<float> times;       ///< K ≥ 1
  Eigen::Matrix4Xf rotations;     ///< 4×K, (x, y, z, w)
  Eigen::Matrix3Xf translations;  ///< 3×K
};

/// Writes `path` (.glb): one scene, one node named `name` holding one mesh of `parts` (one
/// primitive each) and carrying the animation, each textured part's image embedded as PNG.
/// The file appears only when complete (AtomicFile). Throws std::invalid_argument for parts or
/// animation of inconsistent sizes, an index out of range, non-finite numbers or times not
/// increasing; OutputError naming `path` if it cannot be written. `before_commit` runs once the
/// file is whole, before it is put in place: a stop polled there (an exception) leaves no file.
void write_glb(const std::filesystem::path& path, const std::string& name,
               const std::vector<GltfPart>& parts, const GltfAnimation& animation,
               const std::function<void()>& before_commit = {});

}  // namespace bookspin::output
