// `bookspin export SCENE --gltf`: the .glb read back by assimp (an independent glTF reader):
// the vertices written, one animation whose rotation and translation keys are the run's
// frames at render.fps, and rotations equal to the CSV's quaternions (docs/outputs.md).
// The Khronos validator and three.js check the same files in tests/browser/gltf_test.py.
#include <assimp/scene.h>
#include <gtest/gtest.h>

#include <assimp/Importer.hpp>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "support/cli_runner.hpp"

namespace bookspin::cli {
namespace {

using namespace bookspin::test;
namespace fs = std::filesystem;

struct Quaternion {
  double w, x, y, z;
};

/// Column q_w … q_z of each row of `bookspin simulate`'s CSV for the scene.
std::vector<Quaternion> csv_quaternions(const std::string& scene, const std::string& args) {
  const SplitResult r = run_bookspin_split("simulate " + scene + args + " --csv -");
  EXPECT_EQ(r.status, 0) << r.err;
  std::istringstream in(r.out);
  std::string line;
  std::getline(in, line);
  EXPECT_NE(line.find(",q_w,q_x,q_y,q_z,"), std::string::npos);
  std::vector<Quaternion> out;
  while (std::getline(in, line)) {
    std::vector<double> v;
    for (std::istringstream row(line); std::getline(row, line, ',');) {
      double d = 0;
      std::from_chars(line.data(), line.data() + line.size(), d);
      v.push_back(d);
    }
    out.push_back({v[20], v[21], v[22], v[23]});
  }
  return out;
}

struct Readback {
  unsigned vertices = 0;
  unsigned meshes = 0;
  unsigned materials = 0;
  const aiScene* scene = nullptr;
};

Readback read_glb(Assimp::Importer& importer, const fs::path& path) {
  Readback r;
  r.scene = importer.ReadFile(path.string(), 0);  // no post-processing: the file as written
  EXPECT_NE(r.scene, nullptr) << importer.GetErrorString();
  if (r.scene == nullptr) return r;
  r.meshes = r.scene->mNumMeshes;
  r.materials = r.scene->mNumMaterials;
  for (unsigned i = 0; i < r.scene->mNumMeshes; ++i)
    r.vertices += r.scene->mMeshes[i]->mNumVertices;
  return r;
}

/// The exported file's keys: one animation, one channel, `frames` rotation and position keys
/// at k / fps seconds (assimp reports times in ticks: glTF's are seconds × 1000), each rotation
/// the CSV's quaternion of frame k up to sign, to float precision.
void expect_keys_match_csv(const aiScene* scene, const std::vector<Quaternion>& csv, double fps) {
  ASSERT_EQ(scene->mNumAnimations, 1u);
  const aiAnimation* animation = scene->mAnimations[0];
  ASSERT_EQ(animation->mNumChannels, 1u);
  const aiNodeAnim* channel = animation->mChannels[0];
  ASSERT_EQ(channel->mNumRotationKeys, csv.size());
  ASSERT_EQ(channel->mNumPositionKeys, csv.size());
  const double ticks = animation->mTicksPerSecond > 0 ? animation->mTicksPerSecond : 1.0;
  double worst = 0.0;
  for (std::size_t k = 0; k < csv.size(); ++k) {
    const aiQuatKey& key = channel->mRotationKeys[k];
    EXPECT_NEAR(key.mTime / ticks, static_cast<double>(k) / fps, 1e-5) << "key " << k;
    const Quaternion& q = csv[k];
    const double dot =
        key.mValue.w * q.w + key.mValue.x * q.x + key.mValue.y * q.y + key.mValue.z * q.z;
    const double sign = dot < 0 ? -1.0 : 1.0;
    worst =
        std::max({worst, std::abs(sign * key.mValue.w - q.w), std::abs(sign * key.mValue.x - q.x),
                  std::abs(sign * key.mValue.y - q.y), std::abs(sign * key.mValue.z - q.z)});
  }
  EXPECT_LT(worst, 1e-6);  // stored as float: ~6e-8
}

TEST(ExportCommand, TexturedBookGlbReadsBackWithItsVerticesKeysAndTheCsvRotations) {
  const fs::path out = fresh_dir("export_book");
  const std::string scene = scene_path("fig09-matrix-unstable-x");
  const SplitResult r =
      run_bookspin_split("export " + scene + " --gltf --frames 40 -o " + out.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "exported: " + (out / "fig09-matrix-unstable-x.glb").string() +
                       " (40 keyframes, 72 vertices)\n");
  Assimp::Importer importer;
  const Readback glb = read_glb(importer, out / "fig09-matrix-unstable-x.glb");
  ASSERT_NE(glb.scene, nullptr);
  EXPECT_EQ(glb.vertices, 72u);            // 6 faces × 12, as the renderer draws them
  EXPECT_EQ(glb.meshes, 4u);               // front, back, spine, pages
  EXPECT_EQ(glb.scene->mNumTextures, 4u);  // the cover art, embedded
  expect_keys_match_csv(glb.scene, csv_quaternions(scene, " --set time.frames=40"), 30.0);
}

TEST(ExportCommand, PresetAndMeshBodiesCarryTheirColoursAsMaterials) {
  const fs::path out = fresh_dir("export_bodies");
  const std::string handle = scene_path("t-handle-dzhanibekov");
  SplitResult r = run_bookspin_split("export " + handle + " --gltf --frames 25 -o " + out.string());
  ASSERT_EQ(r.status, 0) << r.err;
  {
    Assimp::Importer importer;
    const Readback glb = read_glb(importer, out / "t-handle-dzhanibekov.glb");
    ASSERT_NE(glb.scene, nullptr);
    EXPECT_EQ(glb.vertices, 28u);  // as exported: both bars' boxes, unwelded per colour
    expect_keys_match_csv(glb.scene, csv_quaternions(handle, " --set time.frames=25"), 30.0);
  }
  // A mesh with two materials: a box whose top face is red, the rest blue.
  std::ofstream(out / "box.mtl") << "newmtl red\nKd 1 0 0\nnewmtl blue\nKd 0 0 1\n";
  std::ofstream(out / "box.obj")
      << "mtllib box.mtl\nv 0 0 0\nv 2 0 0\nv 0 1 0\nv 2 1 0\nv 0 0 0.5\nv 2 0 0.5\nv 0 1 0.5\n"
         "v 2 1 0.5\nusemtl blue\nf 1 5 7 3\nf 2 4 8 6\nf 1 2 6 5\nf 3 7 8 4\nf 1 3 4 2\n"
         "usemtl red\nf 5 6 8 7\n";
  std::ofstream(out / "box.toml") << "[body]\nshape = \"mesh\"\nmesh = \"box.obj\"\nmass = 1.0\n"
                                     "[model]\nkind = \"rigid-quaternion\"\n"
                                     "[initial]\nangular_velocity = [0.0, 1.0, 0.05]\n"
                                     "[time]\nframes = 12\n";
  r = run_bookspin_split("export " + (out / "box.toml").string() + " --gltf -o " + out.string());
  ASSERT_EQ(r.status, 0) << r.err;
  Assimp::Importer importer;
  const Readback glb = read_glb(importer, out / "box.glb");
  ASSERT_NE(glb.scene, nullptr);
  EXPECT_EQ(glb.meshes, 2u);
  std::vector<std::array<float, 3>> colours;
  for (unsigned i = 0; i < glb.scene->mNumMeshes; ++i) {  // the meshes' materials
    aiColor4D c;
    const aiMaterial* material = glb.scene->mMaterials[glb.scene->mMeshes[i]->mMaterialIndex];
    if (material->Get(AI_MATKEY_BASE_COLOR, c) == AI_SUCCESS) colours.push_back({c.r, c.g, c.b});
  }
  std::sort(colours.begin(), colours.end());
  EXPECT_EQ(colours, (std::vector<std::array<float, 3>>{{0, 0, 1}, {1, 0, 0}}));
  expect_keys_match_csv(glb.scene, csv_quaternions((out / "box.toml").string(), ""), 30.0);
}

TEST(ExportCommand, DeformingModelExportsItsBestFitRigidMotionAndSaysSo) {
  const fs::path out = fresh_dir("export_particle");
  const SplitResult r = run_bookspin_split("export " + scene_path("fig05-particle-unstable-x") +
                                           " --gltf --frames 5 -o " + out.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("best-fit rigid motion"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(out / "fig05-particle-unstable-x.glb"));
}

TEST(ExportCommand, ComparisonSceneOrNoFormatIsOneLineExitTwoAndNothingWritten) {
  const fs::path out = fresh_dir("export_bad");
  SplitResult r = run_bookspin_split("export " + scene_path("compare-methods-x") + " --gltf -o " +
                                     (out / "o").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("comparison scene"), std::string::npos) << r.err;
  r = run_bookspin_split("export " + scene_path("fig09-matrix-unstable-x") + " -o " +
                         (out / "o").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--gltf"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out / "o"));
}

// A comparison of a lattice body cannot be exported: the error comes alone, not after the
// lattice's informational line (which it makes moot).
TEST(ExportCommand, AComparisonIsRefusedBeforeAnyNoteAboutItsLattice) {
  const fs::path dir = fresh_dir("export_compare_lattice");
  std::ofstream(dir / "handles.toml") << "[body]\nshape = \"t-handle\"\n[time]\nframes = 2\n"
                                         "[[compare]]\nlabel = \"lattice\"\n"
                                         "model.kind = \"particle\"\n[[compare]]\n"
                                         "label = \"exact\"\nmodel.kind = \"exact\"\n";
  const SplitResult r = run_bookspin_split("export " + (dir / "handles.toml").string() +
                                           " --gltf -o " + (dir / "o").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "bookspin: error: " + (dir / "handles.toml").string() +
                       ": --gltf: a comparison scene ([[compare]]) has no single motion to "
                       "export; export one model's scene at a time\n");
  EXPECT_EQ(r.out, "");
  EXPECT_FALSE(fs::exists(dir / "o"));
}

}  // namespace
}  // namespace bookspin::cli
