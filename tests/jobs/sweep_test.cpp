// Sweeps (docs/physics.md §14): the measures a sweep takes of each run against closed forms of
// the exact motion (docs/physics.md §8), and a whole run over a grid. The grid is tested in
// sweep_grid_test.cpp, the table's CSV in sweep_csv_test.cpp, the shards in
// sweep_shard_test.cpp.
#include "jobs/sweep.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>

#include "analysis/motion.hpp"
#include "common/errors.hpp"
#include "engines/models.hpp"
#include "jobs/csv_text.hpp"
#include "physics/exact_model.hpp"
#include "support/closed_form_flips.hpp"

namespace bookspin::jobs {
namespace {

using test::closed_form_flips;
using test::ClosedFormFlips;

std::string scene_file(const std::string& name) {
  return std::string(BOOKSPIN_SOURCE_DIR) + "/scenes/" + name + ".toml";
}

/// exact-unstable-x without jiggle, spin 0.114819 about x (intermediate) plus ε about y.
scene::Scene near_intermediate(double epsilon, const std::string& kind,
                               const std::string& integrator, double dt, int frames) {
  return scene::parse_scene(
      scene_file("exact-unstable-x"),
      {"initial.jiggle=0", "initial.angular_velocity=[0.114819," + full_precision(epsilon) + ",0]",
       "model.kind=\"" + kind + "\"", "model.integrator=\"" + integrator + "\"",
       "time.dt=" + full_precision(dt), "time.steps_per_frame=1",
       "time.frames=" + std::to_string(frames)});
}

/// max over every step of |E/E0 − 1|, and the time of the first step whose state is not
/// finite, recomputed here from the simulator's own states (the definitions of
/// docs/physics.md §14), stepping as the sweep does: (frames − 1)·steps_per_frame steps.
struct Recomputed {
  double energy_drift = 0.0;
  std::optional<double> diverged_at;
};
Recomputed recompute(const scene::Scene& s) {
  auto sim = engines::make_model(s.body, s.model);
  sim->reset(s.initial);
  const double e0 = sim->diagnostics().energy_total;
  Recomputed r;
  const long long steps = static_cast<long long>(s.frames - 1) * s.steps_per_frame;
  for (long long n = 1; n <= steps; ++n) {
    sim->step(s.dt);
    if (!sim->finite()) {
      r.diverged_at = static_cast<double>(n) * s.dt;
      break;
    }
    r.energy_drift = std::max(r.energy_drift, std::abs(sim->diagnostics().energy_total / e0 - 1.0));
  }
  return r;
}

TEST(SweepMeasures, CosIntermediateUsesTheMiddleMoment) {
  physics::Diagnostics d;
  d.cos_axis_L = Eigen::Vector3d(0.1, 0.2, 0.3);
  EXPECT_EQ(analysis::flip_signal(d, Eigen::Vector3d(2, 1, 3)), 0.1);  // the book: x
  EXPECT_EQ(analysis::flip_signal(d, Eigen::Vector3d(1, 2, 3)), 0.2);
  EXPECT_EQ(analysis::flip_signal(d, Eigen::Vector3d(3, 1, 2)), 0.3);
  const physics::Book book;
  EXPECT_EQ(analysis::flip_signal(d, book.principal_moments()), 0.1);
}

TEST(SweepMeasures, RigidRk4FlipPeriodIsTheClosedForm) {
  // T/2 = 2K(k)/λ (docs/physics.md §8), within 1e-6 relative, from sign changes found at
  // every step with linear interpolation.
  for (const char* kind : {"rigid-quaternion", "rigid-matrix"}) {
    const scene::Scene s = near_intermediate(1e-3, kind, "rk4", 1.0 / 120, 120 * 700);
    const analysis::RunMeasures m = analysis::measure_run(s);
    ASSERT_TRUE(m.flip_period && m.flip_period_exact) << kind;
    EXPECT_NEAR(*m.flip_period / *m.flip_period_exact, 1.0, 1e-6) << kind;
    // The exact column against 2K(k)/λ from the invariants (no jiggle here, so ω(0) is ω0).
    EXPECT_NEAR(
        *m.flip_period_exact / closed_form_flips(s.body.moments, s.initial.omega0_body).half_period,
        1.0, 1e-9)
        << kind;
    EXPECT_NEAR(*m.first_flip, *m.first_flip_exact, 1e-6 * *m.first_flip_exact) << kind;
    // The drift is the largest over the run, not the last step's (which is smaller here).
    EXPECT_EQ(*m.energy_drift, recompute(s).energy_drift) << kind;
    EXPECT_LT(*m.energy_drift, 1e-10) << kind;
    EXPECT_LT(*m.orientation_error, 1e-6) << kind;
    EXPECT_FALSE(m.diverged_at);
  }
}

TEST(SweepMeasures, FirstFlipGrowsLikeTheLogOfOneOverEpsilon) {
  // Near the intermediate axis a perturbation grows like exp(σt) with
  // σ = ω0·√((I_x − I_y)(I_z − I_x)/(I_y I_z)) (docs/physics.md §14), so the first flip
  // comes at t ≈ ln(C/ε)/σ: each factor 10 in ε adds ln(10)/σ.
  const physics::Book book;
  const Eigen::Vector3d I = book.principal_moments();
  const double sigma = 0.114819 * std::sqrt((I.x() - I.y()) * (I.z() - I.x()) / (I.y() * I.z()));
  std::vector<double> first;
  for (double eps : {1e-4, 1e-5, 1e-6, 1e-7}) {
    const analysis::RunMeasures m =
        analysis::measure_run(near_intermediate(eps, "exact", "euler", 1.0 / 60, 60 * 300));
    ASSERT_TRUE(m.first_flip) << eps;
    EXPECT_NEAR(*m.first_flip, *m.first_flip_exact, 1e-6) << eps;
    first.push_back(*m.first_flip);
  }
  for (std::size_t i = 1; i < first.size(); ++i)
    EXPECT_NEAR((first[i] - first[i - 1]) * sigma / std::log(10.0), 1.0, 1e-3) << i;
}

TEST(SweepMeasures, TheTHandleSweepSceneFollowsTheSameLogLaw) {
  // sweeps/t-handle-flip-time-vs-perturbation.toml: spin Ω = 2 about y (intermediate), ε
  // about x (smallest), quaternion RK4 at dt = 0.001. Same law as the book's, with
  // σ = Ω·√((I_y − I_x)(I_z − I_y)/(I_x I_z)) from the T-handle's own moments (§12, §14).
  const std::string path =
      std::string(BOOKSPIN_SOURCE_DIR) + "/sweeps/t-handle-flip-time-vs-perturbation.toml";
  std::vector<double> first;
  double sigma = 0.0;
  for (double eps : {1e-3, 1e-4, 1e-5}) {
    const scene::Scene s = scene::parse_scene(
        path, {"initial.angular_velocity=[" + full_precision(eps) + ",2,0]", "time.frames=161"});
    const Eigen::Vector3d I = s.body.moments;
    sigma = 2.0 * std::sqrt((I.y() - I.x()) * (I.z() - I.y()) / (I.x() * I.z()));
    const analysis::RunMeasures m = analysis::measure_run(s);
    ASSERT_TRUE(m.first_flip && m.flip_period) << eps;
    EXPECT_NEAR(*m.first_flip / *m.first_flip_exact, 1.0, 1e-8) << eps;
    EXPECT_NEAR(*m.flip_period / *m.flip_period_exact, 1.0, 1e-5) << eps;
    EXPECT_EQ(*m.energy_drift, recompute(s).energy_drift) << eps;
    EXPECT_LT(*m.energy_drift, 1e-12) << eps;
    first.push_back(*m.first_flip);
  }
  for (std::size_t i = 1; i < first.size(); ++i)
    EXPECT_NEAR((first[i] - first[i - 1]) * sigma / std::log(10.0), 1.0, 1e-3) << i;
}

TEST(SweepMeasures, ExactModelHasNoErrorAndParticleModelIsMeasuredFromItsCorners) {
  const analysis::RunMeasures exact =
      analysis::measure_run(near_intermediate(1e-3, "exact", "euler", 1.0 / 60, 3000));
  EXPECT_LT(*exact.orientation_error, 1e-12);
  EXPECT_EQ(*exact.energy_drift,
            recompute(near_intermediate(1e-3, "exact", "euler", 1.0 / 60, 3000)).energy_drift);
  EXPECT_LT(*exact.energy_drift, 1e-13);
  // The particle model (fig05: stiff springs, damping, normalization) turns like the rigid
  // book: its best-fit rotation stays within 0.01 rad of the exact one until the first flip
  // (t = 100 here; it drifts by radians over the later flips), and it flips within 0.2 time
  // units of the exact first flip.
  const scene::Scene s =
      scene::parse_scene(scene_file("fig05-particle-unstable-x"), {"time.frames=201"});
  const analysis::RunMeasures particle = analysis::measure_run(s);
  ASSERT_TRUE(particle.orientation_error && particle.first_flip_exact);
  EXPECT_GT(*particle.orientation_error, 0.0);
  EXPECT_LT(*particle.orientation_error, 0.01);
  const analysis::RunMeasures longer = analysis::measure_run(
      scene::parse_scene(scene_file("fig05-particle-unstable-x"), {"time.frames=260"}));
  ASSERT_TRUE(longer.first_flip);
  EXPECT_NEAR(*longer.first_flip, *longer.first_flip_exact, 0.2);
}

TEST(SweepMeasures, ADivergingRunIsMeasuredUpToItsLastFiniteStep) {
  // Euler without SVD on the matrix at dt = 2: the matrix grows until it is absurdly large.
  const scene::Scene s =
      scene::parse_scene(scene_file("fig10-matrix-no-normalization"), {"time.dt=2"});
  const analysis::RunMeasures m = analysis::measure_run(s);
  const Recomputed expected = recompute(s);
  ASSERT_TRUE(m.diverged_at);
  ASSERT_TRUE(expected.diverged_at);
  EXPECT_GT(*expected.diverged_at, 2.0);
  EXPECT_EQ(*m.diverged_at, *expected.diverged_at);  // the first step that is not finite
  EXPECT_FALSE(m.orientation_error);
  EXPECT_EQ(*m.energy_drift, expected.energy_drift);  // over the finite steps only
  EXPECT_GT(*m.energy_drift, 1.0);
}

TEST(SweepRun, FlipPeriodOfEveryPointMatchesTheClosedFormOnALogGrid) {
  // The acceptance sweep: 20 log-spaced ε on the exact model (1e-6 … 1e-2) and on
  // quaternion RK4 at dt = 1/60, whose period is round-off limited below ε ≈ 4e-6
  // (docs/physics.md §14), so from 5e-6 … 1e-2.
  for (const auto& [kind, start] :
       {std::pair<std::string, std::string>{"exact", "1e-6"}, {"rigid-quaternion", "5e-6"}}) {
    SweepRequest request;
    request.scene_path =
        std::string(BOOKSPIN_SOURCE_DIR) + "/sweeps/flip-time-vs-perturbation.toml";
    request.overrides = {"model.kind=\"" + kind + "\"", kind == "exact"
                                                            ? "model.integrator=\"euler\""
                                                            : "model.integrator=\"rk4\""};
    request.ranges = {parse_vary("initial.angular_velocity[1]=" + start + ":1e-2:20:log")};
    request.measures = parse_measures("flip_period,first_flip");
    request.jobs = 2;
    std::stringstream csv;
    write_sweep_csv(measure_sweep(request), csv);
    std::string line;
    std::getline(csv, line);
    ASSERT_EQ(line,
              "initial.angular_velocity[1],flip_period,first_flip,flip_period_exact,"
              "first_flip_exact,refused");
    int rows = 0;
    double previous_first = 1e300;
    while (std::getline(csv, line)) {
      const auto c = cells_of(line);
      ASSERT_EQ(c.size(), 6u) << line;
      EXPECT_EQ(c[5], "") << line;  // no point refused
      const double period = std::stod(c[1]), exact = std::stod(c[3]);
      EXPECT_NEAR(period / exact, 1.0, 1e-6) << kind << " " << line;
      EXPECT_LT(std::stod(c[2]), previous_first) << line;  // closer to the axis: later flip
      previous_first = std::stod(c[2]);
      ++rows;
    }
    EXPECT_EQ(rows, 20) << kind;
  }
}

}  // namespace
}  // namespace bookspin::jobs
