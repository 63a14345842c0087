#include "jobs/exact_motion.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>

#include "analysis/scenario_file.hpp"
#include "common/errors.hpp"
#include "common/number_text.hpp"
#include "scene/limits.hpp"

namespace bookspin::jobs {
namespace {

constexpr double kOmegaMax = scene::limit("initial.angular_velocity").max;

/// Every number of `row` finite.
bool finite(const ExactMotionRow& row) {
  return std::isfinite(row.t) && row.q.allFinite() && row.omega_body.allFinite() &&
         row.omega_world.allFinite() && row.L.allFinite() && std::isfinite(row.E);
}

/// `value` for a message: its shortest text, or nan, inf, -inf.
std::string value_text(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0.0 ? "inf" : "-inf";
  return finite_text(value, "a value in a message");
}

/// Throws InputError where the motion's energy ½ ω·Iω, |L| or largest |ω| is beyond a double,
/// naming the moments and ω0: E and L are the rows' constants, ω reaches its peak within a
/// period (|ω| up to |L|/I_min, docs/physics.md §8).
void refuse_overflow(const physics::ExactRotation& exact) {
  if (std::isfinite(exact.energy()) && std::isfinite(exact.angular_momentum_norm()) &&
      std::isfinite(exact.peak_rate()))
    return;
  const Eigen::Vector3d& I = exact.moments();
  const Eigen::Vector3d& w = exact.omega0_body();
  throw InputError(
      "moments (" + value_text(I[0]) + ", " + value_text(I[1]) + ", " + value_text(I[2]) +
      ") and omega0 (" + value_text(w[0]) + ", " + value_text(w[1]) + ", " + value_text(w[2]) +
      "): the motion's energy ½ ω·Iω, |L| or largest |ω| overflows a double (beyond 1.8e308)");
}

}  // namespace

void exact_motion_each(const Eigen::Vector3d& moments, const Eigen::Vector3d& omega0_body,
                       const std::vector<double>& times, const StopPoll& stop,
                       const std::function<void(std::size_t, const ExactMotionRow&)>& row) {
  for (int i = 0; i < 3; ++i) {
    if (!(std::isfinite(moments[i]) && moments[i] > 0.0))
      throw InputError("moments[" + std::to_string(i) + "]: " + value_text(moments[i]) +
                       " is not a finite positive moment of inertia");
    if (!std::isfinite(omega0_body[i]))
      throw InputError("omega0[" + std::to_string(i) + "]: " + value_text(omega0_body[i]) +
                       " is not a finite angular velocity");
    // A scene's range for ω (scenes/README.md, "Limits"): |L|² and E stay within a double.
    if (std::abs(omega0_body[i]) > kOmegaMax)
      throw InputError("omega0[" + std::to_string(i) + "]: " + value_text(omega0_body[i]) +
                       " is outside the angular velocity's range, ±" + value_text(kOmegaMax) +
                       " rad per time unit (a scene's initial.angular_velocity)");
  }
  for (std::size_t n = 0; n < times.size(); ++n)
    if (!std::isfinite(times[n]))
      throw InputError("t[" + std::to_string(n) + "]: " + value_text(times[n]) +
                       " is not a finite time");
  const physics::ExactRotation exact(moments, omega0_body);
  refuse_overflow(exact);
  // Every time within the motion's horizon before the first row (docs/physics.md §8, "How far
  // in time"): past it the phase or ψ is more than a long double carries.
  for (std::size_t n = 0; n < times.size(); ++n)
    if (!(std::abs(times[n]) <= exact.time_horizon()))
      throw InputError("t[" + std::to_string(n) + "]: " + exact.horizon_reason(times[n]));
  for (std::size_t n = 0; n < times.size(); ++n) {
    if (n % 4096 == 0) stop_if_asked(stop, "exact motion");
    const ExactMotionRow state = exact.state(times[n]);
    BOOKSPIN_ASSERT(finite(state));
    row(n, state);
  }
}

std::vector<ExactMotionRow> exact_motion_at(const Eigen::Vector3d& moments,
                                            const Eigen::Vector3d& omega0_body,
                                            const std::vector<double>& times,
                                            const StopPoll& stop) {
  std::vector<ExactMotionRow> rows;
  rows.reserve(times.size());
  exact_motion_each(moments, omega0_body, times, stop,
                    [&rows](std::size_t, const ExactMotionRow& state) { rows.push_back(state); });
  return rows;
}

namespace {

/// A scenario's start, no rows yet: its mass and jiggled ω0 (analysis::start_omega).
ExactMotion exact_start(const analysis::Scenario& scenario) {
  ExactMotion motion;
  motion.scenario = scenario;
  motion.mass = scenario.body.cage.mass;
  motion.omega0_body = analysis::start_omega(scenario);
  motion.omega0_world = motion.omega0_body;
  return motion;
}

}  // namespace

ExactMotion exact_motion(const analysis::Scenario& scenario, const StopPoll& stop) {
  ExactMotion motion = exact_start(scenario);
  const physics::ExactRotation exact(scenario.body.moments, motion.omega0_body);
  refuse_overflow(exact);
  const double t_end = static_cast<double>(scenario.steps) * scenario.dt;
  if (!(t_end <= exact.time_horizon()))
    throw InputError(scenario.name + ": dt × steps: " + exact.horizon_reason(t_end));
  motion.rows.reserve(static_cast<std::size_t>(scenario.steps) + 1);
  for (long long n = 0; n <= scenario.steps; ++n) {
    if (n % 4096 == 0) stop_if_asked(stop, "flipcheck exact motion");
    motion.rows.push_back(exact.state(static_cast<double>(n) * scenario.dt));
  }
  return motion;
}

void ExactRowArrays::put(std::size_t i, const ExactMotionRow& row) const {
  if (t) t[i] = row.t;
  for (int k = 0; k < 4; ++k)
    if (q) q[4 * i + k] = row.q[k];
  for (int k = 0; k < 3; ++k) {
    if (omega_body) omega_body[3 * i + k] = row.omega_body[k];
    if (omega_world) omega_world[3 * i + k] = row.omega_world[k];
    if (L) L[3 * i + k] = row.L[k];
  }
  if (E) E[i] = row.E;
}

CsvTable exact_motion_csv(const ExactMotion& m) {
  CsvTable table;
  table.columns = {"t",        "qw",       "qx",       "qy", "qz", "wx", "wy", "wz",
                   "wx_world", "wy_world", "wz_world", "Lx", "Ly", "Lz", "E"};
  table.rows.reserve(m.rows.size());
  for (const ExactMotionRow& r : m.rows) {
    table.rows.push_back(
        {shortest_cell(r.t), shortest_cell(r.q[0]), shortest_cell(r.q[1]), shortest_cell(r.q[2]),
         shortest_cell(r.q[3]), shortest_cell(r.omega_body.x()), shortest_cell(r.omega_body.y()),
         shortest_cell(r.omega_body.z()), shortest_cell(r.omega_world.x()),
         shortest_cell(r.omega_world.y()), shortest_cell(r.omega_world.z()), shortest_cell(r.L.x()),
         shortest_cell(r.L.y()), shortest_cell(r.L.z()), shortest_cell(r.E)});
  }
  return table;
}

ExportFiles export_files(const ExactMotion& motion, const StopPoll& stop) {
  // Written 4096 rows at a time, the header once, so that a stop is asked between them
  // (10^6 rows take seconds to spell).
  const CsvTable whole = exact_motion_csv(motion);
  std::string csv;
  const std::size_t chunk = 4096;
  for (std::size_t from = 0; from == 0 || from < whole.rows.size(); from += chunk) {
    stop_if_asked(stop, "flipcheck export csv");
    CsvTable part;
    part.columns = whole.columns;
    const std::size_t to = std::min(whole.rows.size(), from + chunk);
    part.rows.assign(whole.rows.begin() + static_cast<std::ptrdiff_t>(from),
                     whole.rows.begin() + static_cast<std::ptrdiff_t>(to));
    const std::string text = csv_text(part, "flipcheck exact motion CSV");
    csv += from == 0 ? text : text.substr(text.find('\n') + 1);
  }
  return {analysis::scenario_file(motion.scenario), std::move(csv)};
}

}  // namespace bookspin::jobs
