// The explorer page's scene data (src/products/explorer.hpp): every tile of a comparison listed
// (the other engines' replayed, docs/explorer.md "Comparison"), two of the page's own compared.
#include "products/explorer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "scene/page_data.hpp"
#include "scene/scene.hpp"
#include "support/scratch.hpp"

namespace bookspin::products {
namespace {

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

/// One scene's data as the page reads it.
std::string explorer_scene_json(const scene::Scene& scene) {
  return json_text({scene::page_data(scene)}, "test scene");
}

TEST(ExplorerSceneJson, EveryTileIsListedAndTheOwnModelsCompare) {
  const std::string engines_only =
      explorer_scene_json(scene::parse_scene_text("[[compare]]\nlabel = \"exact\"\nmodel.kind = "
                                                  "\"exact\"\n[[compare]]\nlabel = \"b\"\n"
                                                  "model.kind = \"bullet\"\n",
                                                  "test.toml", {}));
  EXPECT_TRUE(has(engines_only, "\"model\":\"exact\"")) << engines_only;
  EXPECT_FALSE(has(engines_only, "\"model2\"")) << engines_only;
  EXPECT_FALSE(has(engines_only, "\"compare\":true")) << engines_only;

  const std::string mixed = explorer_scene_json(scene::parse_scene_text(
      "[[compare]]\nlabel = \"q\"\nmodel.kind = \"rigid-quaternion\"\nmodel.integrator = "
      "\"rk4\"\n[[compare]]\nlabel = \"m\"\nmodel.kind = \"mujoco\"\n[[compare]]\nlabel = "
      "\"exact\"\nmodel.kind = \"exact\"\n",
      "test.toml", {}));
  EXPECT_TRUE(has(mixed, "\"model\":\"rigid-quaternion\"")) << mixed;
  EXPECT_TRUE(has(mixed, "\"compare\":true")) << mixed;
  EXPECT_TRUE(has(mixed, "\"model2\":\"exact\"")) << mixed;
  EXPECT_FALSE(has(mixed, "\"model2\":\"mujoco\"")) << mixed;
  // Every tile is listed, in order, the engines' too (the page replays them): none left out.
  EXPECT_TRUE(has(mixed,
                  "\"tiles\":[{\"label\":\"q\",\"model\":\"rigid-quaternion\","
                  "\"integrator\":\"rk4\",\"normalize\":false},{\"label\":\"m\","
                  "\"model\":\"mujoco\",\"integrator\":\"euler\","))
      << mixed;
  EXPECT_TRUE(has(mixed, "\"tiles\":true")) << mixed;
  EXPECT_TRUE(has(engines_only, "{\"label\":\"b\",\"model\":\"bullet\"")) << engines_only;
  EXPECT_FALSE(has(mixed, "left_out")) << mixed;

  // Four methods of the page's own: two compared with tiles=0 (the first and the last), all four
  // shown by the tiles.
  const std::string four = explorer_scene_json(scene::parse_scene_text(
      "[[compare]]\nlabel = \"e\"\nmodel.kind = \"rigid-matrix\"\n[[compare]]\nlabel = \"q\"\n"
      "model.kind = \"rigid-quaternion\"\n[[compare]]\nlabel = \"p\"\nmodel.kind = \"particle\"\n"
      "[[compare]]\nlabel = \"x\"\nmodel.kind = \"exact\"\n",
      "test.toml", {}));
  for (const char* label : {"e", "q", "p", "x"})
    EXPECT_TRUE(has(four, "{\"label\":\"" + std::string(label) + "\",")) << four;
  EXPECT_TRUE(has(four, "\"model2\":\"exact\"")) << four;

  const std::string alone =
      explorer_scene_json(scene::parse_scene_text("[model]\nkind = \"ode\"\n", "test.toml", {}));
  EXPECT_TRUE(has(alone, "\"model\":\"exact\"")) << alone;
}

// A book scene whose every number is given, as the page reads it: the text written out by hand
// from the scene file (speed = dt × steps_per_frame × fps = 0.5 × 2 × 25 time units per second;
// duration = (frames − 1) × dt × steps_per_frame = 299 × 0.5 × 2).
TEST(ExplorerSceneJson, ABookSceneIsTheTextThePageReads) {
  const std::string json = explorer_scene_json(scene::parse_scene_text(
      "[scene]\nname = \"b\"\ntitle = \"A \\\"book\\\"\"\ndescription = \"x</script>\"\n"
      "[model]\nkind = \"rigid-quaternion\"\nintegrator = \"rk4\"\nnormalize = true\n"
      "damping = false\nspring_constant = 2.5\n"
      "[book]\nsize = [1.5, 2, 0.25]\nmass = 3\n"
      "[initial]\nangular_velocity = [0.1, -2, 0]\njiggle = 0.001\nseed = 9223372036854775807\n"
      "[time]\ndt = 0.5\nsteps_per_frame = 2\n[render]\nfps = 25\nshow_body_axes = true\n",
      "test.toml", {}));
  EXPECT_EQ(json,
            "{\"name\":\"b\",\"title\":\"A \\\"book\\\"\",\"description\":\"x</script>\","
            "\"state\":{\"body\":\"book\",\"model\":\"rigid-quaternion\",\"integrator\":\"rk4\","
            "\"normalize\":true,\"damping\":false,\"k\":2.5,\"cells\":0,\"dt\":0.5,"
            "\"axis\":\"custom\",\"w\":[0.1,-2,0],\"jiggle\":0.001,\"seed\":9223372036854775807,"
            "\"speed\":25,\"showL\":false,\"showAxes\":true},"
            "\"book\":{\"size\":[1.5,2,0.25],\"mass\":3},\"duration\":299}");
}

// A scene's air drag (docs/physics.md §21) goes into the page's state as its law and rate, the
// state's keys drag and dragRate; a scene without drag carries neither (the page's none).
TEST(ExplorerSceneJson, AScenesAirDragIsInThePageState) {
  const std::string spin =
      "[initial]\nangular_velocity = [1, 0.01, 0]\n[model]\nkind = \"exact\"\n";
  const std::string damped = explorer_scene_json(
      scene::parse_scene_text(spin + "drag = \"quadratic\"\ndrag_rate = 0.25\n", "air.toml", {}));
  EXPECT_TRUE(has(damped, "\"drag\":\"quadratic\",\"dragRate\":0.25,")) << damped;
  const std::string free = explorer_scene_json(scene::parse_scene_text(spin, "free.toml", {}));
  EXPECT_FALSE(has(free, "drag")) << free;
}

// A scene's measured ω goes into the page whole, with each sample's L/|L| (L = I·ω with the
// book's moments m(b² + c²)/12, …: here a book 2 × 4 × 6 of mass 12, I = (52, 40, 20)), a
// sample with L = 0 left out of the trail.
TEST(ExplorerSceneJson, AMeasuredOmegaGoesInWithItsDirections) {
  bookspin::test::ScratchDir dir;
  std::ofstream(dir.path() / "w.csv") << "t,wx,wy,wz\n0,1,0,0\n0.5,0,0,0\n1,1,1,1\n";
  std::ofstream(dir.path() / "s.toml")
      << "[book]\nsize = [2, 4, 6]\nmass = 12\n[measured]\nomega = \"w.csv\"\n";
  const std::string json = explorer_scene_json(scene::parse_scene(dir.path() / "s.toml"));
  const std::string head =
      "\"measured\":{\"t\":[0,0.5,1],\"w\":[1,0,0,0,0,0,1,1,1],\"ut\":[0,1],\"u\":[1,0,0,";
  const std::size_t at = json.find(head);
  ASSERT_NE(at, std::string::npos) << json;
  std::istringstream rest(json.substr(at + head.size()));
  const double norm = std::sqrt(52.0 * 52 + 40 * 40 + 20 * 20);
  for (const double c : {52 / norm, 40 / norm, 20 / norm}) {
    double got = 0;
    char comma = 0;
    rest >> got >> comma;
    EXPECT_NEAR(got, c, 1e-15) << json;
  }
  EXPECT_FALSE(has(explorer_scene_json(scene::parse_scene_text("[book]\nmass = 2\n", "t.toml")),
                   "measured"));
}

}  // namespace
}  // namespace bookspin::products
