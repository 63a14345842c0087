#include "analysis/accuracy.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "common/errors.hpp"
#include "engines/models.hpp"
#include "physics/exact_model.hpp"
#include "physics/model_modes.hpp"

namespace bookspin::analysis {

namespace {

using physics::Integrator;
using physics::ModelKind;

std::unique_ptr<physics::Simulator> start(const AccuracySettings& s, const Method& m) {
  physics::ModelConfig config = s.model;
  config.kind = m.kind;
  config.integrator = m.integrator;
  auto sim = engines::make_model(s.body, config);
  sim->reset(s.initial);
  return sim;
}

/// Steps between two questions of a run's `stop` (as measures.hpp's kStopPollSteps).
constexpr long kStopEvery = 64;

bool stop_now(const std::function<bool()>& stop, long step) {
  return stop && step % kStopEvery == 0 && stop();
}

/// AccuracySettings::clock_ns, or the steady clock: ns since the program first asked, so
/// that a double holds it to well under a nanosecond whatever the clock's epoch.
double now_ns(const AccuracySettings& s) {
  if (s.clock_ns) return s.clock_ns();
  static const auto origin = std::chrono::steady_clock::now();
  return std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - origin)
      .count();
}

double time_steps(const AccuracySettings& s, const Method& m, double dt, long steps,
                  const std::function<bool()>& stop) {
  auto sim = start(s, m);
  const long n = std::min<long>(steps, kMaxTimedSteps);
  const double begin = now_ns(s);
  for (long i = 0; i < n; ++i) {
    if (stop_now(stop, i + 1)) return 0.0;
    sim->step(dt);
  }
  const double end = now_ns(s);
  volatile double sink = sim->corners()(0, 0);  // keep the loop's result observable
  (void)sink;
  return (end - begin) / static_cast<double>(n);
}

}  // namespace

Method::Method(physics::ModelKind kind, physics::Integrator integrator)
    : kind(kind),
      integrator(integrator),
      label(std::string(physics::to_string(kind)) + " " +
            std::string(physics::to_string(integrator))) {}

std::vector<Method> all_methods() {
  std::vector<Method> methods;
  for (const physics::ModelMode& m : physics::model_modes())
    if (!physics::is_engine(m.kind) && m.kind != ModelKind::exact)
      methods.push_back(Method(m.kind, m.integrator));
  return methods;
}

std::vector<Method> accuracy_methods() {
  std::vector<Method> methods = all_methods();
  for (const Method& m : engine_methods()) methods.push_back(m);
  return methods;
}

std::vector<Method> engine_methods() {
  std::vector<Method> methods;
  for (const engines::EngineMode& m : engines::engine_modes())
    methods.push_back(Method(m.kind, m.integrator));
  return methods;
}

namespace {
std::string quoted(const std::string& text) {
  std::string out(1, '"');
  out.append(text);
  out.push_back('"');
  return out;
}

/// "all, engines, rigid, particle, …, or KIND:INTEGRATOR": what an item of --methods may be,
/// every model but the exact one by its name.
std::string method_items() {
  std::string items = "all, engines, rigid, ";
  for (ModelKind kind : physics::model_kinds())
    if (kind != ModelKind::exact) items.append(physics::to_string(kind)).append(", ");
  return items.append("or KIND:INTEGRATOR");
}
}  // namespace

std::vector<Method> parse_methods(const std::string& list) {
  const auto fail = [&](const std::string& reason) -> void {
    throw InputError("--methods " + list + ": " + reason);
  };
  const std::vector<Method> every = accuracy_methods();
  std::vector<bool> chosen(every.size(), false);
  const auto choose = [&](const auto& wanted) {
    for (std::size_t i = 0; i < every.size(); ++i)
      if (wanted(every[i])) chosen[i] = true;
  };
  std::size_t start = 0;
  while (start <= list.size()) {
    const std::size_t comma = std::min(list.find(',', start), list.size());
    const std::string item = list.substr(start, comma - start);
    start = comma + 1;
    if (item.empty()) fail("an empty item (expected e.g. engines,rigid-quaternion:rk4)");
    if (item == "all") {
      choose([](const Method&) { return true; });
      continue;
    }
    if (item == "engines" || item == "rigid") {
      const bool engines = item == "engines";
      choose([&](const Method& m) {
        return engines ? physics::is_engine(m.kind)
                       : m.kind == ModelKind::rigid_matrix || m.kind == ModelKind::rigid_quaternion;
      });
      continue;
    }
    const std::size_t colon = item.find(':');
    ModelKind kind{};
    const std::string kind_name = item.substr(0, colon);
    if (!physics::parse_model_kind(kind_name, kind))
      fail(quoted(kind_name) + " is not a model (" + method_items() + ")");
    if (kind == ModelKind::exact)
      fail("the exact model is the reference every row is measured against");
    if (colon == std::string::npos) {
      choose([&](const Method& m) { return m.kind == kind; });
      continue;
    }
    Integrator integrator{};
    const std::string integrator_name = item.substr(colon + 1);
    if (!physics::parse_integrator(integrator_name, integrator) ||
        !physics::supports(kind, integrator))
      fail(quoted(integrator_name) + " is not an integrator of " +
           std::string(physics::to_string(kind)));
    choose([&](const Method& m) { return m.kind == kind && m.integrator == integrator; });
  }
  std::vector<Method> methods;
  for (std::size_t i = 0; i < every.size(); ++i)
    if (chosen[i]) methods.push_back(every[i]);
  return methods;
}

std::vector<Method> rigid_methods() {
  std::vector<Method> methods;
  for (const Method& m : all_methods())
    if (m.kind == ModelKind::rigid_matrix || m.kind == ModelKind::rigid_quaternion)
      methods.push_back(m);
  return methods;
}

EnergyHistory energy_history(const AccuracySettings& s, const physics::ExactRotation& exact,
                             const Method& m, double dt, double flips, int windows,
                             const std::function<bool()>& stop) {
  EnergyHistory history;
  history.method = m;
  history.dt = dt;
  const long steps = std::lround(flips * exact.flip_period() / dt);
  const long per_window = std::max(1L, steps / windows);
  auto sim = start(s, m);
  const double E0 = sim->diagnostics().energy_total;
  double worst = 0.0;
  for (long i = 1; i <= steps; ++i) {
    if (stop_now(stop, i)) return history;
    sim->step(dt);
    if (!sim->finite()) {
      history.diverged = true;
      break;
    }
    worst = std::max(worst, std::abs(sim->diagnostics().energy_total / E0 - 1.0));
    if (i % per_window == 0) {
      history.t.push_back(static_cast<double>(i) * dt);
      history.relative_error.push_back(worst);
      worst = 0.0;
    }
  }
  return history;
}

physics::ExactRotation exact_reference(const AccuracySettings& s) {
  physics::ExactModel model(s.body);
  model.reset(s.initial);
  return model.rotation();
}

double orientation_error_at(const AccuracySettings& s, const physics::ExactRotation& exact,
                            const Method& m, double dt, double t_end) {
  auto sim = start(s, m);
  const long steps = std::lround(t_end / dt);
  for (long i = 0; i < steps; ++i) sim->step(dt);
  return rotation_angle_between(exact.orientation(steps * dt), sim->orientation());
}

AccuracyRow measure(const AccuracySettings& s, const physics::ExactRotation& exact, const Method& m,
                    double dt, const std::function<bool()>& stop) {
  const double flip = exact.flip_period();
  if (!std::isfinite(flip)) {
    throw InputError("the exact motion has no flip period (separatrix or pure spin)");
  }
  AccuracyRow row;
  row.method = m;
  row.dt = dt;
  row.steps = std::lround(s.flips * flip / dt);
  row.t_end = row.steps * dt;
  auto sim = start(s, m);
  const physics::Diagnostics d0 = sim->diagnostics();
  FlipDetector flips;
  flips.observe(0.0, flip_signal(d0, s.body.moments));
  for (long i = 1; i <= row.steps; ++i) {
    if (stop_now(stop, i)) return row;
    sim->step(dt);
    if (!sim->finite()) {
      row.diverged = true;
      row.divergence_reason = sim->divergence_reason();
      break;
    }
    const physics::Diagnostics d = sim->diagnostics();
    flips.observe(i * dt, flip_signal(d, s.body.moments));
    row.energy_drift = std::max(row.energy_drift, std::abs(d.energy_total / d0.energy_total - 1.0));
    row.L_drift = std::max(row.L_drift, std::abs(d.L.norm() / d0.L.norm() - 1.0));
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  row.orientation_error =
      row.diverged ? nan : rotation_angle_between(exact.orientation(row.t_end), sim->orientation());
  row.flip_period = flips.flip_period().value_or(std::numeric_limits<double>::quiet_NaN());
  row.flip_period_error = std::abs(row.flip_period / flip - 1.0);
  row.first_flip = flips.first_flip().value_or(nan);
  row.flips = flips.count();
  const int intermediate = physics::principal_order(s.body.moments)[1];
  row.flips_exact = exact_flip_count(exact, intermediate, row.t_end);
  if (const auto first_exact = exact_first_flip(exact, intermediate)) {
    row.first_flip_error = std::abs(row.first_flip / *first_exact - 1.0);
  } else {
    row.first_flip_error = nan;
  }
  row.ns_per_step = time_steps(s, m, dt, row.steps, stop);
  return row;
}

}  // namespace bookspin::analysis
