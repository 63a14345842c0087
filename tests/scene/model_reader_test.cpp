// model.integrator in the scene parser: every integrator name, and the models that take it.
#include <gtest/gtest.h>

#include "scene/scene.hpp"

namespace bookspin::scene {
namespace {

Scene parse(const std::string& text) { return parse_scene_text(text, "test.toml"); }

std::string model_table(const std::string& kind, const std::string& integrator) {
  return "[model]\nkind = \"" + kind + "\"\nintegrator = \"" + integrator + "\"\n";
}

std::string error_of(const std::string& text) {
  try {
    parse(text);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

TEST(ModelReader, Splitting4ParsesForBothRigidModels) {
  for (const std::string kind : {"rigid-matrix", "rigid-quaternion"}) {
    const Scene s = parse(model_table(kind, "splitting4"));
    EXPECT_EQ(s.model.integrator, physics::Integrator::splitting4) << kind;
  }
}

TEST(ModelReader, Splitting4IsRejectedByTheParticleAndExactModels) {
  for (const std::string kind : {"particle", "exact"}) {
    const std::string message = error_of(model_table(kind, "splitting4"));
    EXPECT_NE(message.find("model.integrator: model '" + kind +
                           "' does not support integrator 'splitting4'"),
              std::string::npos)
        << message;
  }
}

TEST(ModelReader, UnknownIntegratorListsEveryName) {
  const std::string message = error_of(model_table("rigid-matrix", "leapfrog"));
  EXPECT_NE(message.find("(expected euler, symplectic-euler, velocity-verlet, rk4, "
                         "implicit-midpoint, splitting, splitting4)"),
            std::string::npos)
      << message;
}

}  // namespace
}  // namespace bookspin::scene
