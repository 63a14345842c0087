// model.normalize_every (docs/physics.md §18): which steps normalize, that N = 1 is the
// every-step normalization, and that a long interval lets the paper's Euler step diverge;
// for every model that normalizes, the lattice of a non-book body (§13) among them.
#include <gtest/gtest.h>

#include "model_helpers.hpp"
#include "physics/presets.hpp"
#include "physics/shape.hpp"

namespace bookspin::physics {
namespace {

using namespace bookspin::physics::testing;  // model_helpers.hpp

constexpr double kDt = 1.0 / 60.0;

physics::InitialState x_spin() { return {original_omega0(0), 0.001, 7}; }

struct Method {
  physics::ModelKind kind;
  physics::Integrator integrator;
  /// The particle model of the T-handle, a lattice (LatticeModel, docs/physics.md §13),
  /// instead of the book's.
  bool lattice = false;
};

std::string name(const Method& m) {
  return std::string(to_string(m.kind)) + " " + std::string(to_string(m.integrator)) +
         (m.lattice ? " (T-handle lattice)" : "");
}

/// The book, or for a lattice method the T-handle of mass 1 (a lattice of 4 cells along its
/// longest side: a few dozen particles, enough to be a lattice and quick to step).
std::unique_ptr<physics::Simulator> make_simulator(const Method& method, physics::ModelConfig c) {
  c.integrator = method.integrator;
  if (!method.lattice) return physics::make_simulator(original_book(), c);
  c.lattice_cells = 4;
  return physics::make_simulator(physics::preset_body(BodyShape::t_handle, 1.0, 1.0), c);
}

std::unique_ptr<physics::Simulator> make(const Method& method, bool normalize, int every) {
  physics::ModelConfig c = config(method.kind, normalize);
  c.normalize_every = every;
  auto sim = make_simulator(method, c);
  sim->reset(x_spin());
  return sim;
}

const Method kMethods[] = {{ModelKind::particle, Integrator::euler},
                           {ModelKind::particle, Integrator::euler, true},
                           {ModelKind::particle, Integrator::velocity_verlet, true},
                           {ModelKind::rigid_matrix, Integrator::euler},
                           {ModelKind::rigid_matrix, Integrator::rk4},
                           {ModelKind::rigid_quaternion, Integrator::euler},
                           {ModelKind::rigid_quaternion, Integrator::rk4}};

/// What a step changes: the corners and the kinetic energy (a particle model's normalization
/// scales its velocities and leaves the positions).
std::pair<Corners, double> state_of(const Simulator& sim) {
  return {sim.corners(), sim.diagnostics().energy_kinetic};
}

/// Steps 1 … N − 1 of an every-N run are the unnormalized run's bits; step N is not, and is
/// normalized (a unit quaternion, a rotation matrix, the centre of mass at the origin); the
/// same again from step N + 1 to 2N, with the count starting afresh at reset(). The rigid
/// models take steps of 0.25 so that RK4's drift off unit length shows in one step.
TEST(NormalizeEvery, NormalizesExactlyOnStepsNTwoNAndAfterReset) {
  constexpr int kEvery = 7;
  for (const Method& method : kMethods) {
    SCOPED_TRACE(name(method));
    const double dt = method.kind == ModelKind::particle ? kDt : 0.25;
    for (int round = 0; round < 2; ++round) {
      auto every = make(method, true, kEvery);
      if (round == 1) {  // the count starts again at reset
        for (int s = 0; s < 3; ++s) every->step(dt);
        every->reset(x_spin());
      }
      auto never = make(method, false, 1);
      const Eigen::Vector3d com_at_rest = never->center_of_mass();
      for (int block = 0; block < 2; ++block) {
        for (int s = 1; s < kEvery; ++s) {
          every->step(dt);
          never->step(dt);
          if (block == 0) {
            ASSERT_EQ(state_of(*every), state_of(*never)) << "step " << s;
          }
        }
        every->step(dt);
        never->step(dt);
        EXPECT_NE(state_of(*every), state_of(*never)) << "step " << (block + 1) * kEvery;
        if (method.kind == ModelKind::rigid_quaternion) {
          EXPECT_NEAR(every->diagnostics().quaternion_norm, 1.0, 1e-15);
          EXPECT_GT(std::abs(never->diagnostics().quaternion_norm - 1.0), 1e-13);
        }
        if (method.kind == ModelKind::rigid_matrix) {
          EXPECT_LT(every->diagnostics().orthogonality_error, 1e-13);
          EXPECT_GT(never->diagnostics().orthogonality_error, 1e-11);
        }
        if (method.kind == ModelKind::particle && !method.lattice) {
          EXPECT_LT(every->center_of_mass().norm(), 1e-15);
        }
        if (method.lattice) {  // back where the lattice's was at rest
          EXPECT_LT((every->center_of_mass() - com_at_rest).norm(), 1e-14);
        }
      }
    }
  }
}

/// N = 1 is today's every-step normalization: the same bits as the default configuration,
/// for every model and integrator that normalizes (the physics hashes pin the default).
TEST(NormalizeEvery, OneIsEveryStep) {
  for (const Method& method : kMethods) {
    auto one = make(method, true, 1);
    auto standard = make_simulator(method, config(method.kind, true));
    standard->reset(x_spin());
    for (int s = 0; s < 600; ++s) {
      one->step(kDt);
      standard->step(kDt);
    }
    EXPECT_EQ(one->corners(), standard->corners()) << name(method);
    EXPECT_EQ(one->diagnostics().energy_total, standard->diagnostics().energy_total);
  }
}

/// The paper's particle book, Euler at dt = 1/8 with damping: explicit Euler on its stiff,
/// damped springs is unstable at this step (docs/physics.md §18), and only the normalization,
/// which caps the kinetic energy at E0 − U, holds the growing mode down. Normalizing every
/// step or every 2nd keeps it finite for 10 flips; every 3rd step it diverges within 4 time
/// units, as it does at every longer interval and without normalization.
TEST(NormalizeEvery, ALongerIntervalLetsTheParticleBookDiverge) {
  constexpr double dt = 1.0 / 8.0;
  const long steps = static_cast<long>(2210.0 / dt);  // 10 flips of T/2 = 221
  auto diverged_at = [&](int every) {
    auto sim = make({ModelKind::particle, Integrator::euler}, true, every);
    for (long s = 1; s <= steps; ++s) {
      sim->step(dt);
      if (!sim->finite()) return s * dt;
    }
    return 0.0;
  };
  EXPECT_EQ(diverged_at(1), 0.0);
  EXPECT_EQ(diverged_at(2), 0.0);
  EXPECT_GT(diverged_at(3), 0.0);
  EXPECT_LT(diverged_at(3), 5.0);
  EXPECT_GT(diverged_at(10000), 0.0);
}

}  // namespace
}  // namespace bookspin::physics
