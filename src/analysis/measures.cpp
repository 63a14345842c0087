#include "analysis/measures.hpp"

#include <algorithm>
#include <cmath>

#include "analysis/motion.hpp"
#include "analysis/twist.hpp"
#include "engines/models.hpp"
#include "physics/exact_model.hpp"

namespace bookspin::analysis {

const std::vector<Measure>& measure_table() {
  static const std::vector<Measure> table{
      {"first_flip", "first flip (time units)", false, &RunMeasures::first_flip, "first_flip_exact",
       &RunMeasures::first_flip_exact},
      {"flip_period", "flip period (time units)", false, &RunMeasures::flip_period,
       "flip_period_exact", &RunMeasures::flip_period_exact},
      {"energy_drift", "max |E/E0 - 1|", true, &RunMeasures::energy_drift, "", nullptr},
      {"orientation_error", "orientation error at the end (rad)", true,
       &RunMeasures::orientation_error, "", nullptr},
      {"diverged_at", "diverged at t (time units)", false, &RunMeasures::diverged_at, "", nullptr},
      {"twist", "twist about L per period (rad)", false, &RunMeasures::twist, "twist_exact",
       &RunMeasures::twist_exact},
  };
  return table;
}

const Measure* find_measure(std::string_view name) {
  const auto& table = measure_table();
  const auto it =
      std::find_if(table.begin(), table.end(), [&](const Measure& m) { return m.name == name; });
  return it == table.end() ? nullptr : &*it;
}

std::string measure_names() {
  std::string names;
  for (const Measure& m : measure_table()) {
    if (!names.empty()) names += ", ";
    names += m.name;
  }
  return names;
}

RunMeasures measure_run(const scene::Scene& scene, const std::function<bool()>& stop) {
  RunMeasures result;
  const Eigen::Vector3d moments = scene.body.moments;
  physics::ExactModel reference(scene.body);
  reference.reset(scene.initial);
  const physics::ExactRotation& exact = reference.rotation();
  auto sim = engines::make_model(scene.body, scene.model);
  sim->reset(scene.initial);
  physics::Diagnostics d = sim->diagnostics();
  const double e0 = d.energy_total;
  double drift = 0.0;
  FlipDetector flips;
  flips.observe(0.0, flip_signal(d, moments));
  // The twist is measured over the first period only (docs/physics.md §19).
  const auto pole = twist_pole(exact);
  std::optional<TwistMeter> twist;
  if (pole) {
    twist.emplace(*pole);
    twist->observe(0.0, sim->orientation(), d.omega_body, d.L);
  }
  const long long total = static_cast<long long>(scene.frames - 1) * scene.steps_per_frame;
  for (long long n = 1; n <= total; ++n) {
    if (stop && n % kStopPollSteps == 0 && stop()) return result;
    sim->step(scene.dt);
    const double t = static_cast<double>(n) * scene.dt;  // a product, as FrameSource does
    if (!sim->finite()) {
      result.diverged_at = t;
      break;
    }
    d = sim->diagnostics();
    drift =
        std::max(drift, e0 != 0.0 ? std::abs(d.energy_total / e0 - 1.0) : std::abs(d.energy_total));
    flips.observe(t, flip_signal(d, moments));
    if (twist && !twist->done()) twist->observe(t, sim->orientation(), d.omega_body, d.L);
  }
  if (twist) result.twist = twist->twist();
  result.energy_drift = drift;
  result.first_flip = flips.first_flip();
  result.flip_period = flips.flip_period();

  result.twist_exact = twist_exact(exact);
  const double half = exact.flip_period();
  if (std::isfinite(half)) result.flip_period_exact = half;
  result.first_flip_exact = exact_first_flip(exact, intermediate_axis(moments));
  if (!result.diverged_at) {
    const Eigen::Matrix3d r_exact = exact.orientation(static_cast<double>(total) * scene.dt);
    result.orientation_error = rotation_angle_between(r_exact, sim->orientation());
  }
  return result;
}

TwistMeasure measure_twist(const scene::Scene& scene) {
  physics::ExactModel reference(scene.body);
  reference.reset(scene.initial);
  const physics::ExactRotation& exact = reference.rotation();
  const auto pole = twist_pole(exact);
  if (!pole) return {};
  TwistMeasure result;
  result.closed_form = twist_exact(exact);
  auto sim = engines::make_model(scene.body, scene.model);
  sim->reset(scene.initial);
  TwistMeter meter(*pole);
  const physics::Diagnostics d0 = sim->diagnostics();
  meter.observe(0.0, sim->orientation(), d0.omega_body, d0.L);
  const auto steps = static_cast<long long>(std::ceil(2.0 * exact.period() / scene.dt));
  for (long long n = 1; n <= steps && !meter.done(); ++n) {
    sim->step(scene.dt);
    if (!sim->finite()) break;
    const physics::Diagnostics d = sim->diagnostics();
    meter.observe(static_cast<double>(n) * scene.dt, sim->orientation(), d.omega_body, d.L);
  }
  result.measured = meter.twist();
  return result;
}

}  // namespace bookspin::analysis
