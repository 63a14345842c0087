// The manifest head and note (cache/manifest_head.hpp): their exact text, members in order,
// written out by hand around the parts that have tests of their own (the canonical scene,
// SHA-256), since a head that changes by one byte makes every earlier output stale.
#include "cache/manifest_head.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "common/sha256.hpp"
#include "output/manifest.hpp"
#include "output/sha256.hpp"
#include "scene/canonical.hpp"
#include "support/scratch.hpp"

namespace bookspin::cache {
namespace {

using test::ScratchDir;

constexpr const char* kScene = R"toml([scene]
title = "A book"
[time]
frames = 10
dt = 0.01
)toml";

/// The "bookspin" member's line, as every head has it.
std::string program_line() {
  return "  \"bookspin\": {\"version\": \"" + output::program_version() +
         "\", \"build_id\": \"sha256:" + output::program_build_id() + "\"},\n";
}

TEST(ManifestHead, IsItsMembersOneALineTwoSpacesIn) {
  ScratchDir dir;
  std::ofstream(dir / "book.toml") << kScene;
  const scene::Scene scene = scene::parse_scene(dir / "book.toml");
  const JsonObject options{{"png", {true}}, {"png_compression", {std::int64_t{6}}}};
  EXPECT_EQ(manifest_head("render", options, scene),
            "  \"manifest\": 1,\n"
            "  \"command\": \"render\",\n" +
                program_line() +
                "  \"options\": {\n"
                "    \"png\": true,\n"
                "    \"png_compression\": 6\n"
                "  },\n"
                "  \"scene\": {\n" +
                scene::canonical_json(scene, 4) +
                "  },\n"
                "  \"inputs\": {},\n");
  // No options: the object still breaks over lines, as the manifests written so far have it.
  const std::string bare = manifest_head("explore", JsonObject{}, scene);
  EXPECT_NE(bare.find("  \"command\": \"explore\",\n" + program_line() +
                      "  \"options\": {\n  },\n  \"scene\": {\n"),
            std::string::npos);
}

TEST(ManifestHead, ListsTheSurfaceAndEveryInputFileWithItsHash) {
  ScratchDir dir;
  std::filesystem::copy_file(std::filesystem::path(BOOKSPIN_SOURCE_DIR) / "scenes/long-box.obj",
                             dir / "box.obj");
  std::ofstream(dir / "box.toml") << "[body]\nshape = \"mesh\"\nmesh = \"box.obj\"\n" << kScene;
  const scene::Scene scene = scene::parse_scene(dir / "box.toml");
  const std::string head = manifest_head("plot", JsonObject{}, scene);
  const std::string mesh_hash = *output::sha256_file(dir / "box.obj");
  // After the scene: the surface's hash (64 hex digits), then the inputs.
  const std::string surface = "  },\n  \"body_surface\": \"sha256:";
  const std::string inputs =
      "\",\n"
      "  \"inputs\": {\n"
      "    \"body.mesh\": \"sha256:" +
      mesh_hash +
      "\"\n"
      "  },\n";
  const auto at = head.find(surface);
  ASSERT_NE(at, std::string::npos);
  EXPECT_EQ(head.substr(at + surface.size() + 64), inputs);
}

TEST(ManifestHead, WithoutASceneIsTheFormatTheCommandAndTheMembers) {
  EXPECT_EQ(manifest_head("gallery", {{"page_sha256", {std::string("ab12")}}}),
            "  \"manifest\": 1,\n"
            "  \"command\": \"gallery\",\n"
            "  \"page_sha256\": \"ab12\",\n");
  EXPECT_EQ(manifest_head("x", JsonObject{}), "  \"manifest\": 1,\n  \"command\": \"x\",\n");
}

TEST(ManifestNote, IsTheSceneFilesPathAndHashOnOneLine) {
  ScratchDir dir;
  std::ofstream(dir / "book.toml") << kScene;
  const scene::Scene scene = scene::parse_scene(dir / "book.toml");
  EXPECT_EQ(manifest_note(scene),
            "  \"scene_file\": {\"path\": \"" +
                std::filesystem::weakly_canonical(dir / "book.toml").string() +
                "\", \"sha256\": \"sha256:" + sha256_text(kScene) + "\"},\n");
}

}  // namespace
}  // namespace bookspin::cache
