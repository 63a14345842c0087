// The engines' models (src/engines, docs/engines.md) against the engines called directly here,
// against the exact motion, and about the largest axis.
#include "engines/models.hpp"

#include <btBulletDynamicsCommon.h>
#include <gtest/gtest.h>
#include <mujoco/mujoco.h>
#include <ode/ode.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "common/errors.hpp"
#include "physics/exact_solution.hpp"
#include "physics/model_modes.hpp"
#include "physics/presets.hpp"
#include "support/scratch.hpp"

namespace bookspin::engines {
namespace {

using physics::Integrator;
using physics::ModelKind;

using Mode = EngineMode;

/// Every mode the room offers; AccuracyFlips.EveryEngineModeIsAnAccuracyRowAndNoneOfAllMethods
/// counts them.
std::vector<Mode> every_mode() { return engine_modes(); }

std::string name(const Mode& m) {
  return std::string(physics::to_string(m.kind)) + " " +
         std::string(physics::to_string(m.integrator));
}

/// The modes of one engine, in the order of engine_modes().
std::vector<Mode> rows_of(ModelKind kind) {
  std::vector<Mode> rows;
  for (const Mode& m : engine_modes())
    if (m.kind == kind) rows.push_back(m);
  return rows;
}

// --- Each engine called directly: a plain program's use of its API, written here on its own. ---

/// MuJoCo from an MJCF file: a free body with inertial mass and diaginertia, ω0 in qvel[3..5].
Eigen::Vector3d mujoco_direct(double mass, const Eigen::Vector3d& I, const Eigen::Vector3d& omega0,
                              const char* integrator, double dt, int steps) {
  // In the running test's own scratch folder: no other test process shares the file.
  const bookspin::test::ScratchDir dir;
  const std::string path = (dir / (std::string("mujoco-") + integrator + ".xml")).string();
  {
    std::ofstream xml(path);
    xml.precision(17);
    xml << "<mujoco><option timestep=\"" << dt << "\" gravity=\"0 0 0\" integrator=\"" << integrator
        << "\"><flag contact=\"disable\"/></option><worldbody><body><freejoint/>"
        << "<inertial pos=\"0 0 0\" mass=\"" << mass << "\" diaginertia=\"" << I.x() << ' ' << I.y()
        << ' ' << I.z() << "\"/></body></worldbody></mujoco>";
  }
  char error[500] = "";
  mjModel* m = mj_loadXML(path.c_str(), nullptr, error, sizeof error);
  std::remove(path.c_str());
  EXPECT_NE(m, nullptr) << error;
  if (m == nullptr) return Eigen::Vector3d::Constant(NAN);
  mjData* d = mj_makeData(m);
  for (int i = 0; i < 3; ++i) d->qvel[3 + i] = omega0[i];
  for (int i = 0; i < steps; ++i) mj_step(m, d);
  const Eigen::Vector3d omega(d->qvel[3], d->qvel[4], d->qvel[5]);
  mj_deleteData(d);
  mj_deleteModel(m);
  return omega;
}

/// Bullet: one rigid body with local inertia I in a world without gravity, one step of dt each.
Eigen::Vector3d bullet_direct(double mass, const Eigen::Vector3d& I, const Eigen::Vector3d& omega0,
                              int flags, double dt, int steps) {
  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher(&configuration);
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world(&dispatcher, &broadphase, &solver, &configuration);
  world.setGravity(btVector3(0, 0, 0));
  btBoxShape shape(btVector3(0.5, 0.5, 0.5));
  btRigidBody body(mass, nullptr, &shape, btVector3(I.x(), I.y(), I.z()));
  body.setActivationState(DISABLE_DEACTIVATION);
  body.setFlags(flags);
  body.setAngularVelocity(btVector3(omega0.x(), omega0.y(), omega0.z()));
  world.addRigidBody(&body);
  for (int i = 0; i < steps; ++i) world.stepSimulation(dt, 0);
  const btVector3 w = body.getWorldTransform().getBasis().transpose() * body.getAngularVelocity();
  world.removeRigidBody(&body);
  return {w.x(), w.y(), w.z()};
}

/// ODE: one body with dMassSetParameters' diagonal inertia, dWorldStep or dWorldQuickStep.
Eigen::Vector3d ode_direct(double mass, const Eigen::Vector3d& I, const Eigen::Vector3d& omega0,
                           bool gyroscopic, bool quick, double dt, int steps) {
  dInitODE2(0);
  dWorldID world = dWorldCreate();
  dWorldSetGravity(world, 0, 0, 0);
  dBodyID body = dBodyCreate(world);
  dMass m;
  dMassSetParameters(&m, mass, 0, 0, 0, I.x(), I.y(), I.z(), 0, 0, 0);
  dBodySetMass(body, &m);
  dBodySetGyroscopicMode(body, gyroscopic);
  dBodySetAngularVel(body, omega0.x(), omega0.y(), omega0.z());
  for (int i = 0; i < steps; ++i) quick ? dWorldQuickStep(world, dt) : dWorldStep(world, dt);
  dVector3 w;
  const dReal* ww = dBodyGetAngularVel(body);
  dBodyVectorFromWorld(body, ww[0], ww[1], ww[2], w);
  dWorldDestroy(world);
  return {w[0], w[1], w[2]};
}

Eigen::Vector3d direct(const Mode& mode, double mass, const Eigen::Vector3d& I,
                       const Eigen::Vector3d& omega0, double dt, int steps) {
  switch (mode.kind) {
    case ModelKind::mujoco:
      return mujoco_direct(mass, I, omega0,
                           mode.integrator == Integrator::rk4        ? "RK4"
                           : mode.integrator == Integrator::implicit ? "implicit"
                                                                     : "Euler",
                           dt, steps);
    case ModelKind::bullet: {
      const int flags = mode.integrator == Integrator::implicit_body    ? 8  // IMPLICIT_BODY
                        : mode.integrator == Integrator::implicit_world ? 4  // IMPLICIT_WORLD
                        : mode.integrator == Integrator::explicit_gyro  ? 2  // EXPLICIT
                                                                        : 0;
      return bullet_direct(mass, I, omega0, flags, dt, steps);
    }
    case ModelKind::ode:
      return ode_direct(mass, I, omega0, mode.integrator != Integrator::none,
                        mode.integrator == Integrator::quickstep, dt, steps);
    default:
      ADD_FAILURE() << name(mode) << ": no engine to call directly";
      return Eigen::Vector3d::Constant(NAN);
  }
}

Eigen::Vector3d model_omega(const physics::Body& body, const Mode& mode,
                            const Eigen::Vector3d& omega0, double dt, int steps) {
  auto sim = make_model(body, {mode.kind, mode.integrator});
  physics::InitialState initial;
  initial.omega0_body = omega0;
  sim->reset(initial);
  for (int i = 0; i < steps; ++i) sim->step(dt);
  return sim->diagnostics().omega_body;
}

// The book (moments y < x < z) and the T-handle (x < y < z), spun near the intermediate axis
// with some of the other two; 600 steps of 1/60 take the book past its first flip.
TEST(EngineModels, EachModelStepsAsItsEngineCalledDirectly) {
  const physics::Body bodies[] = {physics::book_body(physics::Book{}),
                                  physics::preset_body(physics::BodyShape::t_handle, 1.0, 1.0)};
  const Eigen::Vector3d spins[] = {{0.114819, 0.002, 0.003}, {0.004, 1.5, 0.006}};
  for (int b = 0; b < 2; ++b) {
    for (const Mode& mode : every_mode()) {
      const double dt = 1.0 / 60.0;
      const int steps = b == 0 ? 600 : 300;
      const Eigen::Vector3d ours = model_omega(bodies[b], mode, spins[b], dt, steps);
      const Eigen::Vector3d theirs =
          direct(mode, bodies[b].cage.mass, bodies[b].moments, spins[b], dt, steps);
      EXPECT_LE((ours - theirs).norm(), 1e-12 * theirs.norm())
          << name(mode) << " body " << b << ": " << ours.transpose() << " vs "
          << theirs.transpose();
    }
  }
}

// Bullet's two implicit gyroscopic flags take the same one Newton step of implicit Euler on
// Euler's equations, one in the world frame and one in the body frame (docs/engines.md), so
// their runs part only by round-off, which the tolerance above hides. Each of bookspin's
// Bullet modes is held here to Bullet called directly with that mode's own flag, named from
// Bullet's header, bit for bit (the same arithmetic on the same numbers); and the flags are
// shown to part in those bits over the same steps, so a mode stepped with the other
// implicit flag fails. The ω0 handed to Bullet is the model's own after reset (I⁻¹(I ω0)
// rounds), read back through an identity basis, so both start from the same bits.
TEST(EngineModels, BulletModesAreBulletWithTheirOwnGyroscopicFlagBitForBit) {
  const physics::Body book = physics::book_body(physics::Book{});
  const double dt = 1.0 / 60.0;
  const int steps = 120;
  const struct {
    Integrator integrator;
    int flags;
  } modes[] = {{Integrator::implicit_body, BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY},
               {Integrator::implicit_world, BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_WORLD},
               {Integrator::explicit_gyro, BT_ENABLE_GYROSCOPIC_FORCE_EXPLICIT},
               {Integrator::none, 0}};
  auto sim = make_model(book, {ModelKind::bullet, Integrator::none});
  physics::InitialState initial;
  initial.omega0_body = Eigen::Vector3d(0.114819, 0.02, 0.03);
  sim->reset(initial);
  const Eigen::Vector3d omega0 = sim->diagnostics().omega_body;
  for (const auto& mode : modes) {
    const Mode m{ModelKind::bullet, mode.integrator};
    const Eigen::Vector3d ours = model_omega(book, m, initial.omega0_body, dt, steps);
    const Eigen::Vector3d theirs =
        bullet_direct(book.cage.mass, book.moments, omega0, mode.flags, dt, steps);
    for (int i = 0; i < 3; ++i) EXPECT_EQ(ours[i], theirs[i]) << name(m) << " component " << i;
  }
  const Eigen::Vector3d world = bullet_direct(book.cage.mass, book.moments, omega0,
                                              BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_WORLD, dt, steps);
  const Eigen::Vector3d body = bullet_direct(book.cage.mass, book.moments, omega0,
                                             BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY, dt, steps);
  EXPECT_NE(world, body) << "the implicit flags agree to the bit: the test above has no teeth";
  std::printf("Bullet implicit world vs body after %d steps: |Δω| = %.3g of |ω| = %.3g\n", steps,
              (world - body).norm(), world.norm());
}

// The comparison has teeth: the engine handed the book's axes permuted (x ↔ y, the smallest
// and intermediate moments) ends far from the right ω. Not the "none" modes: without the
// gyroscopic term their ω does not depend on the moments at all (the test below).
TEST(EngineModels, PermutedPrincipalAxesAreFarFromTheModel) {
  const physics::Body book = physics::book_body(physics::Book{});
  const Eigen::Vector3d permuted(book.moments.y(), book.moments.x(), book.moments.z());
  const Eigen::Vector3d spin(0.114819, 0.002, 0.003);
  for (const Mode& mode : every_mode()) {
    if (mode.integrator == Integrator::none) continue;
    const Eigen::Vector3d ours = model_omega(book, mode, spin, 1.0 / 60.0, 600);
    const Eigen::Vector3d wrong = direct(mode, book.cage.mass, permuted, spin, 1.0 / 60.0, 600);
    EXPECT_GT((ours - wrong).norm(), 1e-2 * ours.norm()) << name(mode);
  }
}

// Independent numbers: the exact ω(t) (Jacobi elliptic functions, docs/physics.md §8) of the
// book about its intermediate axis, through the first flip. At dt = 1/1000 the engines'
// first-order modes are within a few per cent of the spin; MuJoCo's RK4 within 1e-6.
TEST(EngineModels, SmallStepsFollowTheExactMotionThroughAFlip) {
  const physics::Body book = physics::book_body(physics::Book{});
  const Eigen::Vector3d spin(0.114819, 0.001, 0.001);
  const physics::ExactRotation exact(book.moments, spin);
  const double dt = 1e-3;
  const int steps = static_cast<int>(std::lround(0.5 * exact.flip_period() / dt));
  const Eigen::Vector3d reference = exact.omega_body(steps * dt);
  ASSERT_LT(reference.x(), -0.5 * spin.x());  // the spin about x has turned over by then
  for (const Mode& mode : every_mode()) {
    if (mode.integrator == Integrator::none) continue;  // no gyroscopic term: no flip at all
    const double tolerance = mode.integrator == Integrator::rk4 ? 1e-6 : 0.05;
    const Eigen::Vector3d ours = model_omega(book, mode, spin, dt, steps);
    EXPECT_LE((ours - reference).norm(), tolerance * spin.norm())
        << name(mode) << ": " << ours.transpose() << " vs exact " << reference.transpose();
  }
}

// Without the gyroscopic term the engines add no torque and ω stays what it was in the world
// frame: the body turns about a fixed axis, L = R I Rᵀ ω turns with it, and it never flips.
TEST(EngineModels, WithoutTheGyroscopicTermOmegaStaysPut) {
  const physics::Body book = physics::book_body(physics::Book{});
  const Eigen::Vector3d spin(0.114819, 0.001, 0.001);
  for (const Mode& mode :
       {Mode{ModelKind::bullet, Integrator::none}, Mode{ModelKind::ode, Integrator::none}}) {
    auto sim = make_model(book, {mode.kind, mode.integrator});
    physics::InitialState initial;
    initial.omega0_body = spin;
    sim->reset(initial);
    for (int i = 0; i < 1200; ++i) sim->step(1.0 / 60.0);
    const Eigen::Vector3d omega_world = sim->orientation() * sim->diagnostics().omega_body;
    EXPECT_LE((omega_world - spin).norm(), 1e-12) << name(mode) << ": " << omega_world.transpose();
  }
}

// A spin about the largest axis (the book's z) with a little of the others stays about it in
// every mode: the cosine of the largest principal axis with L stays near 1 for 400 time units
// (about two flip periods of a spin that near the intermediate axis).
TEST(EngineModels, SpinAboutTheLargestAxisStaysPut) {
  const physics::Body book = physics::book_body(physics::Book{});
  physics::InitialState initial;
  initial.omega0_body = Eigen::Vector3d(0.002, 0.003, 0.114819);
  for (const Mode& mode : every_mode()) {
    auto sim = make_model(book, {mode.kind, mode.integrator});
    sim->reset(initial);
    double worst = 1.0;
    for (int i = 0; i < 24000; ++i) {
      sim->step(1.0 / 60.0);
      worst = std::min(worst, std::abs(sim->diagnostics().cos_principal_L[2]));
    }
    EXPECT_GT(worst, 0.99) << name(mode);
  }
}

// The accuracy rows are the engines' rows of the one table of modes (physics::model_modes(),
// whose rows tests/physics/model_modes_test.cpp holds against the docs), in its order, each
// engine's default first.
TEST(EngineModes, TheAccuracyRowsAreTheTablesEngineRows) {
  std::vector<std::string> rows;
  for (const Mode& m : engine_modes()) rows.push_back(name(m));
  std::vector<std::string> table;
  for (const physics::ModelMode& m : physics::model_modes())
    if (physics::is_engine(m.kind)) table.push_back(name(m));
  EXPECT_EQ(rows, table);
  for (const Mode& m : engine_modes())
    EXPECT_EQ(name({m.kind, physics::default_integrator(m.kind)}), name(rows_of(m.kind).front()));
}

// Every engine kind's modes, as the table says, make a model that steps; every other
// integrator is refused; a kind that is no model's is an internal error, never built as
// another engine.
TEST(EngineModes, EveryModeOfTheTableMakesAModelAndNoOther) {
  const physics::Body book = physics::book_body(physics::Book{});
  int made = 0;
  for (ModelKind kind : physics::model_kinds()) {
    if (!physics::is_engine(kind)) continue;
    for (Integrator integrator : physics::integrators()) {
      const Mode mode{kind, integrator};
      if (!physics::supports(kind, integrator)) {
        EXPECT_THROW(make_model(book, {kind, integrator}), std::invalid_argument) << name(mode);
        continue;
      }
      std::unique_ptr<physics::Simulator> sim;
      ASSERT_NO_THROW(sim = make_model(book, {kind, integrator})) << name(mode);
      physics::InitialState initial;
      initial.omega0_body = Eigen::Vector3d(0.114819, 0.002, 0.003);
      sim->reset(initial);
      for (int i = 0; i < 10; ++i) sim->step(1.0 / 60.0);
      EXPECT_TRUE(sim->finite()) << name(mode);
      EXPECT_NEAR(sim->diagnostics().t, 10.0 / 60.0, 1e-12) << name(mode);
      ++made;
    }
  }
  EXPECT_EQ(made, static_cast<int>(engine_modes().size()));
  EXPECT_GT(made, 0);
  const auto unknown = static_cast<ModelKind>(99);
  EXPECT_FALSE(physics::is_engine(unknown));
  EXPECT_THROW(make_model(book, {unknown, Integrator::step}), InternalError);
  EXPECT_THROW(make_model(book, {unknown, Integrator::euler}), InternalError);
}

}  // namespace
}  // namespace bookspin::engines

namespace bookspin::engines {
namespace {

// A body MuJoCo's compiler refuses is bad input (InputError: exit 2, one line naming MuJoCo's
// limit and the body's numbers), never an internal error: the scene reader's check covers the
// known limits, this covers whatever else MuJoCo refuses. Each moment 1e-20 (a 1e-12 mass of
// 1e-4-unit book), below mjMINVAL = 1e-15 (mjmodel.h).
TEST(EngineModels, ABodyMujocoRefusesIsBadInputNamingItsLimit) {
  physics::Book tiny;
  tiny.size = Eigen::Vector3d(1e-4, 2e-4, 3e-4);
  tiny.mass = 1e-12;
  const physics::Body body = physics::book_body(tiny);
  ASSERT_LT(body.moments.maxCoeff(), 1e-15);
  try {
    make_model(body, {ModelKind::mujoco, Integrator::euler});
    FAIL() << "MuJoCo took a body below its mjMINVAL";
  } catch (const InputError& e) {
    const std::string line = e.what();
    EXPECT_NE(line.find("MuJoCo rejected the body's model"), std::string::npos) << line;
    EXPECT_NE(line.find("mjMINVAL, 1e-15"), std::string::npos) << line;
    EXPECT_NE(line.find("mass 1e-12"), std::string::npos) << line;
    EXPECT_EQ(line.find('\n'), std::string::npos) << line;
  }
}

// Sweeps and accuracy runs step one model per thread. ODE's worlds share one global
// self-threaded stepping implementation unless each is given its own, and that one is not safe
// from two threads at once (ode/objects.h, dWorldSetStepThreadingImplementation): stepped in
// parallel they corrupt its job list and abort ("stepperArena != NULL"). Four ODE models,
// each in its own thread, step at once and each ends exactly where the same model stepped alone
// ends.
TEST(EngineModels, OdeModelsStepInParallelThreadsAsEachAlone) {
  const physics::Body book = physics::book_body(physics::Book{});
  physics::InitialState initial;
  initial.omega0_body = Eigen::Vector3d(0.1, 3.0, 0.1);
  constexpr int kThreads = 4;
  constexpr int kSteps = 20000;
  const auto run = [&](Integrator integrator) {
    auto sim = make_model(book, {ModelKind::ode, integrator});
    sim->reset(initial);
    for (int i = 0; i < kSteps; ++i) sim->step(1e-3);
    return Eigen::Vector3d(sim->diagnostics().omega_body);
  };
  const Integrator modes[kThreads] = {Integrator::step, Integrator::quickstep, Integrator::step,
                                      Integrator::quickstep};
  Eigen::Vector3d alone[kThreads];
  for (int j = 0; j < kThreads; ++j) alone[j] = run(modes[j]);
  Eigen::Vector3d together[kThreads];
  std::vector<std::thread> threads;
  for (int j = 0; j < kThreads; ++j) threads.emplace_back([&, j] { together[j] = run(modes[j]); });
  for (std::thread& t : threads) t.join();
  for (int j = 0; j < kThreads; ++j)
    EXPECT_EQ(together[j], alone[j]) << "thread " << j << ": " << together[j].transpose()
                                     << " vs alone " << alone[j].transpose();
}

}  // namespace
}  // namespace bookspin::engines
