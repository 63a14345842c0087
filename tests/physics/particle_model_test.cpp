// The particle model's energy normalization (paper §3.2, docs/physics.md §2), step by step.
#include "physics/particle_model.hpp"

#include <gtest/gtest.h>

#include "model_helpers.hpp"

namespace bookspin::physics {
namespace {

using namespace bookspin::physics::testing;  // model_helpers.hpp

using physics::ModelKind;

/// Runs `steps` normalized steps and checks, after each, the rule of docs/physics.md §2: the
/// kinetic energy is max(E0 − U_start, 0.1·E0), U_start the spring energy at the start of
/// that step and E0 the energy at reset. Returns the largest U_start/E0 seen.
double check_normalization_rule(physics::Simulator& sim, double dt, long steps) {
  const double E0 = sim.diagnostics().energy_total;
  double highest = 0.0;
  for (long s = 0; s < steps; ++s) {
    const double U_start = sim.diagnostics().energy_potential;
    highest = std::max(highest, U_start / E0);
    sim.step(dt);
    const double expected = std::max(E0 - U_start, 0.1 * E0);
    const double kinetic = sim.diagnostics().energy_kinetic;
    if (std::abs(kinetic / expected - 1.0) > 1e-12) {
      ADD_FAILURE() << "step " << s << ": kinetic " << kinetic << ", expected " << expected
                    << " (U at step start " << U_start << ", E0 " << E0 << ")";
      break;
    }
  }
  return highest;
}

// With the paper's springs (k = 10) the springs stretch during the first steps, so the
// spring energy at step start and at step end differ by ~1e-9 relative per step: only the
// start value satisfies the rule.
TEST(ParticleNormalization, KineticEnergyIsEnergyAtResetMinusSpringEnergyAtStepStart) {
  auto sim = physics::make_simulator(original_book(), config(ModelKind::particle, true, true));
  sim->reset({original_omega0(0), 1e-3, 7});
  const double highest = check_normalization_rule(*sim, 1.0 / 60.0, 3000);
  EXPECT_GT(highest, 1e-7);  // the springs did stretch
}

// Very soft springs (k = 5e-5) let the spinning book stretch until the spring energy passes
// E0 (at step ~4400 of 1/60); the floor then holds the kinetic energy at 0.1·E0, where
// E0 − U_start alone would be negative (and its square root not a number).
TEST(ParticleNormalization, KineticEnergyNeverDropsBelowTheFloor) {
  auto sim =
      physics::make_simulator(original_book(), config(ModelKind::particle, true, false, 5e-5));
  sim->reset({original_omega0(0), 0.0, 7});
  const double highest = check_normalization_rule(*sim, 1.0 / 60.0, 20000);
  EXPECT_GT(highest, 1.0);  // the floor was in force
  EXPECT_TRUE(sim->finite());
}

// The springs' forces sum to zero only up to rounding, and damping's velocity-dependent
// forces let that rounding feed back: left alone, the centre of mass drifts (measured
// ~3e-13 after 1e5 steps). Normalization removes the mean velocity and recentres the
// corners every step, so both stay at round-off (docs/physics.md §2).
TEST(ParticleNormalization, CentreOfMassStaysAtTheOriginAndAtRest) {
  auto sim = physics::make_simulator(original_book(), config(ModelKind::particle, true, true));
  sim->reset({original_omega0(0), 1e-3, 7});
  const auto& particles = dynamic_cast<const physics::ParticleModel&>(*sim);
  double worst_centroid = 0.0, worst_velocity = 0.0;
  ASSERT_TRUE(run(*sim, 1.0 / 60.0, 100000, 500, [&](const physics::Simulator& s) {
    worst_centroid = std::max(worst_centroid, s.corners().rowwise().mean().norm());
    worst_velocity = std::max(worst_velocity, particles.velocities().rowwise().mean().norm());
  }));
  EXPECT_LT(worst_centroid, 2e-15);  // length units; the book is ~3.5 across
  EXPECT_LT(worst_velocity, 1e-16);  // length per time unit; corner speeds ~0.2
}

}  // namespace
}  // namespace bookspin::physics
