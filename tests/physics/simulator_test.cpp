// Simulator::cos_axis_L, the flip detector's signal read after every step without the rest of
// the diagnostics (the explorer's step loop, docs/explorer.md "Speed"): for every mode of every
// model make_simulator builds, with and without air drag where the model takes it, the same
// bits as diagnostics().cos_axis_L, from the start along a spin about the intermediate axis.
#include <gtest/gtest.h>

#include <string>

#include "model_helpers.hpp"
#include "physics/model_modes.hpp"

namespace bookspin::physics {
namespace {

using testing::config;
using testing::original_book;
using testing::original_omega0;

/// Checks every axis of `sim` at its current state; `where` names the mode and the step.
void expect_same_cosines(const Simulator& sim, const std::string& where) {
  const Eigen::Vector3d from_diagnostics = sim.diagnostics().cos_axis_L;
  for (int axis = 0; axis < 3; ++axis)
    EXPECT_EQ(sim.cos_axis_L(axis), from_diagnostics[axis]) << where << ", axis " << axis;
}

TEST(CosAxisL, EqualsTheDiagnosticsCosinesBitForBitForEveryModeWithAndWithoutDrag) {
  int modes = 0;
  for (const ModelMode& mode : model_modes()) {
    if (is_engine(mode.kind)) continue;
    for (const bool drag : {false, true}) {
      if (drag && !supports_drag(mode.kind)) continue;
      ModelConfig c = config(mode.kind, /*normalize=*/true);
      c.integrator = mode.integrator;
      if (drag) {
        c.drag.law = DragLaw::linear;
        c.drag.rate = 0.02;
      }
      auto sim = make_simulator(original_book(), c);
      InitialState initial;
      initial.omega0_body = original_omega0(0);  // about x, the book's intermediate axis
      initial.jiggle = 0.01;
      sim->reset(initial);
      const std::string name = std::string(to_string(mode.kind)) + " " +
                               std::string(to_string(mode.integrator)) + (drag ? " with drag" : "");
      ASSERT_TRUE(testing::run(*sim, 0.05, 4000, 97, [&](const Simulator& s) {
        expect_same_cosines(s, name + " at t = " + std::to_string(s.diagnostics().t));
      })) << name;
      ++modes;
    }
  }
  EXPECT_GE(modes, 16);  // particle ×3, rigid ×2×6 (and again with drag), exact ×2
}

}  // namespace
}  // namespace bookspin::physics
