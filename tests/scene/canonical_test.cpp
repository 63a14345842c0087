// The canonical form of a scene (the manifests' "scene" member): the same for every way of
// writing one scene, different for every change of a value.
#include "scene/canonical.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>

#include "common/json_string.hpp"
#include "support/scratch.hpp"

namespace bookspin::scene {
namespace {

std::string canonical(const std::string& text, const std::vector<std::string>& overrides = {}) {
  return canonical_json(parse_scene_text(text, "dir/test.toml", overrides));
}

constexpr const char* kBase = R"toml(
[scene]
title = "A book"
[model]
kind = "rigid-matrix"
normalize = true
[time]
frames = 10
dt = 0.01
)toml";

TEST(CanonicalScene, SameForCommentsLayoutKeyOrderNumberSpellingAndSpelledOutDefaults) {
  const std::string other = R"toml(# a comment
[time]   # time first
dt = 1e-2
frames = 10

[model]
normalize = true  # SVD
kind = 'rigid-matrix'
[scene]
title = """A book"""
[book]
mass = 8.0
size = [1.878, 2.9085, 0.50]
)toml";
  EXPECT_EQ(canonical(kBase), canonical(other));
  // An override that sets a value the file already has is no change either.
  EXPECT_EQ(canonical(kBase), canonical(kBase, {"time.frames=10", "model.integrator=\"euler\""}));
}

TEST(CanonicalScene, EveryValueChangesIt) {
  const std::string base = canonical(kBase);
  for (const std::string assignment : {"scene.name=\"other\"",
                                       "scene.title=\"B\"",
                                       "scene.description=\"d\"",
                                       "model.kind=\"rigid-quaternion\"",
                                       "model.integrator=\"rk4\"",
                                       "model.normalize=false",
                                       "model.normalize_every=2",
                                       "model.damping=false",
                                       "model.spring_constant=11",
                                       "book.size=[1.878,2.9085,0.51]",
                                       "book.mass=8.000000000001",
                                       "initial.angular_velocity=[0.114819,0,1e-9]",
                                       "initial.jiggle=0.001",
                                       "initial.seed=2",
                                       "time.dt=0.010000000000000002",
                                       "model.lattice_cells=1",  // the book: one cell (0 = default)
                                       "render.sphere=true",
                                       "time.steps_per_frame=7",
                                       "time.frames=11",
                                       "render.width=1282",
                                       "render.height=722",
                                       "render.fps=31",
                                       "render.fov_y=31",
                                       "render.camera_distance=5",
                                       "render.camera_direction=[1,0.6,3.2]",
                                       "render.show_angular_momentum=true",
                                       "render.show_body_axes=true",
                                       "render.codec=\"h264_nvenc\"",
                                       "render.crf=19",
                                       "render.preset=\"slow\"",
                                       "render.png_compression=2",
                                       "render.anisotropy=2",
                                       "render.msaa=2",
                                       "render.panel=true"}) {
    EXPECT_NE(canonical(kBase, {assignment}), base) << assignment;
  }
}

TEST(CanonicalScene, BodiesAndSpinAxesAreResolved) {
  const std::string base = canonical(kBase);
  // The book's intermediate axis is x (docs/physics.md §1): the same ω0 as the default.
  EXPECT_EQ(canonical(kBase, {"initial.spin_axis=\"intermediate\"", "initial.spin_rate=0.114819"}),
            base);
  EXPECT_NE(canonical(kBase, {"initial.spin_axis=\"largest\"", "initial.spin_rate=0.114819"}),
            base);
  const std::string handle = canonical(kBase, {"body.shape=\"t-handle\""});
  EXPECT_NE(handle, base);
  EXPECT_NE(handle.find("\"body.shape\": \"t-handle\""), std::string::npos) << handle;
  EXPECT_NE(canonical(kBase, {"body.shape=\"t-handle\"", "body.mass=2"}), handle);
  EXPECT_NE(canonical(kBase, {"body.shape=\"t-handle\"", "body.scale=2"}), handle);
}

TEST(CanonicalScene, ComparisonTilesAreListedInOrder) {
  const std::string text = std::string(kBase) + R"toml(
[[compare]]
label = "SVD"
[[compare]]
label = "no SVD"
model.normalize = false
)toml";
  const std::string c = canonical(text);
  EXPECT_NE(c.find("\"compare[1].label\": \"SVD\""), std::string::npos) << c;
  EXPECT_NE(c.find("\"compare[2].model.normalize\": false"), std::string::npos) << c;
  std::string other = text;
  other.replace(other.rfind("normalize = false"), 17, "normalize = true");
  EXPECT_NE(c, canonical(other));
}

TEST(CanonicalScene, NumbersReadBackExactlyAndStringsAreEscaped) {
  const Scene s = parse_scene_text(kBase, "dir/test.toml", {"time.dt=0.1"});
  const std::string c = canonical_json(s);
  EXPECT_NE(c.find("\"time.dt\": 0.1,"), std::string::npos) << c;             // shortest round trip
  EXPECT_NE(c.find("\"time.steps_per_frame\": 6,"), std::string::npos) << c;  // the default
  EXPECT_EQ(json_string("a\"b\\c\n"), "\"a\\\"b\\\\c\\u000a\"");
}

/// Every key documented in scenes/README.md's key table appears in the canonical form, so a
/// key added to the reader and the README cannot be left out of the manifests.
TEST(CanonicalScene, HoldsEveryDocumentedKey) {
  std::ifstream readme(std::string(BOOKSPIN_SOURCE_DIR) + "/scenes/README.md");
  ASSERT_TRUE(readme);
  const std::string c = canonical(kBase);
  int documented = 0;
  for (std::string line; std::getline(readme, line);) {
    if (line.rfind("| `", 0) != 0) continue;
    const std::string first_cell = line.substr(0, line.find(" |", 2));
    // Every `a.b` in the first cell (a plain scan: GCC 12's std::regex trips
    // -Wmaybe-uninitialized in its own headers).
    for (auto open = first_cell.find('`'); open != std::string::npos;
         open = first_cell.find('`', open + 1)) {
      const auto close = first_cell.find('`', open + 1);
      if (close == std::string::npos) break;
      const std::string name = first_cell.substr(open + 1, close - open - 1);
      open = close;
      if (name.find('.') == std::string::npos) continue;
      if (name.rfind("model.", 0) == 0 && line.find("this panel") != std::string::npos)
        continue;  // the [[compare]] table
      ++documented;
      // Keys the reader resolves into others (canonical.hpp).
      const std::map<std::string, std::string> resolved{
          {"initial.spin_axis", "initial.angular_velocity"},
          {"initial.spin_rate", "initial.angular_velocity"},
          {"body.mass", "body.moments"},
          {"body.scale", "body.moments"},
          {"time.duration", "time.frames"}};
      if (name == "model.normalize_every") {  // listed where it is not 1 (canonical.hpp)
        EXPECT_EQ(c.find("normalize_every"), std::string::npos);
        EXPECT_NE(canonical(kBase, {"model.normalize_every=3"}).find("\"" + name + "\": 3"),
                  std::string::npos);
        continue;
      }
      if (name == "time.unit") {  // listed where given (canonical.hpp)
        EXPECT_EQ(c.find("time.unit"), std::string::npos);
        EXPECT_NE(canonical(kBase, {"time.unit=\"s\""}).find("\"time.unit\": \"s\""),
                  std::string::npos);
        continue;
      }
      if (name == "model.drag" || name == "model.drag_rate") {  // listed with drag only
        EXPECT_EQ(c.find("drag"), std::string::npos);
        const std::string with = canonical(
            kBase, {"model.kind=\"exact\"", "model.drag=\"quadratic\"", "model.drag_rate=0.25"});
        EXPECT_NE(with.find("\"model.drag\": \"quadratic\""), std::string::npos) << with;
        EXPECT_NE(with.find("\"model.drag_rate\": 0.25"), std::string::npos) << with;
        continue;
      }
      if (name == "measured.omega") {  // listed where given (canonical.hpp)
        EXPECT_EQ(c.find("measured"), std::string::npos);
        bookspin::test::ScratchDir dir;
        std::ofstream(dir.path() / "w.csv") << "t,wx,wy,wz\n0,1,2,3\n";
        const std::string with =
            canonical(kBase, {"measured.omega=\"" + (dir.path() / "w.csv").string() + "\""});
        EXPECT_NE(with.find("\"" + name + "\": "), std::string::npos) << with;
        continue;
      }
      const auto it = resolved.find(name);
      const std::string shown = it == resolved.end() ? name : it->second;
      EXPECT_NE(c.find("\"" + shown + "\": "), std::string::npos) << name;
    }
  }
  EXPECT_GE(documented, 30);
}

}  // namespace
}  // namespace bookspin::scene
