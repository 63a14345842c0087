// The explorer page's scene data (src/products/explorer.hpp): the page binds src/physics alone,
// so the other engines' tiles (docs/engines.md) stay out of it.
#include "products/explorer.hpp"

#include <gtest/gtest.h>

#include <string>

#include "scene/scene.hpp"

namespace bookspin::products {
namespace {

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(ExplorerSceneJson, TheEnginesTilesStayOutAndTheRestCompare) {
  const std::string engines_only =
      explorer_scene_json(scene::parse_scene_text("[[compare]]\nlabel = \"exact\"\nmodel.kind = "
                                                  "\"exact\"\n[[compare]]\nlabel = \"b\"\n"
                                                  "model.kind = \"bullet\"\n",
                                                  "test.toml", {}));
  EXPECT_TRUE(has(engines_only, "\"model\":\"exact\"")) << engines_only;
  EXPECT_FALSE(has(engines_only, "bullet")) << engines_only;
  EXPECT_FALSE(has(engines_only, "\"compare\":true")) << engines_only;

  const std::string mixed = explorer_scene_json(scene::parse_scene_text(
      "[[compare]]\nlabel = \"q\"\nmodel.kind = \"rigid-quaternion\"\nmodel.integrator = "
      "\"rk4\"\n[[compare]]\nlabel = \"m\"\nmodel.kind = \"mujoco\"\n[[compare]]\nlabel = "
      "\"exact\"\nmodel.kind = \"exact\"\n",
      "test.toml", {}));
  EXPECT_TRUE(has(mixed, "\"model\":\"rigid-quaternion\"")) << mixed;
  EXPECT_TRUE(has(mixed, "\"compare\":true")) << mixed;
  EXPECT_TRUE(has(mixed, "\"model2\":\"exact\"")) << mixed;
  EXPECT_FALSE(has(mixed, "mujoco")) << mixed;

  const std::string alone =
      explorer_scene_json(scene::parse_scene_text("[model]\nkind = \"ode\"\n", "test.toml", {}));
  EXPECT_TRUE(has(alone, "\"model\":\"exact\"")) << alone;
}

}  // namespace
}  // namespace bookspin::products
