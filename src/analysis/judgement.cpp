#include "analysis/judgement.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "analysis/motion.hpp"
#include "common/errors.hpp"
#include "common/number_text.hpp"
#include "common/text_lines.hpp"
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

/// A unit quaternion's component for a line: three decimals, trailing zeros dropped ("0.707",
/// "1", "0"; round-off such as 3e-21 reads 0, and so does -0).
std::string unit_component(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", value);
  std::string out = text;
  while (out.back() == '0') out.pop_back();
  if (out.back() == '.') out.pop_back();
  return out == "-0" ? "0" : out;
}

/// "1 turn-over", "0 turn-overs", "6 turn-overs": a count in words, its noun in number.
std::string turn_overs(int count) {
  return std::to_string(count) + (count == 1 ? " turn-over" : " turn-overs");
}

}  // namespace

/// `text` with every byte outside printable ASCII as \xNN: a name quoted in one line.
static std::string printable(const std::string& text) {
  std::string out;
  for (const char ch : text) {
    const unsigned code = static_cast<unsigned char>(ch);
    if (code >= 0x20 && code < 0x7f && ch != '\\') {
      out += ch;
      continue;
    }
    char escaped[8];
    std::snprintf(escaped, sizeof escaped, "\\x%02x", code);
    out += escaped;
  }
  return out;
}

std::string scenario_name_problem(const std::string& name) {
  // The rule, said in every refusal of a name it does not take: a letter of another script is
  // a letter, but not in a scenario's name.
  static const std::string rule =
      " (a scenario's name is ASCII letters, digits, '-', '_' and '.', the first a letter or a "
      "digit: a name every engine's tools write as a file's name)";
  if (name.empty()) return "is empty";
  if (name.size() > ScenarioLimits::max_name)
    return "is " + std::to_string(name.size()) + " characters long (at most " +
           std::to_string(ScenarioLimits::max_name) + ")";
  const auto alnum = [](char ch) {
    return (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9');
  };
  for (std::size_t i = 0; i < name.size(); ++i) {
    const char ch = name[i];
    if (alnum(ch) || (i > 0 && (ch == '-' || ch == '_' || ch == '.'))) continue;
    const unsigned code = static_cast<unsigned char>(ch);
    char shown[48];
    if (code >= 0x80)
      std::snprintf(shown, sizeof shown, "a character beyond ASCII (byte 0x%02x)", code);
    else if (code < 0x20 || code == 0x7f)
      std::snprintf(shown, sizeof shown, "byte 0x%02x", code);
    else
      std::snprintf(shown, sizeof shown, "'%c'", ch);
    return std::string(i == 0 ? "starts with " : "holds ") + shown + " at byte " +
           std::to_string(i + 1) + rule;
  }
  return "";
}

void check_scenario(const Scenario& s) {
  if (const std::string why = scenario_name_problem(s.name); !why.empty())
    throw InputError("flipcheck: scenario name " + quoted_name(printable(s.name)) + " " + why);
  const auto refuse = [&s](const std::string& field, const std::string& why) {
    throw InputError(s.name + ": " + field + ": " + why);
  };
  const char* axes = "xyz";
  for (int i = 0; i < 3; ++i) {
    const double m = s.body.moments[i];
    if (!(std::isfinite(m) && m >= ScenarioLimits::min_moment && m <= ScenarioLimits::max_moment))
      refuse(std::string("principal_moments[") + std::to_string(i) + "]",
             short_number(m) + " (about body " + axes[i] +
                 "): each must be finite, from 1e-30 to 1e30 mass·length²");
  }
  if (!(std::isfinite(s.body.cage.mass) && s.body.cage.mass > 0.0))
    refuse("mass", short_number(s.body.cage.mass) + ": must be finite and > 0");
  const Eigen::Vector3d omega0 = start_omega(s);
  for (int i = 0; i < 3; ++i)
    if (!(std::abs(omega0[i]) <= ScenarioLimits::max_omega))
      refuse(std::string("omega0_body[") + std::to_string(i) + "]",
             short_number(omega0[i]) + " is beyond ±1e6 rad per time unit");
  if (omega0.isZero()) refuse("omega0_body", "the body is at rest: nothing to judge");
  if (!(std::isfinite(s.dt) && s.dt > 0.0))
    refuse("dt", short_number(s.dt) + ": must be finite and > 0");
  if (s.steps < 1 || s.steps > ScenarioLimits::max_steps)
    refuse("steps", std::to_string(s.steps) +
                        ": must be from 1 to 10^7 (the exact motion is exported at every step)");
  const double turn = omega0.norm() * s.dt * static_cast<double>(s.steps);
  if (!(turn <= ScenarioLimits::max_turn))
    refuse("dt", short_number(s.dt) + " over " + std::to_string(s.steps) +
                     " steps turns the body by |ω0|·dt·steps = " + short_number(turn) +
                     " rad: at most 1e8 (a double carries the exact motion's phase to 1e-8 "
                     "rad there)");
}

Eigen::Vector3d start_omega(const Scenario& scenario) {
  const Eigen::Vector3d& moments = scenario.body.moments;
  return physics::initial_angular_momentum(moments, scenario.initial).cwiseQuotient(moments);
}

namespace {

/// The angle (rad, 0 … π) of the rotation `q`, 2·atan2(|q_xyz|, |q_w|): well conditioned at 0
/// and at π alike (2·asin(‖a − b‖_F/√8) loses half its digits near π, where a motion that
/// has turned over the wrong way sits).
double angle_of(const Eigen::Quaterniond& q) {
  return 2.0 * std::atan2(q.vec().norm(), std::abs(q.w()));
}

/// Angle (rad) between two vectors, atan2(|a × b|, a·b): accurate near 0 and π.
double angle_between(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

/// The exact motion's turn-overs as rows every `stride` steps up to `last_step` show them.
struct SampledExact {
  int flips = 0;
  std::optional<double> first_flip;
};

SampledExact sample_exact(const physics::ExactRotation& exact, int mid, double dt, long long stride,
                          long long last_step) {
  FlipDetector seen;
  const double L_norm = exact.angular_momentum_norm();
  for (long long n = 0; n <= last_step; n += stride) {
    const double t = static_cast<double>(n) * dt;
    seen.observe(t, exact.angular_momentum_body(t)[mid] / L_norm);
  }
  return {seen.count(), seen.first_flip()};
}

/// Whether `seen` shows the exact motion's turn-overs: all `flips_exact` of them, the first
/// within `tolerance` of its time `first_exact` (time units).
bool shows_turn_overs(const SampledExact& seen, int flips_exact,
                      const std::optional<double>& first_exact, double tolerance) {
  if (seen.flips != flips_exact) return false;
  if (!first_exact || !seen.first_flip) return true;
  return std::abs(*seen.first_flip - *first_exact) <= tolerance;
}

/// InputError for rows too far apart to show the turn-overs, naming a stride that shows them.
/// Not inlined (a cold path): inlined into judge_motion, GCC 12 took the payload of an empty
/// std::optional passed to it for possibly uninitialized (-Wmaybe-uninitialized).
[[noreturn, gnu::noinline]] void refuse_sampling(const physics::ExactRotation& exact, int mid,
                                                 double dt, long long stride, long long last_step,
                                                 int flips_exact, const SampledExact& seen,
                                                 const std::optional<double>& first_exact,
                                                 double tolerance) {
  // A stride named safe for any smaller one too: at most `tolerance` (1 % of T/2) apart, so
  // that the first turn-over, bracketed by two rows, is placed within it; halved until the
  // exact motion at it shows every turn-over.
  const double safe = std::floor(tolerance / dt);
  long long fine = std::max<long long>(1, stride / 2);
  if (safe < static_cast<double>(fine)) fine = safe >= 1.0 ? static_cast<long long>(safe) : 1;
  while (fine > 1 && !shows_turn_overs(sample_exact(exact, mid, dt, fine, last_step), flips_exact,
                                       first_exact, tolerance))
    fine = std::max<long long>(1, fine / 2);
  std::string shown = std::to_string(seen.flips) + " of its " + turn_overs(flips_exact);
  if (seen.flips == flips_exact && seen.first_flip && first_exact)
    shown = "its first turn-over " + short_number(std::abs(*seen.first_flip - *first_exact)) +
            " time units off";
  if (stride == 1)
    throw InputError("the scenario's dt = " + short_number(dt) +
                     " is too coarse to judge the turn-overs: its exact motion at every step "
                     "shows " +
                     shown + " (a scenario with a smaller dt can be judged)");
  throw InputError("rows every " + std::to_string(stride) + " steps (" +
                   short_number(static_cast<double>(stride) * dt) +
                   " time units) are too far apart to judge the turn-overs: the exact motion "
                   "at these rows shows " +
                   shown + "; write a row at least every " + std::to_string(fine) + " steps (" +
                   short_number(static_cast<double>(fine) * dt) + " time units)");
}

}  // namespace

Conformance judge_motion(const Scenario& s, const std::vector<MotionSample>& motion,
                         const ConformanceThresholds& limits, const StopPoll& stop) {
  BOOKSPIN_ASSERT(!motion.empty() && motion.front().step == 0);
  // The physics first (start, exact motion, the rows' diagnostics), then the measures of
  // analysis/motion.hpp over them.
  const Eigen::Vector3d& moments = s.body.moments;
  const Eigen::Vector3d omega0 = start_omega(s);
  const physics::ExactRotation exact(moments, omega0);
  const int mid = physics::principal_order(moments)[1];  // the intermediate axis
  const double I2 = moments[mid];
  const Eigen::Vector3d L_exact_world = exact.angular_momentum_world();

  Conformance c;
  c.stride = motion.size() > 1 ? motion[1].step : 1;
  c.last_step = motion.back().step;
  // Whole when the rows reach the last step, or the last multiple of the stride before it (the
  // next row would be past the end).
  c.complete = c.last_step >= s.steps || c.last_step + c.stride > s.steps;
  c.half_period = exact.flip_period();
  // The motion's own diagnostics from its q and ω (docs/physics.md §9): L = R I ω in the world.
  const auto diagnostics_of = [&](const MotionSample& row, const Eigen::Matrix3d& R) {
    const Eigen::Vector3d L = R * moments.cwiseProduct(row.omega_body);
    physics::Diagnostics d =
        physics::rigid_diagnostics(s.body, R, L, static_cast<double>(row.step) * s.dt);
    d.omega_body = row.omega_body;
    return d;
  };
  const physics::Diagnostics d0 =
      diagnostics_of(motion.front(), motion.front().q.normalized().toRotationMatrix());
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
  // The scenario starts at the identity (Scenario::initial): a q(0) away from it is judged
  // first, and its rows read with the components in x, y, z, w order, the common engine order
  // (docs/flipcheck.md, "What judge measures"), are measured against the exact motion too.
  c.start_orientation_error = angle_of(motion.front().q.normalized());
  const bool start_turned = !(c.start_orientation_error <= limits.orientation_error);
  double xyzw_error = 0.0;

  FlipDetector flips, exact_at_rows;
  for (std::size_t i = 0; i < motion.size(); ++i) {
    if (i % 4096 == 4095) stop_if_asked(stop, "flipcheck judge rows");
    const MotionSample& row = motion[i];
    const double t = static_cast<double>(row.step) * s.dt;
    const Eigen::Matrix3d R = row.q.normalized().toRotationMatrix();
    const physics::Diagnostics d = i == 0 ? d0 : diagnostics_of(row, R);
    const physics::ExactState e = exact.state(t);
    // The whole motion against the exact one: the orientation and L's direction at every row.
    const Eigen::Quaterniond q_exact(e.q[0], e.q[1], e.q[2], e.q[3]);
    const Eigen::Matrix3d R_exact = q_exact.toRotationMatrix();
    // Each row-wise measure: its largest and where, and the first row past its limit.
    const auto past = [&](std::optional<long long>& first, double value, double limit) {
      if (!first && !(value <= limit)) first = row.step;
    };
    if (const double angle = angle_of(q_exact.conjugate() * row.q.normalized());
        angle > c.orientation_error || !std::isfinite(angle)) {
      c.orientation_error = angle;
      c.orientation_error_step = row.step;
    }
    past(c.orientation_past, c.orientation_error, limits.orientation_error);
    if (start_turned) {
      // The columns qw, qx, qy, qz holding x, y, z, w: w is the fourth.
      const Eigen::Quaterniond xyzw(row.q.z(), row.q.w(), row.q.x(), row.q.y());
      xyzw_error = std::max(xyzw_error, angle_of(q_exact.conjugate() * xyzw.normalized()));
    }
    if (const double angle = angle_between(d.L, L_exact_world); angle > c.L_direction_error) {
      c.L_direction_error = angle;
      c.L_direction_error_step = row.step;
    }
    past(c.L_direction_past, c.L_direction_error, limits.L_direction);
    const Eigen::Vector3d L_exact = R_exact.transpose() * e.L;  // body frame
    if (std::abs(L_exact[c.spin_axis]) < kTumbleCosine * exact.angular_momentum_norm())
      exact_tumbles = true;
    exact_at_rows.observe(t, L_exact[mid] / exact.angular_momentum_norm());
    if (const double e = std::abs(d.energy_total / E0 - 1.0); e > c.energy_drift) {
      c.energy_drift = e;
      c.energy_drift_step = row.step;
    }
    past(c.energy_drift_past, c.energy_drift, limits.energy_drift);
    if (const double l = std::abs(d.L.norm() / L0 - 1.0); l > c.L_drift) {
      c.L_drift = l;
      c.L_drift_step = row.step;
    }
    past(c.L_drift_past, c.L_drift, limits.L_drift);
    flips.observe(t, d.cos_axis_L[mid]);
    if (!c.tumble_time && std::abs(d.cos_axis_L[c.spin_axis]) < kTumbleCosine) c.tumble_time = t;
    const double r = ratio(d);
    c.separatrix_ratio_drift = std::max(c.separatrix_ratio_drift, std::abs(r / r0 - 1.0));
    if (const double a = (r - r0) / (1.0 - r0); a > c.separatrix_approach) {
      c.separatrix_approach = a;
      c.separatrix_approach_step = row.step;
    }
    past(c.separatrix_past, c.separatrix_approach, limits.separatrix_approach);
  }
  c.stable_spin = c.spin_axis != mid && !exact_tumbles;
  c.q_written_xyzw = start_turned && xyzw_error <= limits.orientation_error;
  const double t_last = static_cast<double>(c.last_step) * s.dt;
  c.flips = flips.count();
  c.first_flip = flips.first_flip();
  c.flips_exact = exact_flip_count(exact, mid, t_last);
  if (exact_flip_amplitude(exact) > FlipDetector::kMargin)
    c.first_flip_exact = exact_first_flip(exact, mid);
  if (c.first_flip && c.first_flip_exact)
    c.first_flip_error = std::abs(*c.first_flip / *c.first_flip_exact - 1.0);
  // Rows too far apart to show the exact motion's own turn-overs cannot be counted: refused.
  // A turn-over the span ends in the middle of (ω about the axis past 0, the cosine not yet
  // past the margin) is not one at any spacing: the count is the exact motion's at every step.
  const double tolerance = limits.sampling_first_flip * c.half_period;
  const SampledExact seen{exact_at_rows.count(), exact_at_rows.first_flip()};
  std::optional<double> first_in_span = c.first_flip_exact;
  if (first_in_span && *first_in_span > t_last) first_in_span.reset();
  if (!shows_turn_overs(seen, c.flips_exact, first_in_span, tolerance)) {
    if (c.stride > 1) {
      const SampledExact every = sample_exact(exact, mid, s.dt, 1, c.last_step);
      c.flips_exact = every.flips;
    } else {
      c.flips_exact = seen.flips;
    }
    if (!shows_turn_overs(seen, c.flips_exact, first_in_span, tolerance))
      refuse_sampling(exact, mid, s.dt, c.stride, c.last_step, c.flips_exact, seen, first_in_span,
                      tolerance);
  }

  auto& f = c.failures;
  // " at step W (limit X; past it from step F)": where a row-wise failure is worst and where it
  // starts.
  const auto where = [](long long worst, const std::optional<long long>& first,
                        const std::string& limit) {
    return " at step " + std::to_string(worst) + " (limit " + limit + "; past it from step " +
           std::to_string(first.value_or(worst)) + ")";
  };
  // q(0) first: a q in the wrong order or turned makes every measure after it wrong, ω's start
  // too where the file gives ω in the world frame (read into the body frame through q).
  if (start_turned) {
    const Eigen::Quaterniond q0 = motion.front().q.normalized();
    const std::string read = "(" + unit_component(q0.w()) + ", " + unit_component(q0.x()) + ", " +
                             unit_component(q0.y()) + ", " + unit_component(q0.z()) + ")";
    const std::string off = short_number(c.start_orientation_error) +
                            " rad from the scenario's orientation (1, 0, 0, 0)";
    f.push_back(c.q_written_xyzw
                    ? "q is written x, y, z, w: bookspin reads w, x, y, z (columns qw, qx, qy, "
                      "qz), so q at step 0 reads " +
                          read + ", " + off +
                          "; read as x, y, z, w, q is the exact motion's within " +
                          short_number(limits.orientation_error) + " rad at every row"
                    : "q at step 0 is " + read + ", " + off + " (limit " +
                          short_number(limits.orientation_error) + " rad)");
  }
  if (!c.complete)
    f.push_back("ends at step " + std::to_string(c.last_step) + " of " + std::to_string(s.steps));
  if (c.start_error > limits.start)
    f.push_back("starts " + short_number(c.start_error) + " off the scenario's omega0 (limit " +
                short_number(limits.start) + ")");
  if (c.energy_drift > limits.energy_drift)
    f.push_back("energy drift " + short_number(c.energy_drift) +
                where(c.energy_drift_step, c.energy_drift_past, short_number(limits.energy_drift)));
  if (c.L_drift > limits.L_drift)
    f.push_back("|L| drift " + short_number(c.L_drift) +
                where(c.L_drift_step, c.L_drift_past, short_number(limits.L_drift)));
  if (!(c.L_direction_error <= limits.L_direction))
    f.push_back(
        "L turned " + short_number(c.L_direction_error) + " rad" +
        where(c.L_direction_error_step, c.L_direction_past, short_number(limits.L_direction)));
  if (c.flips != c.flips_exact)
    f.push_back(turn_overs(c.flips) + ", exact " + std::to_string(c.flips_exact));
  if (c.first_flip && c.first_flip_exact &&
      std::abs(*c.first_flip - *c.first_flip_exact) > limits.first_flip * c.half_period)
    f.push_back("first turn-over " + short_number(*c.first_flip - *c.first_flip_exact) +
                " time units off (limit " + short_number(limits.first_flip * c.half_period) + ", " +
                short_number(100.0 * limits.first_flip) + " % of T/2)");
  if (!(c.orientation_error <= limits.orientation_error))
    f.push_back("orientation error " + short_number(c.orientation_error) + " rad" +
                where(c.orientation_error_step, c.orientation_past,
                      short_number(limits.orientation_error)));
  if (c.stable_spin && c.tumble_time) f.push_back("tumbles at t = " + short_number(*c.tumble_time));
  if (c.stable_spin && c.separatrix_approach > limits.separatrix_approach)
    f.push_back("r = 2E·I2/L² " + short_number(100.0 * c.separatrix_approach) +
                " % of the way to the separatrix" +
                where(c.separatrix_approach_step, c.separatrix_past,
                      short_number(100.0 * limits.separatrix_approach) + " %"));
  return c;
}

std::string verdict_line(const Conformance& c) {
  std::string line = c.pass() ? "PASS" : "FAIL (";
  for (std::size_t i = 0; i < c.failures.size(); ++i) line += (i ? "; " : "") + c.failures[i];
  if (!c.pass()) line += ")";
  line += ": turn-overs " + std::to_string(c.flips) + "/" + std::to_string(c.flips_exact) +
          ", energy drift " + short_number(c.energy_drift) + ", |L| drift " +
          short_number(c.L_drift) + ", L direction " + short_number(c.L_direction_error) +
          " rad, orientation error " + short_number(c.orientation_error) + " rad";
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
                                                   "orientation_error_step",
                                                   "L_direction_error",
                                                   "L_direction_error_step",
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
                          std::to_string(c.orientation_error_step),
                          shortest_cell(c.L_direction_error),
                          std::to_string(c.L_direction_error_step),
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

JudgementRow judgement_row(const Scenario& scenario, const std::string& scenario_sha256,
                           const std::vector<MotionSample>& motion, const std::string& name) {
  const Conformance c = judge_motion(scenario, motion);
  const CsvTable table = judgement_table(scenario, scenario_sha256, {{name, name, c}});
  JudgementRow out;
  out.columns = table.columns;
  // The row as the command line writes it (the one CSV writer), read back into its cells.
  out.csv = csv_text(table, "flipcheck judge CSV");
  const std::size_t row = out.csv.find('\n') + 1;
  out.cells = csv_cells(out.csv.substr(row, out.csv.size() - row - 1));
  out.line = verdict_line(c);
  out.failures = c.failures;
  out.pass = c.pass();
  return out;
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
  rule("orientation_error_over", 1.0);  // every row, not the last alone
  rule("L_direction", limits.L_direction);
  rule("sampling_first_flip", limits.sampling_first_flip);
  rule("max_steps", static_cast<double>(ScenarioLimits::max_steps));
  rule("max_omega", ScenarioLimits::max_omega);
  rule("min_moment", ScenarioLimits::min_moment);
  rule("max_moment", ScenarioLimits::max_moment);
  rule("max_turn", ScenarioLimits::max_turn);
  rule("separatrix_approach", limits.separatrix_approach);
  rule("tumble_cosine", kTumbleCosine);
  rule("flip_margin", FlipDetector::kMargin);
  // The rows' spacing (docs/flipcheck.md, "The motion file"): every stride steps from step 0,
  // ending at the last whole stride or with one more row at the last step.
  text += "rows every_stride_from_0 last_whole_stride_or_last_step\n";
  text += "columns";
  for (const std::string& column : judgement_columns()) text += " " + column;
  return text + "\n";
}

}  // namespace bookspin::analysis
