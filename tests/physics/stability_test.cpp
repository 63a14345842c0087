// Stable and unstable principal axes, for every model (docs/physics.md §1, §7).
#include <gtest/gtest.h>

#include <numbers>

#include "model_helpers.hpp"
#include "support/physics_printers.hpp"

namespace bookspin::physics {
namespace {

using namespace bookspin::physics::testing;  // model_helpers.hpp

using physics::ModelKind;
constexpr double kDt = 1.0 / 60.0;

class Stability : public ::testing::TestWithParam<ModelKind> {
 protected:
  std::unique_ptr<physics::Simulator> start(int axis) {
    auto sim = physics::make_simulator(original_book(), config(GetParam(), true, true));
    sim->reset({original_omega0(axis), 1e-3, 3});
    return sim;
  }
};

// y (smallest moment) and z (largest) are stable: the axis stays within 0.99 of L.
TEST_P(Stability, SpinAboutYOrZStaysOnAxisFor20Revolutions) {
  for (int axis : {1, 2}) {
    auto sim = start(axis);
    const double revolution = 2.0 * std::numbers::pi / original_omega0(axis)[axis];
    const long steps = static_cast<long>(20.0 * revolution / kDt);
    double worst = 1.0;
    ASSERT_TRUE(run(*sim, kDt, steps, 10, [&](const physics::Simulator& s) {
      worst = std::min(worst, s.diagnostics().cos_axis_L[axis]);
    }));
    EXPECT_GT(worst, 0.99) << "axis " << axis;
  }
}

// x (intermediate moment) is unstable: the book flips, so the x axis turns against L.
TEST_P(Stability, SpinAboutXFlips) {
  auto sim = start(0);
  double lowest = 1.0;
  run(*sim, kDt, 60000, 10, [&](const physics::Simulator& s) {
    lowest = std::min(lowest, s.diagnostics().cos_axis_L[0]);
  });
  EXPECT_LT(lowest, -0.9);
}

INSTANTIATE_TEST_SUITE_P(AllModels, Stability,
                         ::testing::Values(ModelKind::particle, ModelKind::rigid_matrix,
                                           ModelKind::rigid_quaternion),
                         [](const auto& info) {
                           std::string name(physics::to_string(info.param));
                           std::erase(name, '-');
                           return name;
                         });

}  // namespace
}  // namespace bookspin::physics
