// Bench section: the cost of one step of every model × integrator and its accuracy, next
// to MuJoCo's mj_step on the same free book with the same dt.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "analysis/accuracy.hpp"
#include "bench/clock.hpp"
#include "bench/mujoco.hpp"
#include "bench/sections.hpp"
#include "physics/shape.hpp"
#include "scene/scene.hpp"

namespace bookspin::bench {

namespace {

constexpr long kSteps = 100000;       // ≥ 4 ms per timed run even for the cheapest step
constexpr long kMujocoSteps = 10000;  // about as long for mj_step
constexpr int kRepetitions = 7;

std::string time_text(double t) {
  char text[64];
  std::snprintf(text, sizeof text, "at t = %.1f (2 exact flip periods)", t);
  return text;
}

/// ns per step, thread CPU time, of one timed run after a reset.
template <typename Reset, typename Run>
double time_run(long steps, Reset&& reset, Run&& run) {
  return best_ns_per_step(steps, 1, reset, run);
}

/// The physics settings and the MuJoCo books built from them.
struct PhysicsBench {
  analysis::AccuracySettings settings;
  double dt = 0.0;
  long error_steps = 0;
  std::unique_ptr<MujocoBook> euler, rk4;  ///< null without MuJoCo
};

std::unique_ptr<MujocoBook> mujoco_book(const PhysicsBench& b, bool rk4) {
  const Eigen::Vector3d L0 =
      physics::initial_angular_momentum(b.settings.body.cage, b.settings.initial);
  const Eigen::Vector3d omega0 =
      b.settings.body.cage.principal_moments().cwiseInverse().cwiseProduct(L0);
  return std::make_unique<MujocoBook>(MujocoSetup{b.settings.body.cage, omega0, b.dt, rk4});
}

void report_inertia(const MujocoBook& book, const physics::Book& ours, BenchReport& report) {
  Eigen::Vector3d moments = ours.principal_moments();
  std::sort(moments.data(), moments.data() + 3);
  const Eigen::Vector3d theirs = book.sorted_moments();
  char text[200];
  std::snprintf(
      text, sizeof text,
      "MuJoCo's principal moments %.9g %.9g %.9g (largest relative gap to the book's: %.1e)",
      theirs.x(), theirs.y(), theirs.z(),
      (theirs - moments).cwiseQuotient(moments).cwiseAbs().maxCoeff());
  report.remark(text);
}

/// MuJoCo's rows apart from the paired Euler timings: RK4's cost and both errors.
void report_mujoco(PhysicsBench& b, const physics::ExactRotation& exact, BenchReport& report) {
  report_inertia(*b.euler, b.settings.body.cage, report);
  for (MujocoBook* book : {b.euler.get(), b.rk4.get()}) {
    const std::string name = book == b.rk4.get() ? "MuJoCo mj_step RK4" : "MuJoCo mj_step Euler";
    if (book == b.rk4.get()) {
      const double ns = best_ns_per_step(
          kMujocoSteps, kRepetitions, [&] { book->reset(); }, [&](long n) { book->step(n); });
      report.add({"physics", name, ns, "ns/step", "free box of the book's size and mass, same dt"});
    }
    book->reset();
    book->step(b.error_steps);
    report.add({"physics", name + ", orientation error",
                analysis::rotation_angle_between(exact.orientation(b.error_steps * b.dt),
                                                 book->orientation()),
                "rad", time_text(b.error_steps * b.dt)});
  }
}

/// Best-of timings of one method and of MuJoCo's Euler step, taken in alternation so that
/// both see the same load on a shared machine.
struct Paired {
  double method_ns = 0.0;
  std::optional<double> mujoco_ns;
};

Paired time_paired(const PhysicsBench& b, const analysis::Method& m) {
  physics::ModelConfig config = b.settings.model;
  config.kind = m.kind;
  config.integrator = m.integrator;
  auto sim = physics::make_simulator(b.settings.body, config);
  Paired best;
  for (int r = 0; r < kRepetitions; ++r) {
    const double ns = time_run(
        kSteps, [&] { sim->reset(b.settings.initial); },
        [&](long n) {
          for (long i = 0; i < n; ++i) sim->step(b.dt);
        });
    best.method_ns = r == 0 ? ns : std::min(best.method_ns, ns);
    if (!b.euler) continue;
    const double mj = time_run(
        kMujocoSteps, [&] { b.euler->reset(); }, [&](long n) { b.euler->step(n); });
    best.mujoco_ns = best.mujoco_ns ? std::min(*best.mujoco_ns, mj) : mj;
  }
  volatile double keep = sim->corners()(0, 0);  // the steps' result stays observable
  (void)keep;
  return best;
}

}  // namespace

void bench_physics(const BenchContext& c) {
  const scene::Scene scene = scene::parse_scene(c.options.scene_path);
  PhysicsBench b;
  b.settings = {scene.body, scene.initial, scene.model, 2.0};
  b.settings.model.normalize = true;  // the paper's per-step normalization for every model
  b.dt = scene.dt;
  const auto exact = analysis::exact_reference(b.settings);
  b.error_steps = std::lround(b.settings.flips * exact.flip_period() / b.dt);
  BenchReport& report = *c.report;
  if (const std::string why = mujoco_missing(); why.empty()) {
    b.euler = mujoco_book(b, false);
    b.rk4 = mujoco_book(b, true);
    report_mujoco(b, exact, report);
  } else {
    report.remark("MuJoCo rows skipped: " + why);
  }
  double mujoco_best = INFINITY;
  for (const analysis::Method& m : analysis::all_methods()) {
    const std::string name = m.label + ", normalized";
    const Paired t = time_paired(b, m);
    report.add({"physics", name, t.method_ns, "ns/step",
                "best of " + std::to_string(kRepetitions) + ", thread CPU time"});
    report.add({"physics", name + ", orientation error",
                analysis::orientation_error_at(b.settings, exact, m, b.dt, b.error_steps * b.dt),
                "rad", time_text(b.error_steps * b.dt)});
    if (!t.mujoco_ns) continue;
    mujoco_best = std::min(mujoco_best, *t.mujoco_ns);
    const double ratio = *t.mujoco_ns / t.method_ns;
    report.add({"physics", "MuJoCo Euler / " + m.label, ratio, "x",
                "times cheaper than mj_step (timed in alternation)"});
  }
  if (std::isfinite(mujoco_best))
    report.add({"physics", "MuJoCo mj_step Euler", mujoco_best, "ns/step",
                "best over all the alternated runs"});
}

}  // namespace bookspin::bench
