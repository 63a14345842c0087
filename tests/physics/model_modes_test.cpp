// The one table of models and their modes (physics::model_modes()) against the modes of
// docs/physics.md §10 and docs/engines.md spelled out here, and what supports(),
// default_integrator() and make_simulator() make of it.
#include "physics/model_modes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

namespace bookspin::physics {
namespace {

std::string name(ModelKind kind, Integrator integrator) {
  return std::string(to_string(kind)) + ":" + std::string(to_string(integrator));
}

/// Every mode, each model's default first, as the docs list them.
const std::vector<std::string> kDocumented{"particle:euler",
                                           "particle:symplectic-euler",
                                           "particle:velocity-verlet",
                                           "rigid-matrix:euler",
                                           "rigid-matrix:rk4",
                                           "rigid-matrix:implicit-midpoint",
                                           "rigid-matrix:splitting",
                                           "rigid-matrix:splitting4",
                                           "rigid-matrix:rescaled-euler",
                                           "rigid-quaternion:euler",
                                           "rigid-quaternion:rk4",
                                           "rigid-quaternion:implicit-midpoint",
                                           "rigid-quaternion:splitting",
                                           "rigid-quaternion:splitting4",
                                           "rigid-quaternion:rescaled-euler",
                                           "exact:euler",
                                           "mujoco:euler",
                                           "mujoco:rk4",
                                           "mujoco:implicit",
                                           "bullet:implicit-body",
                                           "bullet:implicit-world",
                                           "bullet:explicit",
                                           "bullet:none",
                                           "ode:step",
                                           "ode:quickstep",
                                           "ode:none"};

TEST(ModelModes, TheTableHoldsEveryDocumentedModeInOrder) {
  std::vector<std::string> table;
  for (const ModelMode& m : model_modes()) table.push_back(name(m.kind, m.integrator));
  EXPECT_EQ(table, kDocumented);
}

// supports() is a row of the table, every pair of kind and integrator asked; the default is
// the model's first row (the engines' own: docs/engines.md).
TEST(ModelModes, SupportsAndTheDefaultReadTheTable) {
  int supported = 0;
  for (ModelKind kind : model_kinds()) {
    for (Integrator integrator : integrators()) {
      const std::string pair = name(kind, integrator);
      const bool documented =
          std::find(kDocumented.begin(), kDocumented.end(), pair) != kDocumented.end();
      EXPECT_EQ(supports(kind, integrator), documented) << pair;
      supported += documented ? 1 : 0;
    }
  }
  EXPECT_EQ(supported, 26);
  EXPECT_EQ(default_integrator(ModelKind::particle), Integrator::euler);
  EXPECT_EQ(default_integrator(ModelKind::rigid_quaternion), Integrator::euler);
  EXPECT_EQ(default_integrator(ModelKind::exact), Integrator::euler);
  EXPECT_EQ(default_integrator(ModelKind::mujoco), Integrator::euler);
  EXPECT_EQ(default_integrator(ModelKind::bullet), Integrator::implicit_body);
  EXPECT_EQ(default_integrator(ModelKind::ode), Integrator::step);
  const auto unknown = static_cast<ModelKind>(99);
  EXPECT_FALSE(supports(unknown, Integrator::euler));
  EXPECT_THROW(default_integrator(unknown), std::logic_error);
}

// Every row of bookspin's own models makes a simulator that steps; the engines' rows are
// refused here (engines::make_model builds them), as is every pair not in the table and a
// kind with no row, never built as another model.
TEST(ModelModes, EveryOwnModeMakesASimulatorAndNoOther) {
  const Body book = book_body(Book{});
  for (ModelKind kind : model_kinds()) {
    for (Integrator integrator : integrators()) {
      const ModelConfig config{kind, integrator};
      if (!supports(kind, integrator) || is_engine(kind)) {
        EXPECT_THROW(make_simulator(book, config), std::invalid_argument) << name(kind, integrator);
        continue;
      }
      auto sim = make_simulator(book, config);
      sim->reset(InitialState{});
      sim->step(1.0 / 60.0);
      EXPECT_TRUE(sim->finite()) << name(kind, integrator);
      EXPECT_GT(sim->diagnostics().t, 0.0) << name(kind, integrator);
    }
  }
  EXPECT_THROW(make_simulator(book, {static_cast<ModelKind>(99), Integrator::euler}),
               std::logic_error);
}

TEST(ModelModes, OnlyMujocoBulletAndOdeAreOtherEngines) {
  std::vector<std::string> engines;
  for (ModelKind kind : model_kinds())
    if (is_engine(kind)) engines.emplace_back(to_string(kind));
  EXPECT_EQ(engines, (std::vector<std::string>{"mujoco", "bullet", "ode"}));
}

}  // namespace
}  // namespace bookspin::physics
