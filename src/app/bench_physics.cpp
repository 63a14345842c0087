// Bench section: the cost of one step of every model × integrator, and its accuracy, next
// to MuJoCo's mj_step on the same free book with the same dt.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "analysis/accuracy.hpp"
#include "app/bench_clock.hpp"
#include "app/bench_mujoco.hpp"
#include "app/bench_sections.hpp"
#include "physics/shape.hpp"
#include "scene/scene.hpp"

namespace bookspin::app {

namespace {

constexpr long kTimingSteps = 100000;  // ≥ 5 ms per run even for the cheapest step
constexpr long kMujocoTimingSteps = 20000;
constexpr int kRepetitions = 5;

std::string method_name(const analysis::Method& m) {
  return std::string(physics::to_string(m.kind)) + " " + std::string(physics::to_string(m.integrator));
}

double ns_per_step(const analysis::AccuracySettings& s, const analysis::Method& m, double dt) {
  physics::ModelConfig config = s.model;
  config.kind = m.kind;
  config.integrator = m.integrator;
  auto sim = physics::make_simulator(s.book, config);
  const double ns = best_ns_per_step(
      kTimingSteps, kRepetitions, [&] { sim->reset(s.initial); },
      [&](long steps) {
        for (long i = 0; i < steps; ++i) sim->step(dt);
      });
  volatile double keep = sim->corners()(0, 0);  // the steps' result stays observable
  (void)keep;
  return ns;
}

/// The speed targets of issue 7, against MuJoCo's Euler step; 0 where there is none.
double speed_target(const analysis::Method& m) {
  if (m.integrator != physics::Integrator::euler) return 0.0;
  switch (m.kind) {
    case physics::ModelKind::rigid_quaternion: return 20.0;
    case physics::ModelKind::rigid_matrix: return 5.0;
    case physics::ModelKind::particle: return 4.0;
    default: return 0.0;
  }
}

std::string time_text(double t) {
  char text[64];
  std::snprintf(text, sizeof text, "at t = %.1f (2 exact flip periods)", t);
  return text;
}

/// MuJoCo derives the inertia from the box geom; says whether it is the book's.
void report_inertia(const Eigen::Vector3d& mujoco_sorted, const physics::Book& book,
                    BenchReport& report) {
  Eigen::Vector3d ours = book.principal_moments();
  std::sort(ours.data(), ours.data() + 3);
  const double gap = ((mujoco_sorted - ours).cwiseQuotient(ours)).cwiseAbs().maxCoeff();
  char text[160];
  std::snprintf(text, sizeof text, "MuJoCo's principal moments %.9g %.9g %.9g (relative gap to the book's %.1e)",
                mujoco_sorted.x(), mujoco_sorted.y(), mujoco_sorted.z(), gap);
  report.remark(text);
}

/// MuJoCo's Euler ns/step, or NaN when MuJoCo is missing or fails.
double bench_mujoco(const analysis::AccuracySettings& s, const physics::ExactRotation& exact,
                    double dt, long error_steps, BenchReport& report) {
  if (const std::string why = mujoco_missing(); !why.empty()) {
    report.remark("MuJoCo rows skipped: " + why);
    return std::nan("");
  }
  const Eigen::Vector3d L0 = physics::initial_angular_momentum(s.book, s.initial);
  MujocoSetup setup{s.book, s.book.principal_moments().cwiseInverse().cwiseProduct(L0), dt, false};
  double euler_ns = 0.0;
  for (bool rk4 : {false, true}) {
    setup.rk4 = rk4;
    const MujocoResult r = run_mujoco(setup, exact, error_steps, kMujocoTimingSteps, kRepetitions);
    const std::string name = rk4 ? "MuJoCo mj_step RK4" : "MuJoCo mj_step Euler";
    report.add({"physics", name, r.ns_per_step, "ns/step", "free box, same size, mass, dt"});
    report.add({"physics", name + ", orientation error", r.orientation_error, "rad",
                time_text(error_steps * dt)});
    if (!rk4) euler_ns = r.ns_per_step;
    if (!rk4) report_inertia(r.moments, s.book, report);
  }
  return euler_ns;
}

}  // namespace

void bench_physics(const BenchContext& c) {
  const scene::Scene scene = scene::parse_scene(c.options.scene_path);
  analysis::AccuracySettings s{scene.book, scene.initial, scene.model, 2.0};
  s.model.normalize = true;  // the paper's per-step normalization for every model
  const auto exact = analysis::exact_reference(s);
  const double dt = scene.dt;
  const long error_steps = std::lround(s.flips * exact.flip_period() / dt);
  BenchReport& report = *c.report;
  const double mujoco_ns = bench_mujoco(s, exact, dt, error_steps, report);
  for (const analysis::Method& m : analysis::all_methods()) {
    const std::string name = method_name(m) + ", normalized";
    const double ns = ns_per_step(s, m, dt);
    report.add({"physics", name, ns, "ns/step", "dt = " + std::to_string(dt)});
    report.add({"physics", name + ", orientation error",
                analysis::orientation_error_at(s, exact, m, dt, error_steps * dt), "rad",
                time_text(error_steps * dt)});
    if (std::isnan(mujoco_ns)) continue;
    const double target = speed_target(m);
    report.add({"physics", "MuJoCo Euler / " + method_name(m), mujoco_ns / ns, "x",
                target > 0.0 ? at_least(mujoco_ns / ns, target) : "times cheaper than mj_step"});
  }
}

}  // namespace bookspin::app
