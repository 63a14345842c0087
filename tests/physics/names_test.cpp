// The physics' names listed whole (names.hpp): every model kind, integrator and body shape
// once, in the order of their enums, each name parsing back to its value (the explorer page
// offers these lists).
#include "physics/names.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "physics/body.hpp"
#include "physics/simulator.hpp"

namespace bookspin::physics {
namespace {

TEST(Names, ModelKindsListEveryKindOnceInOrder) {
  const std::vector<ModelKind> listed = model_kinds();
  const std::vector<ModelKind> expected{
      ModelKind::particle, ModelKind::rigid_matrix, ModelKind::rigid_quaternion,
      ModelKind::exact,    ModelKind::mujoco,       ModelKind::bullet,
      ModelKind::ode};
  EXPECT_EQ(listed, expected);
  for (ModelKind kind : listed) {
    ModelKind parsed = ModelKind::ode == kind ? ModelKind::particle : ModelKind::ode;
    EXPECT_TRUE(parse_model_kind(to_string(kind), parsed)) << to_string(kind);
    EXPECT_EQ(parsed, kind);
  }
}

TEST(Names, IntegratorsListEveryIntegratorOnceInOrder) {
  const std::vector<Integrator> listed = integrators();
  const std::vector<Integrator> expected{Integrator::euler,
                                         Integrator::symplectic_euler,
                                         Integrator::velocity_verlet,
                                         Integrator::rk4,
                                         Integrator::implicit_midpoint,
                                         Integrator::splitting,
                                         Integrator::splitting4,
                                         Integrator::implicit,
                                         Integrator::implicit_body,
                                         Integrator::implicit_world,
                                         Integrator::explicit_gyro,
                                         Integrator::none,
                                         Integrator::step,
                                         Integrator::quickstep,
                                         Integrator::rescaled_euler};
  EXPECT_EQ(listed, expected);
  for (Integrator integrator : listed) {
    Integrator parsed =
        integrator == Integrator::quickstep ? Integrator::euler : Integrator::quickstep;
    EXPECT_TRUE(parse_integrator(to_string(integrator), parsed)) << to_string(integrator);
    EXPECT_EQ(parsed, integrator);
  }
}

TEST(Names, EachModelSupportsAListedIntegrator) {
  // The explorer offers, per model, the listed integrators it supports: never none.
  for (ModelKind kind : model_kinds()) {
    int supported = 0;
    for (Integrator integrator : integrators()) supported += supports(kind, integrator) ? 1 : 0;
    EXPECT_GE(supported, 1) << to_string(kind);
  }
}

TEST(Names, BodyShapesListEveryShapeOnceInOrder) {
  const std::vector<BodyShape> listed(body_shapes().begin(), body_shapes().end());
  const std::vector<BodyShape> expected{BodyShape::book, BodyShape::t_handle,
                                        BodyShape::tennis_racket, BodyShape::phone,
                                        BodyShape::mesh};
  EXPECT_EQ(listed, expected);
  for (BodyShape shape : listed) {
    BodyShape parsed = shape == BodyShape::mesh ? BodyShape::book : BodyShape::mesh;
    EXPECT_TRUE(parse_body_shape(to_string(shape), parsed)) << to_string(shape);
    EXPECT_EQ(parsed, shape);
  }
}

}  // namespace
}  // namespace bookspin::physics
