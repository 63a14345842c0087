// The mesh loader: OBJ, ASCII and binary STL, glTF 2.0 written here into a scratch folder,
// and the files it must reject with an InputError naming them.
#include "mesh/mesh.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <fstream>
#include <limits>

#include "common/errors.hpp"
#include "support/cli_runner.hpp"
#include "support/mesh_files.hpp"

namespace bookspin::mesh {
namespace {

using namespace bookspin::test;  // scratch folders and mesh writers (tests/support)

namespace fs = std::filesystem;

const Point kSize{1.0f, 2.0f, 3.0f};

/// Σ a·(b×c)/6 over the triangles: the enclosed volume when the surface is closed and wound
/// outward, computed here independently of src/physics.
double signed_volume(const TriangleMesh& m) {
  double six_v = 0.0;
  for (Eigen::Index t = 0; t < m.triangles.cols(); ++t) {
    const Eigen::Vector3d a = m.vertices.col(m.triangles(0, t));
    const Eigen::Vector3d b = m.vertices.col(m.triangles(1, t));
    const Eigen::Vector3d c = m.vertices.col(m.triangles(2, t));
    six_v += a.dot(b.cross(c));
  }
  return six_v / 6.0;
}

/// The box [0,1]×[0,2]×[0,3] (shifted by `offset`, scaled by `scale`): 8 welded corners,
/// 12 triangles, winding kept.
void expect_box(const TriangleMesh& m, double scale = 1.0,
                const Eigen::Vector3d& offset = Eigen::Vector3d::Zero()) {
  EXPECT_EQ(m.vertices.cols(), 8);
  EXPECT_EQ(m.triangles.cols(), 12);
  EXPECT_NEAR(signed_volume(m), 6.0 * scale * scale * scale, 1e-12);
  const Eigen::Vector3d low = m.vertices.rowwise().minCoeff();
  const Eigen::Vector3d high = m.vertices.rowwise().maxCoeff();
  EXPECT_TRUE(low.isApprox(scale * offset, 1e-12) || (offset.isZero() && low.isZero()))
      << low.transpose();
  EXPECT_TRUE(high.isApprox(scale * (offset + Eigen::Vector3d(1, 2, 3)), 1e-12))
      << high.transpose();
}

/// The InputError's one line, or "(no error)".
std::string error_loading(const fs::path& path, double scale = 1.0) {
  try {
    load_mesh(path, scale);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(LoadMesh, ObjQuadsAreTriangulated) {
  const fs::path file = fresh_dir("mesh/obj") / "box.obj";
  write_box_obj(file, kSize);
  expect_box(load_mesh(file));
}

TEST(LoadMesh, ScaleMultipliesEveryCoordinate) {
  const fs::path file = fresh_dir("mesh/scale") / "box.OBJ";  // extension in any case
  write_box_obj(file, kSize);
  expect_box(load_mesh(file, 2.5), 2.5);
}

TEST(LoadMesh, AsciiStlCornersAreWelded) {
  const fs::path file = fresh_dir("mesh/ascii-stl") / "box.stl";
  write_box_ascii_stl(file, kSize);
  expect_box(load_mesh(file));
}

TEST(LoadMesh, BinaryStlCornersAreWelded) {
  const fs::path file = fresh_dir("mesh/binary-stl") / "box.stl";
  write_bytes(file, box_binary_stl(kSize));
  ASSERT_EQ(fs::file_size(file), 84u + 12u * 50u);
  expect_box(load_mesh(file));
}

TEST(LoadMesh, GltfNodeTranslationIsApplied) {
  const fs::path file = fresh_dir("mesh/gltf") / "box.gltf";
  write_box_gltf(file, kSize, {10.0f, -4.0f, 0.5f});
  expect_box(load_mesh(file), 1.0, Eigen::Vector3d(10.0, -4.0, 0.5));
}

TEST(LoadMesh, BinaryGltfIsRead) {
  const fs::path file = fresh_dir("mesh/glb") / "box.glb";
  write_box_glb(file, kSize, {0.0f, 0.0f, -7.0f});
  expect_box(load_mesh(file), 1.0, Eigen::Vector3d(0.0, 0.0, -7.0));
}

// Groups become separate parts in assimp; their shared corners must still be one vertex.
TEST(LoadMesh, PartsOfOneSurfaceAreWeldedTogether) {
  const fs::path file = fresh_dir("mesh/groups") / "box.obj";
  {
    std::ofstream out(file);
    for (int i = 0; i < 8; ++i) {
      const Point p = box_corner(i, kSize);
      out << "v " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
    }
    int face = 0;
    for (const auto& q : box_quads()) {
      out << "g side" << face++ << "\nf " << q[0] + 1 << ' ' << q[1] + 1 << ' ' << q[2] + 1 << ' '
          << q[3] + 1 << '\n';
    }
  }
  expect_box(load_mesh(file));
}

TEST(LoadMesh, MaterialColoursComeFromTheFile) {
  // Two groups of a tetrahedron with their own MTL materials: the base red, the sides blue.
  const fs::path dir = fresh_dir("mesh/mtl");
  std::ofstream(dir / "t.mtl") << "newmtl red\nKd 0.9 0.1 0.1\nnewmtl blue\nKd 0.1 0.2 0.8\n";
  std::ofstream(dir / "t.obj") << "mtllib t.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                                  "g base\nusemtl red\nf 1 3 2\n"
                                  "g sides\nusemtl blue\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  const TriangleMesh m = load_mesh(dir / "t.obj");
  ASSERT_EQ(m.triangles.cols(), 4);
  ASSERT_EQ(m.face_colours.cols(), 4);
  int red = 0, blue = 0;
  for (Eigen::Index t = 0; t < 4; ++t) {
    const Eigen::Vector3f c = m.face_colours.col(t);
    red += c.isApprox(Eigen::Vector3f(0.9f, 0.1f, 0.1f), 1e-6f);
    blue += c.isApprox(Eigen::Vector3f(0.1f, 0.2f, 0.8f), 1e-6f);
  }
  EXPECT_EQ(red, 1);
  EXPECT_EQ(blue, 3);
  EXPECT_FALSE(m.smooth);  // no normals in the file
}

TEST(LoadMesh, SmoothNormalsInTheFileMakeASmoothSurface) {
  // The same tetrahedron with one normal per corner pointing out from the centre (a file
  // meant to look round), and as STL (a normal per face): smooth, then flat.
  const fs::path dir = fresh_dir("mesh/normals");
  std::ofstream(dir / "round.obj")
      << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
         "vn -1 -1 -1\nvn 3 -1 -1\nvn -1 3 -1\nvn -1 -1 3\n"
         "f 1//1 3//3 2//2\nf 1//1 2//2 4//4\nf 1//1 4//4 3//3\nf 2//2 3//3 4//4\n";
  EXPECT_TRUE(load_mesh(dir / "round.obj").smooth);
  write_box_ascii_stl(dir / "box.stl", kSize);
  const TriangleMesh box = load_mesh(dir / "box.stl");
  EXPECT_FALSE(box.smooth);
  EXPECT_EQ(box.face_colours.cols(), box.triangles.cols());
}

// Meshes are read in single precision: a box 1e-90 across reads as one point, one 1e300
// across as infinite coordinates. Each is refused saying so, not as "no triangles" or a bare
// "non-finite" coordinate.
TEST(LoadMesh, CoordinatesThatUnderOrOverflowAreSaidToDoSo) {
  const fs::path dir = fresh_dir("mesh/float-range");
  const auto tetrahedron = [&dir](const std::string& name, const std::string& size) {
    std::ofstream(dir / name) << "v 0 0 0\nv " << size << " 0 0\nv 0 " << size << " 0\nv 0 0 "
                              << size << "\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
    return dir / name;
  };
  const fs::path tiny = tetrahedron("tiny.obj", "1e-90");
  EXPECT_EQ(error_loading(tiny),
            tiny.string() +
                ": vertex coordinates underflow: the mesh is 0 across in single precision, in "
                "which meshes are read (numbers below 1.2e-38 lose their digits or become 0); "
                "write it in larger units");
  // 1e-40 is a subnormal float: not 0, but below FLT_MIN = 1.17549435e-38.
  EXPECT_NE(
      error_loading(tetrahedron("subnormal.obj", "1e-40")).find("vertex coordinates underflow"),
      std::string::npos);
  const fs::path huge = tetrahedron("huge.obj", "1e300");
  EXPECT_EQ(error_loading(huge),
            huge.string() +
                ": vertex coordinate overflows (0, inf, 0): single precision, in which meshes are "
                "read, holds at most 3.4e38; write it in smaller units");
  // Just inside single precision either way: read, and at the file's size.
  EXPECT_EQ(error_loading(tetrahedron("small.obj", "1e-37")), "(no error)");
  const TriangleMesh big = load_mesh(tetrahedron("big.obj", "1e38"));
  EXPECT_NEAR(big.vertices.maxCoeff(), 1e38, 1e31);
}

TEST(LoadMesh, MissingFileIsRejected) {
  const fs::path file = fresh_dir("mesh/missing") / "nothing.obj";
  EXPECT_EQ(error_loading(file), file.string() + ": mesh file not found");
}

TEST(LoadMesh, DirectoryIsRejected) {
  const fs::path dir = fresh_dir("mesh/directory.obj");
  EXPECT_EQ(error_loading(dir), dir.string() + ": is a directory, not a mesh file");
}

TEST(LoadMesh, UnknownFormatIsRejectedByItsExtension) {
  const fs::path dir = fresh_dir("mesh/unknown");
  write_box_obj(dir / "box.ply", kSize);
  EXPECT_EQ(error_loading(dir / "box.ply"),
            (dir / "box.ply").string() +
                ": unknown mesh format \".ply\"; expected .obj, .stl, .gltf or .glb");
  write_box_obj(dir / "box", kSize);
  EXPECT_EQ(error_loading(dir / "box"),
            (dir / "box").string() +
                ": unknown mesh format (no extension); expected .obj, .stl, .gltf or .glb");
}

TEST(LoadMesh, TruncatedBinaryStlIsRejected) {
  const fs::path file = fresh_dir("mesh/truncated") / "box.stl";
  write_bytes(file, box_binary_stl(kSize).substr(0, 84 + 11 * 50 + 20));
  EXPECT_EQ(error_loading(file), file.string() +
                                     ": binary STL header claims 12 triangles (684 bytes) but "
                                     "the file has 654 bytes");
  write_bytes(file, std::string(40, '\0'));
  EXPECT_EQ(error_loading(file),
            file.string() + ": truncated binary STL: 40 bytes, shorter than the 84-byte header");
}

// A header claiming 100 million triangles (5 GB) on a small file is rejected from the size
// alone, before anything is allocated for it.
TEST(LoadMesh, BinaryStlClaimingGigabytesIsRejected) {
  const fs::path file = fresh_dir("mesh/huge-claim") / "box.stl";
  write_bytes(file, box_binary_stl(kSize, 100'000'000));
  EXPECT_EQ(error_loading(file), file.string() +
                                     ": binary STL header claims 100000000 triangles "
                                     "(5000000084 bytes) but the file has 684 bytes");
}

TEST(LoadMesh, NoTrianglesIsEmpty) {
  const fs::path file = fresh_dir("mesh/empty") / "points.obj";
  std::ofstream(file) << "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  EXPECT_EQ(error_loading(file), file.string() + ": empty mesh: no triangles");
}

TEST(LoadMesh, NonFiniteCoordinateIsRejected) {
  const fs::path dir = fresh_dir("mesh/nan");
  std::string bytes = box_binary_stl(kSize);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(bytes.data() + 84 + 12 + 4, &nan, sizeof nan);  // triangle 1, vertex 1, y
  write_bytes(dir / "box.stl", bytes);
  EXPECT_EQ(error_loading(dir / "box.stl"),
            (dir / "box.stl").string() + ": non-finite vertex coordinate (0, nan, 0)");
}

TEST(LoadMesh, NonPositiveScaleIsRejected) {
  const fs::path file = fresh_dir("mesh/bad-scale") / "box.obj";
  write_box_obj(file, kSize);
  EXPECT_NE(error_loading(file, 0.0).find("scale must be a positive number"), std::string::npos);
}

}  // namespace
}  // namespace bookspin::mesh
