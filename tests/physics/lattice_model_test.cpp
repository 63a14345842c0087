// The lattice particle model (docs/physics.md §13): the one-cell book is the paper's
// particle model; the T-handle's lattice conserves what it must and flips with the exact
// motion.
#include "physics/lattice_model.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "lattice_shapes.hpp"
#include "model_helpers.hpp"
#include "physics/exact_solution.hpp"
#include "physics/particle_model.hpp"
#include "support/flip_timer.hpp"

namespace bookspin::physics {
namespace {

using testing::box_surface;
using testing::principal;
using testing::Surface;
using testing::t_surface;

LatticeModel book_lattice_model(const Book& book, const ModelConfig& config) {
  const Surface s = box_surface(-0.5 * book.size, 0.5 * book.size);
  return LatticeModel(build_lattice(s.vertices, s.triangles, book.mass, 1),
                      book.principal_moments(), book.body_corners(), config);
}

// The one-cell lattice of the book against ParticleModel, 1000 steps of 1/60 with a
// jiggle, every integrator with and without damping and normalization.
TEST(LatticeModel, OneCellBookIsTheParticleModel) {
  const Book book = testing::original_book();
  for (Integrator integrator :
       {Integrator::euler, Integrator::symplectic_euler, Integrator::velocity_verlet})
    for (bool damping : {true, false})
      for (bool normalize : {false, true}) {
        ModelConfig config = testing::config(ModelKind::particle, normalize, damping);
        config.integrator = integrator;
        ParticleModel reference(book, config);
        LatticeModel lattice = book_lattice_model(book, config);
        const InitialState initial{testing::original_omega0(0), 1e-3, 7};
        reference.reset(initial);
        lattice.reset(initial);
        const double L0 = reference.diagnostics().L.norm();
        const double E0 = reference.diagnostics().energy_total;
        EXPECT_EQ(lattice.diagnostics().L, reference.diagnostics().L);
        double worst = 0.0;
        for (int step = 0; step < 1000; ++step) {
          reference.step(1.0 / 60.0);
          lattice.step(1.0 / 60.0);
          const Corners a = reference.corners(), b = lattice.corners();
          worst = std::max(worst, (a - b).cwiseAbs().maxCoeff() / a.cwiseAbs().maxCoeff());
        }
        std::printf("%-16s damping %d normalize %d: largest relative corner difference %.2e\n",
                    std::string(to_string(integrator)).c_str(), damping, normalize, worst);
        EXPECT_LE(worst, 1e-12) << to_string(integrator) << " " << damping << normalize;
        // Without normalization the arithmetic is the same, operation by operation.
        if (!normalize) {
          EXPECT_EQ(worst, 0.0);
        }
        const Diagnostics d = reference.diagnostics(), e = lattice.diagnostics();
        EXPECT_NEAR((d.L - e.L).norm(), 0.0, 1e-12 * L0);
        EXPECT_NEAR(d.energy_total, e.energy_total, 1e-12 * std::max(E0, d.energy_total));
        EXPECT_NEAR(d.strain_max, e.strain_max, 1e-12);
        if (d.L.norm() > 0.1 * L0) {  // cos(axis, L) is ill-conditioned where L has gone
          EXPECT_NEAR((d.cos_axis_L - e.cos_axis_L).norm(), 0.0, 1e-10);
        }
      }
}

/// The T in its principal frame, mass 1, and its mesh's mass properties.
struct TBody {
  Surface surface;
  MassProperties props;
};

TBody t_body() {
  TBody t;
  t.surface = principal(t_surface(), 1.0, t.props);
  return t;
}

/// The box around the surface (3×8), the cage corners() reports.
Corners bounding_cage(const Surface& s) {
  const Eigen::Vector3d lo = s.vertices.rowwise().minCoeff(), hi = s.vertices.rowwise().maxCoeff();
  return box_surface(lo, hi).vertices;
}

/// A step with ω_max·dt ≤ 1 for the lattice at spring constant k.
double stable_step(const Lattice& lat, double k) { return 1.0 / max_angular_frequency(lat, k); }

/// The particle model on the T's lattice of `cells` cells along its longest side (mass 1,
/// docs/physics.md §13): unnormalized, damped or not, spring constant `k`, `integrator`.
LatticeModel t_lattice_model(const TBody& t, int cells, bool damping, double k,
                             Integrator integrator) {
  ModelConfig config = testing::config(ModelKind::particle, false, damping, k);
  config.integrator = integrator;
  return LatticeModel(build_lattice(t.surface.vertices, t.surface.triangles, 1.0, cells),
                      t.props.principal_moments, bounding_cage(t.surface), config);
}

// Undamped, unnormalized: symplectic Euler and velocity Verlet conserve the momentum and
// the angular momentum (central pair forces) to round-off and keep the energy within a
// small bounded error (docs/physics.md §10, §13).
TEST(LatticeModel, UndampedTConservesMomentumAndEnergy) {
  const TBody t = t_body();
  const double k = 2000.0;
  for (Integrator integrator : {Integrator::symplectic_euler, Integrator::velocity_verlet}) {
    LatticeModel model = t_lattice_model(t, 8, false, k, integrator);
    const Lattice& lat = model.lattice();
    model.reset({Eigen::Vector3d(0.05, 1.0, 0.05), 0.0, 1});
    const Diagnostics d0 = model.diagnostics();
    const double dt = 0.5 * stable_step(lat, k);
    double worst_energy = 0.0;
    for (int step = 1; step <= 4000; ++step) {
      model.step(dt);
      if (step % 100 == 0) {
        const Diagnostics d = model.diagnostics();
        worst_energy = std::max(worst_energy, std::abs(d.energy_total / d0.energy_total - 1.0));
        EXPECT_LE((d.L - d0.L).norm(), 1e-12 * d0.L.norm()) << step;
      }
    }
    const Eigen::Vector3d momentum = model.velocities() * lat.mass;
    std::printf("%s: dt %.2e, momentum %.1e, worst relative energy error %.2e\n",
                std::string(to_string(integrator)).c_str(), dt, momentum.norm(), worst_energy);
    EXPECT_LE(momentum.norm(), 1e-13);
    EXPECT_LE(worst_energy, 1e-3);
    EXPECT_TRUE(model.finite());
  }
}

// Damping forces act along the springs too: with damping the spin's angular momentum stays
// to round-off while the springs' vibration dies out (docs/physics.md §2, §13).
TEST(LatticeModel, DampedTKeepsItsAngularMomentum) {
  const double k = 2000.0;
  LatticeModel model = t_lattice_model(t_body(), 12, true, k, Integrator::symplectic_euler);
  const Lattice& lat = model.lattice();
  model.reset({Eigen::Vector3d(0.05, 1.0, 0.05), 1e-3, 3});
  const Diagnostics d0 = model.diagnostics();
  // Damping bounds the step more than the springs do: γ_max·dt = 1.
  const double gamma = max_damping_rate(lat, k);
  EXPECT_GT(gamma, 5.0 * max_angular_frequency(lat, k));
  const double dt = 1.0 / gamma;
  for (int step = 1; step <= 20000; ++step) {
    model.step(dt);
    if (step % 100 != 0) continue;
    const Diagnostics d = model.diagnostics();
    ASSERT_LE((d.L - d0.L).norm(), 1e-12 * d0.L.norm()) << step;
  }
  // The springs stretched under the spin and the damping took the vibration's energy.
  EXPECT_LT(model.diagnostics().energy_total, d0.energy_total * (1.0 - 1e-5));
  EXPECT_TRUE(model.finite());
}

// The rigid cage and the deformed surface follow a spin: after a quarter turn about z at
// rest shape, corners and surface are the rest ones turned by 90° about the centre of mass.
TEST(LatticeModel, CageAndSurfaceFollowTheLattice) {
  const TBody t = t_body();
  const double k = 1e5;
  LatticeModel model = t_lattice_model(t, 8, false, k, Integrator::velocity_verlet);
  const Lattice& lat = model.lattice();
  const double omega = 0.2;
  // Spin about the largest axis (z), stable.
  model.reset({Eigen::Vector3d(0.0, 0.0, omega), 0.0, 1});
  const double dt = 0.5 * stable_step(lat, k);
  const int steps = static_cast<int>(std::lround(0.5 * M_PI / omega / dt));
  for (int s = 0; s < steps; ++s) model.step(dt);
  const double angle = omega * steps * dt;
  const Eigen::Matrix3d R = Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::Vector3d c0 = lat.center_of_mass;
  const Corners expected = (R * (bounding_cage(t.surface).colwise() - c0)).colwise() + c0;
  EXPECT_LE((model.corners() - expected).cwiseAbs().maxCoeff(), 2e-3);
  const Eigen::Matrix3Xd surface = (R * (t.surface.vertices.colwise() - c0)).colwise() + c0;
  EXPECT_LE((model.deformed_surface() - surface).cwiseAbs().maxCoeff(), 2e-3);
  const Eigen::Vector3d cos = model.cos_principal_L();
  EXPECT_NEAR(cos[2], 1.0, 1e-6);  // largest axis along L
  // ω_body = I_lattice⁻¹ Rᵀ L: the spin itself, not the mesh's I⁻¹ L.
  EXPECT_NEAR(model.diagnostics().omega_body.z() / omega, 1.0, 1e-3);
}

/// First time the sign of cos(intermediate axis, L) differs from its sign at t = 0.
double first_flip_exact(const Eigen::Vector3d& moments, const Eigen::Vector3d& omega0, double dt,
                        double t_end) {
  const ExactRotation exact(moments, omega0);
  const Eigen::Vector3d L = exact.angular_momentum_world();
  test::FlipTimer timer;
  for (double t = 0.0; t < t_end && timer.count() == 0; t += dt)
    timer.sample(t, exact.orientation(t).col(1).dot(L));
  return timer.first();
}

// The paper's claim (docs/physics.md §13): a stiff lattice that knows nothing of the
// inertia tensor flips with the exact motion of the mesh's inertia. Spin about the
// intermediate axis (y) with a small tilt: the first flip time of the lattice against the
// exact one, for n = 8, 12, 16, 24; within 2.7% at 24 (1.35% measured).
TEST(LatticeModel, TFlipsWithTheExactModel) {
  const TBody t = t_body();
  const Eigen::Vector3d omega0(0.02, 1.0, 0.02);
  const double k = 3000.0;
  const double exact = first_flip_exact(t.props.principal_moments, omega0, 1e-3, 100.0);
  ASSERT_GT(exact, 0.0);
  std::printf("T moments %.5f %.5f %.5f, exact first flip at t = %.4f\n",
              t.props.principal_moments[0], t.props.principal_moments[1],
              t.props.principal_moments[2], exact);
  double error24 = 1.0;
  for (int n : {8, 12, 16, 24}) {
    LatticeModel model = t_lattice_model(t, n, false, k, Integrator::velocity_verlet);
    const Lattice& lat = model.lattice();
    model.reset({omega0, 0.0, 1});
    const double dt = 0.5 * stable_step(lat, k);
    const auto start = std::chrono::steady_clock::now();
    test::FlipTimer timer;
    timer.sample(0.0, model.diagnostics().cos_axis_L[1]);
    double strain = 0.0;
    long steps = 0;
    for (double time = dt; time < 2.0 * exact && timer.count() == 0; time += dt, ++steps) {
      model.step(dt);
      if (steps % 20 != 0) continue;
      const Diagnostics d = model.diagnostics();
      strain = std::max(strain, d.strain_max);
      timer.sample(d.t, d.cos_axis_L[1]);
    }
    const double flip = timer.first();
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double error = flip / exact - 1.0;
    std::printf(
        "  n=%2d particles %5d springs %6d dt %.2e steps %6ld (%.2f us/step): first flip "
        "%.4f, exact %.4f, rel %+.4f, lattice moments err %+.4f %+.4f %+.4f, strain %.1e\n",
        n, lat.particles(), lat.spring_count(), dt, steps, 1e6 * seconds / steps, flip, exact,
        error, lat.principal_moments[0] / t.props.principal_moments[0] - 1.0,
        lat.principal_moments[1] / t.props.principal_moments[1] - 1.0,
        lat.principal_moments[2] / t.props.principal_moments[2] - 1.0, strain);
    EXPECT_GT(flip, 0.0) << "n = " << n;
    if (n == 24) error24 = std::abs(error);
  }
  EXPECT_LE(error24, 0.027);  // 1.35% here: about twice that
}

// The body-frame ω of the diagnostics is I_lattice⁻¹ Rᵀ L (docs/physics.md §13): for a
// spin about no principal axis, far from the start, it follows the exact motion of the
// lattice's own (diagonal) inertia. The one-cell book: its 8 corner masses.
TEST(LatticeModel, BodyFrameOmegaFollowsTheExactMotionOfAGeneralSpin) {
  const Book book = testing::original_book();
  ModelConfig config = testing::config(ModelKind::particle, false, false, 1e5);
  config.integrator = Integrator::velocity_verlet;
  LatticeModel model = book_lattice_model(book, config);
  const Eigen::Matrix3d inertia = model.lattice().inertia;
  ASSERT_LE((inertia - Eigen::Matrix3d(inertia.diagonal().asDiagonal())).norm(),
            1e-12 * inertia.norm());
  const Eigen::Vector3d omega0(0.3, -0.5, 0.4);
  model.reset({omega0, 0.0, 1});
  const ExactRotation exact(inertia.diagonal(), omega0);
  const double dt = 0.5 * stable_step(model.lattice(), config.spring_constant);
  const long steps = std::lround(8.0 / dt), every = steps / 8;
  double worst = 0.0, turned = 0.0;
  for (long step = 1; step <= steps; ++step) {
    model.step(dt);
    if (step % every != 0) continue;
    const double t = static_cast<double>(step) * dt;
    const Diagnostics d = model.diagnostics();
    const double error = (d.omega_body - exact.omega_body(t)).norm() / omega0.norm();
    ASSERT_TRUE(std::isfinite(error))
        << d.omega_body.transpose() << " / " << exact.omega_body(t).transpose();
    worst = std::max(worst, error);
    turned = std::max(turned, Eigen::AngleAxisd(exact.orientation(t)).angle());
  }
  std::printf("largest |omega_body - exact| / |omega0|: %.2e (turned up to %.2f rad)\n", worst,
              turned);
  EXPECT_GT(turned, 2.0);    // far from the start: R is far from I and from a z rotation
  EXPECT_LE(worst, 1.2e-5);  // 6.1e-6 here
}

// Critical damping per spring uses twice the pair's reduced mass, m_s = 2 m_i m_j/(m_i + m_j)
// (docs/physics.md §13). Two particles of masses 1 and 3, one spring of k = 1 started 0.1
// longer than its rest length, at rest: the stretch u obeys μ ü = −k u − b u̇ with
// μ = 3/4 and b = 2√(k m_s) = 2√1.5, a damping ratio ζ = √(m_s/μ) = √2, so
// u(t) = u0 (r2 e^{r1 t} − r1 e^{r2 t})/(r2 − r1), r1,2 = −ω0 (ζ ∓ √(ζ² − 1)), ω0 = √(k/μ).
TEST(LatticeModel, SpringDampingUsesThePairsMass) {
  Lattice lat;
  lat.rest.resize(3, 2);
  lat.rest.col(0) = Eigen::Vector3d(-0.75, 0.0, 0.0);
  lat.rest.col(1) = Eigen::Vector3d(0.25, 0.0, 0.0);
  lat.mass = Eigen::Vector2d(1.0, 3.0);
  lat.springs.resize(2, 1);
  lat.springs << 0, 1;
  lat.rest_length = Eigen::VectorXd::Constant(1, 0.9);
  lat.stiffness = Eigen::VectorXd::Constant(1, 1.0);
  lat.vertex_cell.resize(8, 0);
  lat.vertex_coords.resize(3, 0);
  lat.total_mass = 4.0;
  lat.center_of_mass = Eigen::Vector3d::Zero();
  lat.inertia = Eigen::Vector3d(1e-3, 0.75, 0.75).asDiagonal();  // unused by the motion
  ModelConfig config = testing::config(ModelKind::particle, false, true, 1.0);
  config.integrator = Integrator::velocity_verlet;
  const Surface box = box_surface(Eigen::Vector3d::Constant(-1), Eigen::Vector3d::Constant(1));
  LatticeModel model(lat, Eigen::Vector3d(1, 1, 1), box.vertices, config);
  model.reset({Eigen::Vector3d::Zero(), 0.0, 1});
  const double mu = 0.75, zeta = std::sqrt(2.0), w0 = std::sqrt(1.0 / mu), u0 = 0.1;
  const double r1 = -w0 * (zeta - std::sqrt(zeta * zeta - 1.0));
  const double r2 = -w0 * (zeta + std::sqrt(zeta * zeta - 1.0));
  const double dt = 1e-4;
  double worst = 0.0;
  for (int step = 1; step <= 60000; ++step) {
    model.step(dt);
    if (step % 5000 != 0) continue;
    const double t = step * dt;
    const Eigen::Matrix3Xd x = model.positions();
    const double u = (x.col(1) - x.col(0)).norm() - 0.9;
    const double expected = u0 * (r2 * std::exp(r1 * t) - r1 * std::exp(r2 * t)) / (r2 - r1);
    worst = std::max(worst, std::abs(u - expected) / u0);
  }
  std::printf("largest |u - closed form| / u0: %.2e\n", worst);
  EXPECT_LE(worst, 1.5e-5);  // 6.6e-6 here (velocity Verlet with a velocity-dependent force)
}

// cos_principal_L() sorts the axes by moment: the book's smallest moment is about y, its
// intermediate about x (docs/physics.md §1).
TEST(LatticeModel, PrincipalCosinesAreSortedByMoment) {
  const Book book = testing::original_book();
  ModelConfig config = testing::config(ModelKind::particle, false, true);
  LatticeModel model = book_lattice_model(book, config);
  model.reset({Eigen::Vector3d(0.3, 0.1, 0.2), 0.0, 1});
  for (int s = 0; s < 200; ++s) model.step(1.0 / 60.0);
  const Eigen::Vector3d cos = model.cos_principal_L(), axis = model.diagnostics().cos_axis_L;
  EXPECT_NEAR(cos[0], axis[1], 1e-15);
  EXPECT_NEAR(cos[1], axis[0], 1e-15);
  EXPECT_NEAR(cos[2], axis[2], 1e-15);
  EXPECT_GT(std::abs(cos[0] - cos[1]), 1e-3);  // the order matters here
}

TEST(LatticeModel, RejectsWhatItCannotRun) {
  const Book book;
  const Surface s = box_surface(-0.5 * book.size, 0.5 * book.size);
  const Lattice lat = build_lattice(s.vertices, s.triangles, book.mass, 1);
  ModelConfig config;
  config.integrator = Integrator::rk4;
  EXPECT_THROW(LatticeModel(lat, book.principal_moments(), book.body_corners(), config),
               std::invalid_argument);
  EXPECT_THROW(LatticeModel(lat, Eigen::Vector3d(1, 0, 1), book.body_corners(), ModelConfig{}),
               std::invalid_argument);
}

}  // namespace
}  // namespace bookspin::physics
