// Integrators against the exact motion: convergence orders and the dt = 1/60 targets
// (docs/physics.md §10).
#include "analysis/accuracy.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "engines/models.hpp"
#include "physics/particle_model.hpp"
#include "physics/shape.hpp"
#include "support/physics_printers.hpp"

namespace bookspin::analysis {
namespace {

using analysis::Method;
using physics::Integrator;
using physics::ModelKind;

/// The original program's x-axis spin with a 1e-3 jiggle of L (docs/physics.md §5–6).
analysis::AccuracySettings original_x_spin() {
  analysis::AccuracySettings s;
  s.initial = {{0.114819, 0.0, 0.0}, 1e-3, 2012};
  s.model.normalize = true;
  return s;
}

struct OrderCase {
  Method method;
  double order;
  double dt = 0.0;  ///< coarse step; 0: 1/15 for order 4, 1/240 below
};

std::string name_of(const Method& m) {
  std::string name =
      std::string(physics::to_string(m.kind)) + "_" + std::string(physics::to_string(m.integrator));
  std::replace(name.begin(), name.end(), '-', '_');
  return name;
}

// gtest prints parameters into the names ctest registers; print a stable text, not bytes.
[[maybe_unused]] void PrintTo(const OrderCase& c, std::ostream* out) { *out << name_of(c.method); }

class RigidOrder : public ::testing::TestWithParam<OrderCase> {};

// Halving dt divides the orientation error by 2^order (within 10%) once dt is small enough
// for the leading term to dominate; measured at t = 20, well before the first flip.
TEST_P(RigidOrder, ErrorRatioWhenDtHalvesMatchesTheoreticalOrder) {
  const auto s = original_x_spin();
  const auto exact = analysis::exact_reference(s);
  const Method m = GetParam().method;
  const double dt =
      GetParam().dt > 0.0 ? GetParam().dt : (GetParam().order >= 4 ? 1.0 / 15.0 : 1.0 / 240.0);
  const double coarse = analysis::orientation_error_at(s, exact, m, dt, 20.0);
  const double fine = analysis::orientation_error_at(s, exact, m, dt / 2, 20.0);
  const double ratio = coarse / fine, expected = std::pow(2.0, GetParam().order);
  EXPECT_NEAR(ratio, expected, 0.1 * expected) << "errors " << coarse << ", " << fine;
}

INSTANTIATE_TEST_SUITE_P(
    Methods, RigidOrder,
    ::testing::Values(OrderCase{{ModelKind::rigid_matrix, Integrator::euler}, 1},
                      OrderCase{{ModelKind::rigid_matrix, Integrator::rk4}, 4},
                      OrderCase{{ModelKind::rigid_matrix, Integrator::implicit_midpoint}, 2},
                      OrderCase{{ModelKind::rigid_matrix, Integrator::splitting}, 2},
                      // splitting4 is ~1000× more accurate than RK4: at dt = 1/15 its error
                      // at t = 20 is near round-off (6e-14), at dt = 1/4 it is 1.3e-11.
                      OrderCase{{ModelKind::rigid_matrix, Integrator::splitting4}, 4, 0.25},
                      OrderCase{{ModelKind::rigid_quaternion, Integrator::euler}, 1},
                      OrderCase{{ModelKind::rigid_quaternion, Integrator::rk4}, 4},
                      OrderCase{{ModelKind::rigid_quaternion, Integrator::implicit_midpoint}, 2},
                      OrderCase{{ModelKind::rigid_quaternion, Integrator::splitting}, 2},
                      OrderCase{{ModelKind::rigid_quaternion, Integrator::splitting4}, 4, 0.25}),
    [](const auto& info) { return name_of(info.param.method); });

// The particle model is a different body (soft springs), so its integrators are measured
// against a very fine run of the same model: corner positions at t = 5, springs undamped and
// unnormalized so that every integrator solves the same smooth ODE.
/// Phase-space state (positions and velocities, 6×8) of the particle model at t_end: the
/// velocities matter, since symplectic Euler's positions alone can look second order.
Eigen::Matrix<double, 6, 8> particle_state(Integrator integrator, double dt, double t_end) {
  physics::ModelConfig c;
  c.kind = ModelKind::particle;
  c.integrator = integrator;
  c.damping = false;
  c.normalize = false;
  auto sim = physics::make_simulator(physics::Book{}, c);
  sim->reset({{0.114819, 0.0, 0.0}, 1e-3, 2012});
  const long steps = std::lround(t_end / dt);
  for (long i = 0; i < steps; ++i) sim->step(dt);
  Eigen::Matrix<double, 6, 8> state;
  state << sim->corners(), dynamic_cast<const physics::ParticleModel&>(*sim).velocities();
  return state;
}

class ParticleOrder : public ::testing::TestWithParam<std::pair<Integrator, double>> {};

TEST_P(ParticleOrder, ErrorRatioWhenDtHalvesMatchesTheoreticalOrder) {
  const auto [integrator, order] = GetParam();
  const double t_end = 5.0, dt = order >= 2 ? 1.0 / 100.0 : 1.0 / 800.0;
  const auto reference = particle_state(Integrator::velocity_verlet, 1.0 / 25600.0, t_end);
  const double coarse = (particle_state(integrator, dt, t_end) - reference).norm();
  const double fine = (particle_state(integrator, dt / 2, t_end) - reference).norm();
  const double expected = std::pow(2.0, order);
  EXPECT_NEAR(coarse / fine, expected, 0.1 * expected) << "errors " << coarse << ", " << fine;
}

INSTANTIATE_TEST_SUITE_P(Integrators, ParticleOrder,
                         ::testing::Values(std::pair{Integrator::euler, 1.0},
                                           std::pair{Integrator::symplectic_euler, 1.0},
                                           std::pair{Integrator::velocity_verlet, 2.0}),
                         [](const auto& info) {
                           std::string name(physics::to_string(info.param.first));
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

/// One 10-flip row at dt = 1/60 on the original x spin.
analysis::AccuracyRow ten_flips(ModelKind kind, Integrator integrator) {
  const auto s = original_x_spin();
  const auto row =
      analysis::measure(s, analysis::exact_reference(s), {kind, integrator}, 1.0 / 60.0);
  EXPECT_FALSE(row.diverged);
  EXPECT_GT(row.t_end, 9.99 * analysis::exact_reference(s).flip_period());
  return row;
}

// The targets at dt = 1/60 on the jiggled x spin over 10 flips (docs/physics.md §10; their
// costs per step are benchmark numbers, shown by `bookspin accuracy`, not asserted here).
// RK4 with R(q/|q|) in its stages: 6e-11 rad (4.8e-9 with R(q) of the non-unit stage q).
TEST(AccuracyTarget, QuaternionRk4IsWithin1e10RadAfterTenFlips) {
  const auto row = ten_flips(ModelKind::rigid_quaternion, Integrator::rk4);
  EXPECT_LT(row.orientation_error, 1e-10);
  EXPECT_LT(row.flip_period_error, 1e-9);
}

// The sorted splitting: 3.5e-7 rad (1.4e-5 in the index order x, y, z).
TEST(AccuracyTarget, SortedSplittingIsWithin5e7RadAfterTenFlips) {
  for (ModelKind kind : {ModelKind::rigid_matrix, ModelKind::rigid_quaternion}) {
    const auto row = ten_flips(kind, Integrator::splitting);
    EXPECT_LT(row.orientation_error, 5e-7) << physics::to_string(kind);
  }
}

// The fourth-order composition: far below 1e-8 rad, and its energy error is that of a
// fourth-order method (the splitting's is ~3e-7).
TEST(AccuracyTarget, Splitting4IsWithin1e8RadAfterTenFlips) {
  for (ModelKind kind : {ModelKind::rigid_matrix, ModelKind::rigid_quaternion}) {
    const auto row = ten_flips(kind, Integrator::splitting4);
    EXPECT_LT(row.orientation_error, 1e-8) << physics::to_string(kind);
    EXPECT_LT(row.energy_drift, 1e-9) << physics::to_string(kind);
  }
}

// The rigid models take Π = RᵀL afresh every step, so |Π| = |L| exactly and rounding does
// not accumulate in the energy: at dt = 1/240 (530 000 steps) splitting4's energy error stays
// near round-off (3e-14). Carrying Π from step to step instead drifts it to 1.5e-12.
TEST(AccuracyTarget, Splitting4EnergyStaysNearRoundOffAtSmallSteps) {
  const auto s = original_x_spin();
  const auto row =
      analysis::measure(s, analysis::exact_reference(s),
                        {ModelKind::rigid_quaternion, Integrator::splitting4}, 1.0 / 240.0);
  EXPECT_LT(row.energy_drift, 2e-13);
  EXPECT_LT(row.orientation_error, 1e-9);
}

// Implicit midpoint conserves the energy (a quadratic invariant) to round-off.
TEST(AccuracyTarget, ImplicitMidpointConservesEnergy) {
  auto s = original_x_spin();
  s.flips = 2;
  const auto exact = analysis::exact_reference(s);
  for (ModelKind kind : {ModelKind::rigid_matrix, ModelKind::rigid_quaternion}) {
    const auto row = analysis::measure(s, exact, {kind, Integrator::implicit_midpoint}, 1.0 / 60.0);
    EXPECT_LT(row.energy_drift, 1e-12);
  }
}

// A step the implicit midpoint cannot solve makes the row diverged, with the reason.
TEST(AccuracyTarget, NonConvergedImplicitMidpointRowIsDivergedWithAReason) {
  const auto s = original_x_spin();
  const auto row =
      analysis::measure(s, analysis::exact_reference(s),
                        {ModelKind::rigid_quaternion, Integrator::implicit_midpoint}, 150.0);
  EXPECT_TRUE(row.diverged);
  EXPECT_NE(row.divergence_reason.find("did not converge"), std::string::npos)
      << row.divergence_reason;
}

// The flip spacing of a very fine RK4 run is the exact 2K(k)/λ.
TEST(AccuracyTarget, FineRk4FlipSpacingMatchesEllipticPeriod) {
  auto s = original_x_spin();
  s.flips = 4;
  const auto exact = analysis::exact_reference(s);
  const auto row =
      analysis::measure(s, exact, {ModelKind::rigid_matrix, Integrator::rk4}, 1.0 / 240.0);
  const double elliptic = 2.0 * std::comp_ellint_1(exact.modulus()) / exact.lambda();
  EXPECT_NEAR(row.flip_period / elliptic, 1.0, 1e-6);
}

}  // namespace
}  // namespace bookspin::analysis

namespace bookspin::analysis {
namespace {

// The flip columns: ten exact flip periods T/2 hold exactly ten flips of the exact motion (one
// zero of sn per half period, docs/physics.md §14); RK4 sees each of them, its first within
// 1e-9 of the exact first flip. An engine without its gyroscopic term never flips
// (docs/engines.md): no first flip, none counted.
TEST(AccuracyFlips, TenFlipPeriodsHoldTenFlipsAndTheEnginesWithoutTheTermNone) {
  const analysis::AccuracySettings s = original_x_spin();
  const auto exact = exact_reference(s);
  const auto rk4 = measure(s, exact, {ModelKind::rigid_quaternion, Integrator::rk4}, 1.0 / 60.0);
  EXPECT_EQ(rk4.flips_exact, 10);
  EXPECT_EQ(rk4.flips, 10);
  EXPECT_LT(rk4.first_flip_error, 1e-9);
  const auto none = measure(s, exact, {ModelKind::ode, Integrator::none}, 1.0 / 60.0);
  EXPECT_EQ(none.flips_exact, 10);
  EXPECT_EQ(none.flips, 0);
  EXPECT_TRUE(std::isnan(none.first_flip));
}

// ns_per_step is the time of the steps timed over their count: up to 200,000 steps of each
// method (docs/accuracy.md), not every step of the run. A clock that moves by exactly 1e9 ns
// between its readings stands in for the steady clock, so nothing is timed: a run of one flip
// at dt = 1/1000 (about 221,000 steps) costs 1e9 / 200,000 = 5000 ns a step, and one at
// dt = 1/60 (about 13,000 steps, all timed) 1e9 / steps.
TEST(AccuracyCost, NsPerStepIsTheClocksTimeOverTheStepsTimed) {
  analysis::AccuracySettings s = original_x_spin();
  s.flips = 1;
  int readings = 0;
  s.clock_ns = [&readings] { return 1e9 * ++readings; };
  const auto exact = exact_reference(s);
  const Method euler{ModelKind::rigid_quaternion, Integrator::euler};

  const auto fine = measure(s, exact, euler, 1.0 / 1000.0);
  EXPECT_EQ(readings, 2);  // once before the timed steps, once after
  ASSERT_GT(fine.steps, 200000);
  EXPECT_DOUBLE_EQ(fine.ns_per_step, 5000.0);

  readings = 0;
  const auto coarse = measure(s, exact, euler, 1.0 / 60.0);
  EXPECT_EQ(readings, 2);
  ASSERT_LT(coarse.steps, 200000);
  ASSERT_GT(coarse.steps, 10000);
  EXPECT_DOUBLE_EQ(coarse.ns_per_step, 1e9 / static_cast<double>(coarse.steps));
}

// The accuracy rows are bookspin's methods and every engine mode; all_methods() (which the
// bench and the explorer's benchmark time against the page) holds no engine.
TEST(AccuracyFlips, EveryEngineModeIsAnAccuracyRowAndNoneOfAllMethods) {
  int engines = 0;
  for (const Method& m : accuracy_methods()) engines += physics::is_engine(m.kind) ? 1 : 0;
  EXPECT_EQ(engines, static_cast<int>(engines::engine_modes().size()));
  EXPECT_GT(engines, 0);
  for (const Method& m : all_methods()) EXPECT_FALSE(physics::is_engine(m.kind));
}

// --methods: the names a user types, against the pairs of docs/accuracy.md spelled out here.
TEST(AccuracyMethods, AListNamesTheMethodsInTableOrderEachOnce) {
  const auto names = [](const std::vector<Method>& methods) {
    std::vector<std::string> out;
    for (const Method& m : methods)
      out.push_back(std::string(physics::to_string(m.kind)) + ":" +
                    std::string(physics::to_string(m.integrator)));
    return out;
  };
  using Names = std::vector<std::string>;
  EXPECT_EQ(names(parse_methods("mujoco")),
            (Names{"mujoco:euler", "mujoco:rk4", "mujoco:implicit"}));
  EXPECT_EQ(names(parse_methods("ode:none,rigid-quaternion:rk4,ode")),
            (Names{"rigid-quaternion:rk4", "ode:step", "ode:quickstep", "ode:none"}));
  EXPECT_EQ(names(parse_methods("engines")),
            (Names{"mujoco:euler", "mujoco:rk4", "mujoco:implicit", "bullet:implicit-body",
                   "bullet:implicit-world", "bullet:explicit", "bullet:none", "ode:step",
                   "ode:quickstep", "ode:none"}));
  EXPECT_EQ(parse_methods("rigid").size(), 12u);  // 2 models × 6 integrators
  EXPECT_EQ(parse_methods("particle").size(), 3u);
  EXPECT_EQ(parse_methods("all").size(), 3u + 12u + 10u);
  EXPECT_EQ(parse_methods("rigid,all").size(), 25u);
}

TEST(AccuracyMethods, EachMethodIsLabelledByItsModelAndIntegratorNames) {
  // The names of scenes/README.md's model.kind and model.integrator rows, as the tables print them.
  EXPECT_EQ(parse_methods("rigid-quaternion:rk4").front().label, "rigid-quaternion rk4");
  EXPECT_EQ(parse_methods("bullet:implicit-world").front().label, "bullet implicit-world");
  EXPECT_EQ(parse_methods("particle:velocity-verlet").front().label, "particle velocity-verlet");
  for (const Method& m : accuracy_methods()) EXPECT_FALSE(m.label.empty());
}

TEST(AccuracyMethods, UnknownEmptyExactOrUnsupportedNamesAreInputErrors) {
  for (const char* bad : {"", ",", "rk4", "engines,", "exact", "exact:euler", "mujoco:step",
                          "particle:rk4", "rigid-matrix:", "bullet:implicit"}) {
    SCOPED_TRACE(bad);
    EXPECT_THROW(parse_methods(bad), InputError);
  }
}

}  // namespace
}  // namespace bookspin::analysis
