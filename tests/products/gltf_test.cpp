// The glTF product: OUT/<name>.glb, a binary glTF 2.0 (its 12-byte header: magic "glTF",
// version 2, the file's length; Khronos' GLB layout) with one keyframe per frame, and its
// manifest OUT/<name>/gltf-manifest.json (docs/outputs.md, "glTF export"); a comparison has
// no single motion and is refused; a deforming model exports its best-fit rigid motion and
// says so. (The file through the Khronos validator and three.js: tests/browser/gltf_test.py.)
#include "products/gltf.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "output/manifest.hpp"
#include "support/cli_runner.hpp"
#include "support/scratch.hpp"

namespace bookspin::products {
namespace {

namespace fs = std::filesystem;

/// The T-handle, a rigid model, 5 frames; `more` overrides after these.
GltfJob handle_job(const fs::path& out, const std::vector<std::string>& more = {}) {
  std::vector<std::string> overrides{"body.shape=\"t-handle\"", "model.kind=\"rigid-quaternion\"",
                                     "time.frames=5"};
  overrides.insert(overrides.end(), more.begin(), more.end());
  std::ofstream(out / "handle.toml") << "[scene]\nname = \"handle\"\n";
  GltfJob job;
  job.scene = scene::parse_scene(out / "handle.toml", overrides);
  job.out_dir = out;
  return job;
}

std::uint32_t le32(const std::string& bytes, std::size_t at) {
  std::uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = v << 8 | static_cast<unsigned char>(bytes[at + i]);
  return v;
}

TEST(Gltf, WritesAGlbWithAKeyframePerFrameAndItsManifest) {
  test::ScratchDir dir;
  const GltfJob job = handle_job(dir.path());
  EXPECT_NE(gltf_manifest_head(job).find("\"options\": {\n    \"format\": \"glb\"\n  }"),
            std::string::npos)
      << gltf_manifest_head(job);
  const GltfExportResult result = make_gltf(job);
  EXPECT_EQ(result.outcome, cache::Outcome::made);
  EXPECT_EQ(result.path, dir / "handle.glb");
  EXPECT_EQ(result.keyframes, 5);
  EXPECT_FALSE(result.diverged_at.has_value());
  EXPECT_GT(result.vertices, 0);
  const std::string glb = test::read_file(dir / "handle.glb");
  ASSERT_GE(glb.size(), 12u);
  EXPECT_EQ(glb.substr(0, 4), "glTF");
  EXPECT_EQ(le32(glb, 4), 2u);
  EXPECT_EQ(le32(glb, 8), glb.size());
  EXPECT_EQ(output::read_manifest(dir / "handle" / "gltf-manifest.json").outputs,
            (std::vector<std::string>{"handle.glb"}));
  EXPECT_EQ(make_gltf(job).outcome, cache::Outcome::up_to_date);
}

TEST(Gltf, AComparisonIsRefusedBeforeAnythingIsWritten) {
  test::ScratchDir dir;
  const GltfJob job = handle_job(
      dir.path(), {"compare=[{label = \"a\", model = {kind = \"exact\"}}, {label = \"b\"}]"});
  EXPECT_THROW(check_gltf_scene(job.scene), InputError);
  EXPECT_THROW(make_gltf(job), InputError);
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"handle.toml"}));
}

TEST(Gltf, ADeformingModelSaysItExportsItsBestFitRigidMotion) {
  test::ScratchDir dir;
  GltfJob job = handle_job(dir.path(), {"model.kind=\"particle\"", "model.lattice_cells=4"});
  std::vector<std::string> notes;
  job.on_note = [&](const std::string& note) { notes.push_back(note); };
  EXPECT_EQ(make_gltf(job).keyframes, 5);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("handle: the lattice model deforms"), std::string::npos) << notes[0];
  EXPECT_NE(notes[0].find("best-fit rigid motion"), std::string::npos) << notes[0];
}

}  // namespace
}  // namespace bookspin::products
