// scene::model_line: a scene's model in words, as the caption and the plot sheet print it.
#include "scene/model_line.hpp"

#include <gtest/gtest.h>

namespace bookspin::scene {
namespace {

Scene with_model(physics::ModelKind kind, physics::Integrator integrator, double dt) {
  Scene scene;
  scene.model.kind = kind;
  scene.model.integrator = integrator;
  scene.dt = dt;
  return scene;
}

TEST(ModelLine, NamesTheModelIntegratorStepAndNormalization) {
  Scene s = with_model(physics::ModelKind::rigid_matrix, physics::Integrator::euler, 1.0 / 60.0);
  s.model.normalize = true;
  EXPECT_EQ(model_line(s), "rigid-matrix, euler, dt = 0.01667, normalized");
  s.model.normalize = false;
  EXPECT_EQ(model_line(s), "rigid-matrix, euler, dt = 0.01667, not normalized");
}

TEST(ModelLine, TheExactMotionHasNoStepAndAnEngineNoNormalizationSwitch) {
  EXPECT_EQ(model_line(with_model(physics::ModelKind::exact, physics::Integrator::euler, 0.01)),
            "exact");
  EXPECT_EQ(model_line(with_model(physics::ModelKind::mujoco, physics::Integrator::rk4, 0.01)),
            "mujoco, rk4, dt = 0.01");
}

TEST(ModelLine, TheParticleModelSaysItsDampingAndSpringConstant) {
  Scene s = with_model(physics::ModelKind::particle, physics::Integrator::symplectic_euler, 0.005);
  s.model.normalize = true;
  s.model.damping = false;
  s.model.spring_constant = 10.0;
  EXPECT_EQ(model_line(s), "particle, symplectic-euler, dt = 0.005, normalized, undamped, k = 10");
}

}  // namespace
}  // namespace bookspin::scene
