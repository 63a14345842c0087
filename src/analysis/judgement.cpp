#include "analysis/judgement.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "analysis/motion.hpp"
#include "common/errors.hpp"
#include "common/number_text.hpp"
#include "common/version.hpp"
#include "physics/exact_solution.hpp"
#include "physics/shape.hpp"

namespace bookspin::analysis {

namespace {

/// A measure for the verdict line: "%.3g" (a line for people; the CSV has every digit).
std::string short_number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

}  // namespace

Eigen::Vector3d start_omega(const Scenario& scenario) {
  const Eigen::Vector3d& moments = scenario.body.moments;
  return physics::initial_angular_momentum(moments, scenario.initial).cwiseQuotient(moments);
}

Conformance judge_motion(const Scenario& s, const std::vector<MotionSample>& motion,
                         const ConformanceThresholds& limits) {
  BOOKSPIN_ASSERT(!motion.empty() && motion.front().step == 0);
  // The physics first (start, exact motion, the rows' diagnostics), then the measures of
  // analysis/motion.hpp over them.
  const Eigen::Vector3d& moments = s.body.moments;
  const Eigen::Vector3d omega0 = start_omega(s);
  const physics::ExactRotation exact(moments, omega0);
  const int mid = physics::principal_order(moments)[1];  // the intermediate axis
  const double I2 = moments[mid];

  Conformance c;
  c.stride = motion.size() > 1 ? motion[1].step : 1;
  c.last_step = motion.back().step;
  c.complete = c.last_step >= s.steps;
  c.half_period = exact.flip_period();
  // The motion's own diagnostics from its q and ω (docs/physics.md §9): L = R I ω in the world.
  const auto diagnostics_of = [&](const MotionSample& row) {
    const Eigen::Matrix3d R = row.q.normalized().toRotationMatrix();
    const Eigen::Vector3d L = R * moments.cwiseProduct(row.omega_body);
    physics::Diagnostics d =
        physics::rigid_diagnostics(s.body, R, L, static_cast<double>(row.step) * s.dt);
    d.omega_body = row.omega_body;
    return d;
  };
  const physics::Diagnostics d0 = diagnostics_of(motion.front());
  c.start_error = (motion.front().omega_body - omega0).norm() / omega0.norm();
  const double E0 = d0.energy_total, L0 = d0.L.norm();
  // The spin axis: the body axis nearest L at the start (largest |L_b| component).
  const Eigen::Vector3d L0_body = moments.cwiseProduct(omega0);
  L0_body.cwiseAbs().maxCoeff(&c.spin_axis);
  const auto ratio = [&](const physics::Diagnostics& d) {
    return 2.0 * d.energy_total * I2 / d.L.squaredNorm();  // 1 on the separatrix (§8)
  };
  const double r0 = ratio(d0);
  bool exact_tumbles = false;

  FlipDetector flips;
  for (const MotionSample& row : motion) {
    const double t = static_cast<double>(row.step) * s.dt;
    const physics::Diagnostics d = row.step == 0 ? d0 : diagnostics_of(row);
    const Eigen::Vector3d L_exact = exact.angular_momentum_body(t);
    if (std::abs(L_exact[c.spin_axis]) < kTumbleCosine * exact.angular_momentum_norm())
      exact_tumbles = true;
    c.energy_drift = std::max(c.energy_drift, std::abs(d.energy_total / E0 - 1.0));
    c.L_drift = std::max(c.L_drift, std::abs(d.L.norm() / L0 - 1.0));
    flips.observe(t, d.cos_axis_L[mid]);
    if (!c.tumble_time && std::abs(d.cos_axis_L[c.spin_axis]) < kTumbleCosine) c.tumble_time = t;
    const double r = ratio(d);
    c.separatrix_ratio_drift = std::max(c.separatrix_ratio_drift, std::abs(r / r0 - 1.0));
    c.separatrix_approach = std::max(c.separatrix_approach, (r - r0) / (1.0 - r0));
  }
  c.stable_spin = c.spin_axis != mid && !exact_tumbles;
  const double t_last = static_cast<double>(c.last_step) * s.dt;
  c.flips = flips.count();
  c.first_flip = flips.first_flip();
  c.flips_exact = exact_flip_count(exact, mid, t_last);
  if (exact_flip_amplitude(exact) > FlipDetector::kMargin)
    c.first_flip_exact = exact_first_flip(exact, mid);
  if (c.first_flip && c.first_flip_exact)
    c.first_flip_error = std::abs(*c.first_flip / *c.first_flip_exact - 1.0);
  const Eigen::Matrix3d R_last = motion.back().q.normalized().toRotationMatrix();
  c.orientation_error = rotation_angle_between(exact.orientation(t_last), R_last);

  auto& f = c.failures;
  if (!c.complete)
    f.push_back("ends at step " + std::to_string(c.last_step) + " of " + std::to_string(s.steps));
  if (c.start_error > limits.start)
    f.push_back("starts " + short_number(c.start_error) + " off the scenario's omega0");
  if (c.energy_drift > limits.energy_drift)
    f.push_back("energy drift " + short_number(c.energy_drift));
  if (c.L_drift > limits.L_drift) f.push_back("|L| drift " + short_number(c.L_drift));
  if (c.flips != c.flips_exact)
    f.push_back(std::to_string(c.flips) + " turn-overs, exact " + std::to_string(c.flips_exact));
  if (c.first_flip && c.first_flip_exact &&
      std::abs(*c.first_flip - *c.first_flip_exact) > limits.first_flip * c.half_period)
    f.push_back("first turn-over " + short_number(*c.first_flip - *c.first_flip_exact) +
                " time units off");
  if (c.orientation_error > limits.orientation_error)
    f.push_back("orientation error " + short_number(c.orientation_error) + " rad");
  if (c.stable_spin && c.tumble_time) f.push_back("tumbles at t = " + short_number(*c.tumble_time));
  if (c.stable_spin && c.separatrix_approach > limits.separatrix_approach)
    f.push_back("r = 2E·I2/L² " + short_number(100.0 * c.separatrix_approach) +
                " % of the way to the separatrix");
  return c;
}

std::string verdict_line(const Conformance& c) {
  std::string line = c.pass() ? "PASS" : "FAIL (";
  for (std::size_t i = 0; i < c.failures.size(); ++i) line += (i ? "; " : "") + c.failures[i];
  if (!c.pass()) line += ")";
  line += ": turn-overs " + std::to_string(c.flips) + "/" + std::to_string(c.flips_exact) +
          ", energy drift " + short_number(c.energy_drift) + ", |L| drift " +
          short_number(c.L_drift) + ", orientation error " + short_number(c.orientation_error) +
          " rad";
  if (c.stable_spin)
    line += c.tumble_time ? ", tumbles at t = " + short_number(*c.tumble_time) : ", no tumble";
  return line;
}

namespace {

const std::vector<std::string>& judgement_columns() {
  static const std::vector<std::string> columns = {"scenario",
                                                   "motion",
                                                   "verdict",
                                                   "stride",
                                                   "last_step",
                                                   "start_error",
                                                   "energy_drift",
                                                   "L_drift",
                                                   "flips",
                                                   "flips_exact",
                                                   "first_flip",
                                                   "first_flip_exact",
                                                   "first_flip_error",
                                                   "orientation_error",
                                                   "stable_spin",
                                                   "tumble_time",
                                                   "separatrix_ratio_drift",
                                                   "separatrix_approach",
                                                   "failures",
                                                   "version",
                                                   "scenario_sha256"};
  return columns;
}

}  // namespace

CsvTable judgement_table(const Scenario& scenario, const std::string& scenario_sha256,
                         const std::vector<JudgedMotion>& judged) {
  CsvTable table;
  table.columns = judgement_columns();
  const std::string judged_by = version();
  for (const JudgedMotion& j : judged) {
    const Conformance& c = j.result;
    std::string failures;
    for (const std::string& f : c.failures) failures += (failures.empty() ? "" : "; ") + f;
    const auto if_stable = [&c](double value) {
      return shortest_cell(c.stable_spin ? std::optional<double>(value) : std::nullopt);
    };
    table.rows.push_back({scenario.name,
                          j.name,
                          std::string(c.pass() ? "pass" : "fail"),
                          std::to_string(c.stride),
                          std::to_string(c.last_step),
                          shortest_cell(c.start_error),
                          shortest_cell(c.energy_drift),
                          shortest_cell(c.L_drift),
                          std::to_string(c.flips),
                          std::to_string(c.flips_exact),
                          shortest_cell(c.first_flip),
                          shortest_cell(c.first_flip_exact),
                          shortest_cell(c.first_flip_error),
                          shortest_cell(c.orientation_error),
                          std::string(c.stable_spin ? "1" : "0"),
                          shortest_cell(c.stable_spin ? c.tumble_time : std::nullopt),
                          if_stable(c.separatrix_ratio_drift),
                          if_stable(c.separatrix_approach),
                          failures,
                          judged_by,
                          scenario_sha256});
  }
  return table;
}

std::string judge_rules() {
  const ConformanceThresholds limits;
  std::string text;
  const auto rule = [&text](const std::string& name, double value) {
    text += name + " " + finite_text(value, name) + "\n";
  };
  rule("start", limits.start);
  rule("energy_drift", limits.energy_drift);
  rule("L_drift", limits.L_drift);
  rule("first_flip", limits.first_flip);
  rule("orientation_error", limits.orientation_error);
  rule("separatrix_approach", limits.separatrix_approach);
  rule("tumble_cosine", kTumbleCosine);
  rule("flip_margin", FlipDetector::kMargin);
  text += "columns";
  for (const std::string& column : judgement_columns()) text += " " + column;
  return text + "\n";
}

}  // namespace bookspin::analysis
