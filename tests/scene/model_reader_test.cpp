// The model reader: model.integrator, [[compare]] entries and render keys in the scene parser.
#include <gtest/gtest.h>

#include "scene/scene.hpp"
#include "scene_text.hpp"

namespace bookspin::scene {
namespace {

using testing::error_of;
using testing::parse;

/// A scene whose only table is [render] holding `keys` (TOML, one line).
Scene with_render(const std::string& keys) { return parse("[render]\n" + keys + "\n"); }

TEST(CompareKeys, PanelsInheritTheSceneModelAndOverrideTheirOwnKeys) {
  const Scene s = parse(R"toml(
[model]
kind = "rigid-matrix"
normalize = true

[[compare]]
label = "Matrix, Euler"

[[compare]]
label = "quaternion (RK4)"
model.kind = "rigid-quaternion"
model.integrator = "rk4"

[[compare]]
label = "no SVD"
model = { normalize = false }
)toml");
  ASSERT_EQ(s.compare.size(), 3u);
  EXPECT_EQ(s.compare[0].name, "matrix-euler");
  EXPECT_EQ(s.compare[0].model.kind, physics::ModelKind::rigid_matrix);
  EXPECT_TRUE(s.compare[0].model.normalize);
  EXPECT_EQ(s.compare[1].name, "quaternion-rk4");
  EXPECT_EQ(s.compare[1].model.kind, physics::ModelKind::rigid_quaternion);
  EXPECT_EQ(s.compare[1].model.integrator, physics::Integrator::rk4);
  EXPECT_TRUE(s.compare[1].model.normalize);
  EXPECT_FALSE(s.compare[2].model.normalize);
}

TEST(CompareKeys, PanelSceneCarriesThePanelModelAndLabel) {
  const Scene s = parse(R"toml(
[scene]
name = "cmp"

[[compare]]
label = "Exact"
model.kind = "exact"
)toml");
  const Scene p = tile_scene(s, s.compare[0]);
  EXPECT_EQ(p.model.kind, physics::ModelKind::exact);
  EXPECT_EQ(p.title, "Exact");
  EXPECT_EQ(p.name, "cmp-exact");
  EXPECT_TRUE(p.compare.empty());
}

TEST(CompareKeys, PanelDefaultsOffAndParses) {
  EXPECT_FALSE(with_render("width = 640").render.panel);
  EXPECT_TRUE(with_render("panel = true").render.panel);
  EXPECT_TRUE(with_render("width = 640").compare.empty());
}

TEST(RenderKeys, AnisotropyDefaultsToAutomaticAndParses) {
  EXPECT_EQ(with_render("width = 640").render.anisotropy, 0);
  EXPECT_EQ(with_render("anisotropy = 8").render.anisotropy, 8);
}

TEST(RenderKeys, MsaaDefaultsToFourAndParses) {
  EXPECT_EQ(with_render("width = 640").render.msaa, 4);
  EXPECT_EQ(with_render("msaa = 1").render.msaa, 1);
}

TEST(CompareKeys, ErrorsNameTheEntry) {
  const auto message = [](const std::string& text) {
    try {
      parse(text);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message(R"toml([[compare]]
label = "a"
speed = 2
)toml"),
            "test.toml:3: compare[1].speed: unknown key");
  EXPECT_EQ(message(R"toml([[compare]]
label = "!!"
)toml"),
            "test.toml:2: compare[1].label: must contain a letter or digit");
  EXPECT_EQ(message(R"toml([[compare]]
label = 3
)toml"),
            "test.toml:2: compare[1].label: expected a string, got an integer");
  std::string many;
  for (int i = 0; i < 10; ++i) many += "[[compare]]\nlabel = \"p" + std::to_string(i) + "\"\n";
  EXPECT_EQ(message(many), "test.toml:1: compare: expected 1 to 9 [[compare]] entries, got 10");
}

TEST(CompareKeys, SetOverrideOfTheWholeArrayIsNamedAsSuch) {
  try {
    parse_scene_text("[model]\nkind = \"exact\"\n", "test.toml",
                     {"compare=[{label = \"a\", colour = 1}]"});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "--set compare[1].colour: unknown key");
  }
}

// model.integrator: every integrator name, and the models that take it.

std::string model_table(const std::string& kind, const std::string& integrator) {
  return "[model]\nkind = \"" + kind + "\"\nintegrator = \"" + integrator + "\"\n";
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
                         "implicit-midpoint, splitting, splitting4, implicit, implicit-body, "
                         "implicit-world, explicit, none, step, quickstep, rescaled-euler)"),
            std::string::npos)
      << message;
}

// Each engine's default mode when the scene names none (docs/engines.md), also for a tile
// whose base model is another kind.
TEST(ModelReader, EnginesTakeTheirOwnDefaultIntegrator) {
  const std::pair<std::string, physics::Integrator> defaults[] = {
      {"mujoco", physics::Integrator::euler},
      {"bullet", physics::Integrator::implicit_body},
      {"ode", physics::Integrator::step}};
  for (const auto& [kind, integrator] : defaults) {
    const Scene s = parse(
        "[model]\nkind = \"rigid-quaternion\"\nintegrator = "
        "\"rk4\"\n[[compare]]\nlabel = \"e\"\nmodel.kind = \"" +
        kind + "\"\n");
    EXPECT_EQ(s.compare[0].model.integrator, integrator) << kind;
    const Scene alone = parse("[model]\nkind = \"" + kind + "\"\n");
    EXPECT_EQ(alone.model.integrator, integrator) << kind;
  }
}

// A tile takes only the keys that apply to its model: the exact and the particle model have no
// rk4, so their tiles in an rk4 scene take their own default (euler); a rigid tile keeps the
// scene's rk4; a tile that names rk4 for a model without it is still refused.
TEST(ModelReader, TilesOfModelsWithoutTheScenesIntegratorTakeTheirOwnDefault) {
  const Scene s = parse(R"toml(
[model]
kind = "rigid-quaternion"
integrator = "rk4"
normalize = true
[[compare]]
label = "exact"
model.kind = "exact"
[[compare]]
label = "particle"
model.kind = "particle"
[[compare]]
label = "matrix"
model.kind = "rigid-matrix"
)toml");
  ASSERT_EQ(s.compare.size(), 3u);
  EXPECT_EQ(s.compare[0].model.integrator, physics::Integrator::euler);
  EXPECT_EQ(s.compare[1].model.integrator, physics::Integrator::euler);
  EXPECT_EQ(s.compare[2].model.integrator, physics::Integrator::rk4);
  EXPECT_TRUE(s.compare[2].model.normalize);
  EXPECT_NE(error_of("[model]\nkind = \"rigid-quaternion\"\nintegrator = \"rk4\"\n[[compare]]\n"
                     "label = \"x\"\nmodel.kind = \"exact\"\nmodel.integrator = \"rk4\"\n")
                .find("compare[1].model.integrator: model 'exact' does not support integrator "
                      "'rk4'"),
            std::string::npos);
}

TEST(ModelReader, EnginesRefuseOtherEnginesModesAndBookspinsSettings) {
  EXPECT_NE(error_of(model_table("bullet", "rk4"))
                .find("model 'bullet' does not support integrator 'rk4' (expected implicit-body, "
                      "implicit-world, explicit, none)"),
            std::string::npos);
  EXPECT_NE(error_of(model_table("mujoco", "quickstep")).find("(expected euler, rk4, implicit)"),
            std::string::npos);
  EXPECT_NE(error_of(model_table("ode", "implicit-body")).find("(expected step, quickstep, none)"),
            std::string::npos);
  for (const std::string key : {"normalize = true", "normalize_every = 4", "damping = false",
                                "spring_constant = 5.0", "lattice_cells = 4"}) {
    const std::string message = error_of(model_table("ode", "step") + key + "\n");
    const std::string name = key.substr(0, key.find(' '));
    EXPECT_NE(message.find("model." + name + ": model 'ode' (another engine) has no such setting"),
              std::string::npos)
        << message;
  }
}

}  // namespace
}  // namespace bookspin::scene
