// Every column of the sweep, accuracy, energy and diagnostics CSVs against a number computed
// here without the code that writes it (docs/physics.md §8, §9, §14): closed forms (the flip
// times from the invariants, the lag of an Euler step, the step at which a growing matrix
// passes the divergence limit, the symmetric top's twist), rotations compared by
// Eigen::AngleAxisd, energies from ω and I_body by hand, and the runs replayed step by step
// here. Each CSV is read back and compared column by column, by name: a column without an
// expected value here fails, so a new column needs its independent check
// (tests/architecture/csv_columns_test.cpp lists them all).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "analysis/accuracy.hpp"
#include "common/csv_writer.hpp"
#include "engines/models.hpp"
#include "jobs/accuracy_report.hpp"
#include "jobs/csv_text.hpp"
#include "jobs/simulation.hpp"
#include "jobs/sweep.hpp"
#include "output/atomic_output.hpp"
#include "physics/exact_solution.hpp"
#include "physics/particle_model.hpp"
#include "scene/scene.hpp"
#include "support/closed_form_flips.hpp"
#include "support/scratch.hpp"

namespace bookspin::jobs {
namespace {

using test::closed_form_flips;
using test::ClosedFormFlips;

constexpr double kPi = std::numbers::pi;

/// What one cell must hold: a number within a tolerance, an empty cell, or a text.
struct Expected {
  enum class Kind { number, empty, text, positive } kind = Kind::empty;
  double value = 0.0, tolerance = 0.0;
  std::string text;
};
Expected near(double value, double tolerance) {
  return {Expected::Kind::number, value, tolerance, {}};
}
Expected relative(double value, double tolerance) {
  return near(value, tolerance * std::abs(value));
}
Expected empty() { return {}; }
Expected text(std::string t) { return {Expected::Kind::text, 0.0, 0.0, std::move(t)}; }
/// A measured time (the accuracy CSV's ns_per_step): no value to recompute, only a finite
/// positive one.
Expected positive() { return {Expected::Kind::positive, 0.0, 0.0, {}}; }

/// The expected cells of one row, by column name.
using ExpectedRow = std::map<std::string, Expected>;

/// Compares every cell of row `r` with the expected value of its column, looked up by the
/// column's name in the header. A column with no expected value fails: adding a column to a
/// CSV means adding its independent value to the test that reads it.
void expect_row(const Csv& csv, std::size_t r, const ExpectedRow& expected) {
  ASSERT_LT(r, csv.rows.size());
  const auto& cells = csv.rows[r];
  ASSERT_EQ(cells.size(), csv.header.size()) << "row " << r;
  for (std::size_t c = 0; c < csv.header.size(); ++c) {
    const std::string& name = csv.header[c];
    const auto it = expected.find(name);
    if (it == expected.end()) {
      ADD_FAILURE() << "column " << name << " has no independent value in this test";
      continue;
    }
    const Expected& e = it->second;
    const std::string& cell = cells[c];
    SCOPED_TRACE("row " + std::to_string(r) + ", column " + name + " = \"" + cell + "\"");
    switch (e.kind) {
      case Expected::Kind::empty:
        EXPECT_TRUE(cell.empty());
        break;
      case Expected::Kind::text:
        EXPECT_EQ(cell, e.text);
        break;
      case Expected::Kind::number: {
        ASSERT_FALSE(cell.empty());
        char* end = nullptr;  // strtod, not stod: a subnormal cell is a number here
        EXPECT_NEAR(std::strtod(cell.c_str(), &end), e.value, e.tolerance);
        EXPECT_EQ(*end, '\0');
        break;
      }
      case Expected::Kind::positive:
        ASSERT_FALSE(cell.empty());
        EXPECT_GT(std::stod(cell), 0.0);
        EXPECT_TRUE(std::isfinite(std::stod(cell)));
        break;
    }
  }
  for (const auto& [name, e] : expected)
    EXPECT_NE(std::find(csv.header.begin(), csv.header.end(), name), csv.header.end())
        << "expected column " << name << " is missing";
}

/// The angle of the rotation aᵀb, by Eigen's axis–angle decomposition.
double angle_between(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  return Eigen::AngleAxisd(a.transpose() * b).angle();
}

/// The rigid body's kinetic energy from the body-frame ω and the principal moments.
double energy_by_hand(const Eigen::Vector3d& moments, const Eigen::Vector3d& omega) {
  return 0.5 * omega.dot(moments.cwiseProduct(omega));
}

/// A run replayed here, `steps` steps of dt with t = n·dt, measured after every step by this
/// test's own bookkeeping: the sign changes of the diagnostics' cos_intermediate_L placed by
/// linear interpolation, the largest |E/E0 − 1| (E from ω and I_body by hand for the rigid
/// models and the engines, the particle model's kinetic plus spring energy) and |L|/|L0| − 1,
/// the first step that is not finite, and the orientation at the end.
struct Replay {
  std::vector<double> flips;
  double energy_drift = 0.0, L_drift = 0.0;
  std::optional<double> diverged_at;
  double t_end = 0.0;
  Eigen::Matrix3d orientation = Eigen::Matrix3d::Identity();
};

double energy_of(const physics::ModelConfig& model, const Eigen::Vector3d& moments,
                 const physics::Diagnostics& d) {
  return model.kind == physics::ModelKind::particle ? d.energy_kinetic + d.energy_potential
                                                    : energy_by_hand(moments, d.omega_body);
}

Replay replay(const physics::Body& body, const physics::ModelConfig& model,
              const physics::InitialState& initial, double dt, long long steps) {
  auto sim = engines::make_model(body, model);
  sim->reset(initial);
  const physics::Diagnostics d0 = sim->diagnostics();
  const double e0 = energy_of(model, body.moments, d0), L0 = d0.L.norm();
  Replay r;
  // Turn-overs (docs/physics.md §14): a sign change of cos(intermediate axis, L) counts once
  // the cosine has gone past 0.5 on the new side; it is placed at the zero crossing.
  double previous_t = 0.0, previous = d0.cos_principal_L[1];
  bool from_positive = previous > 0.0;
  double crossing = 0.0;  // set by the sign change that must come before the margin
  for (long long n = 1; n <= steps; ++n) {
    sim->step(dt);
    const double t = static_cast<double>(n) * dt;
    if (!sim->finite()) {
      r.diverged_at = t;
      break;
    }
    const physics::Diagnostics d = sim->diagnostics();
    r.energy_drift = std::max(r.energy_drift, std::abs(energy_of(model, body.moments, d) / e0 - 1));
    r.L_drift = std::max(r.L_drift, std::abs(d.L.norm() / L0 - 1));
    const double now = d.cos_principal_L[1];
    if (now != 0.0 && previous != 0.0 && (now > 0.0) != (previous > 0.0) &&
        (now > 0.0) != from_positive)
      crossing = previous_t + (t - previous_t) * previous / (previous - now);
    if (from_positive ? now < -0.5 : now > 0.5) {
      r.flips.push_back(crossing);
      from_positive = !from_positive;
    }
    if (now != 0.0) {
      previous = now;
      previous_t = t;
    }
    r.t_end = t;
    r.orientation = sim->orientation();
  }
  return r;
}

/// A scene replayed as a sweep runs it: (frames − 1)·steps_per_frame steps of dt.
Replay replay(const scene::Scene& s) {
  return replay(s.body, s.model, s.initial, s.dt,
                static_cast<long long>(s.frames - 1) * s.steps_per_frame);
}

/// Writes `toml` as `name`.toml under `dir`, sweeps it over `vary` measuring `measures` and
/// reads the CSV back.
Csv sweep(const std::filesystem::path& dir, const std::string& name, const std::string& toml,
          const std::string& vary, const std::string& measures) {
  const auto path = dir / (name + ".toml");
  std::ofstream(path) << toml;
  SweepRequest request;
  request.scene_path = path;
  request.ranges = {parse_vary(vary)};
  request.measures = parse_measures(measures);
  request.jobs = 2;
  std::ofstream csv(dir / (name + "-sweep.csv"));
  write_sweep_csv(measure_sweep(request), csv);
  csv.close();
  return read_csv(dir / (name + "-sweep.csv"));
}

const std::string kAllMeasures =
    "first_flip,flip_period,energy_drift,orientation_error,diverged_at,twist";

// A flipping run (the book spun near its intermediate axis x, 10× the original rate, RK4 at
// a step coarse enough to leave a visible error): the measured flips, drift and orientation
// against this test's replay of the same run, the exact columns against the closed form of
// docs/physics.md §8 (the first zero of sn and 2K(k)/λ from the invariants).
TEST(CsvColumns, SweepRowsOfAFlippingRunMatchTheReplayAndTheClosedForm) {
  test::ScratchDir dir;
  const std::string toml_head =
      "[model]\nkind = \"rigid-quaternion\"\nintegrator = \"rk4\"\nnormalize = true\n"
      "[initial]\njiggle = 0\nangular_velocity = [1.14819, 0.1, 0.0]\n"
      "[time]\ndt = 0.1\nsteps_per_frame = 1\n";
  const physics::Book book;
  const ClosedFormFlips slowest =
      closed_form_flips(book.principal_moments(), Eigen::Vector3d(1.14819, 0.1, 0.0));
  // Three flips or more at every point (a larger ε flips sooner and more often).
  const std::string toml =
      toml_head + "duration = " + std::to_string(slowest.first_flip + 2.5 * slowest.half_period) +
      "\n";
  const Csv csv = sweep(dir.path(), "flipping", toml, "initial.angular_velocity[1]=0.1:0.3:3",
                        "first_flip,flip_period,energy_drift,orientation_error,diverged_at");
  ASSERT_EQ(csv.rows.size(), 3u);
  for (std::size_t r = 0; r < 3; ++r) {
    const double epsilon = 0.1 * static_cast<double>(r + 1);
    const Eigen::Vector3d omega(1.14819, epsilon, 0.0);
    const scene::Scene s = scene::parse_scene_text(
        toml, "flipping.toml",
        {"initial.angular_velocity=[1.14819," + full_precision(epsilon) + ",0]"});
    const Replay run = replay(s);
    ASSERT_GE(run.flips.size(), 3u);
    const ClosedFormFlips exact = closed_form_flips(s.body.moments, omega);
    const Eigen::Matrix3d r_exact =
        physics::ExactRotation(s.body.moments, omega).orientation(run.t_end);
    const double orientation = angle_between(r_exact, run.orientation);
    const double period = (run.flips.back() - run.flips.front()) / (run.flips.size() - 1.0);
    // The step's error is far above the tolerances: measured and exact cells cannot stand in
    // for each other.
    EXPECT_GT(std::abs(run.flips.front() / exact.first_flip - 1.0), 1e-7);
    EXPECT_GT(orientation, 1e-6);
    expect_row(csv, r,
               {{"initial.angular_velocity[1]", near(epsilon, 1e-15)},
                {"first_flip", relative(run.flips.front(), 1e-10)},
                {"flip_period", relative(period, 1e-10)},
                {"energy_drift", near(run.energy_drift, 1e-6 * run.energy_drift + 1e-15)},
                {"orientation_error", near(orientation, 1e-6 * orientation + 1e-12)},
                {"diverged_at", empty()},
                {"first_flip_exact", relative(exact.first_flip, 1e-10)},
                {"flip_period_exact", relative(exact.half_period, 1e-10)},
                {"refused", empty()}});
  }
}

/// x wrapped into (−π, π].
double wrap(double x) {
  x = std::remainder(x, 2 * kPi);
  return x <= -kPi ? x + 2 * kPi : x;
}

// The twist of a symmetric top by hand (docs/physics.md §19): a flat book with a = b has
// moments (I⊥, I⊥, I3); spun at (ω⊥, ω3), L_b circles the z axis with period
// T = 2π I⊥/(|I3 − I⊥| |ω3|), and R(T) turns about L by |L|·T/I⊥, so the twist is that angle
// wrapped into (−π, π].
TEST(CsvColumns, SweepTwistColumnsOfASymmetricTopAreTheHandFormula) {
  test::ScratchDir dir;
  const std::string toml =
      "[model]\nkind = \"exact\"\n[book]\nsize = [2.0, 2.0, 0.5]\n"
      "[initial]\njiggle = 0\nangular_velocity = [0.3, 0.1, 0.5]\n"
      "[time]\ndt = 0.016666666666666666\nsteps_per_frame = 1\nduration = 20\n";
  const Csv csv = sweep(dir.path(), "top", toml, "initial.angular_velocity[2]=0.5:0.6:2", "twist");
  ASSERT_EQ(csv.rows.size(), 2u);
  const scene::Scene s = scene::parse_scene_text(toml, "top.toml");
  const double I_perp = s.body.moments.x(), I3 = s.body.moments.z();
  ASSERT_EQ(s.body.moments.y(), I_perp);
  for (std::size_t r = 0; r < 2; ++r) {
    const double omega3 = 0.5 + 0.1 * static_cast<double>(r);
    const double L = std::hypot(I_perp * std::hypot(0.3, 0.1), I3 * omega3);
    const double period = 2 * kPi * I_perp / (std::abs(I3 - I_perp) * omega3);
    const double twist = wrap(L * period / I_perp);
    EXPECT_GT(std::abs(std::sin(twist)), 0.05);  // no coincidence of a trivial angle
    expect_row(csv, r,
               {{"initial.angular_velocity[2]", near(omega3, 1e-15)},
                {"twist", near(twist, 1e-8)},
                {"twist_exact", near(twist, 1e-9)},
                {"refused", empty()}});
  }
}

/// The sweep row of a spin about z (a steady motion: ω and E constant, no flip, no twist,
/// and no exact column, since it has no finite period) at ω_z = `omega`, with its
/// orientation error and divergence cells.
ExpectedRow steady_spin_row(double omega, const Expected& orientation_error,
                            const Expected& diverged_at) {
  return {{"initial.angular_velocity[2]", near(omega, 1e-15)},
          {"first_flip", empty()},
          {"flip_period", empty()},
          {"energy_drift", near(0.0, 1e-13)},
          {"orientation_error", orientation_error},
          {"diverged_at", diverged_at},
          {"twist", empty()},
          {"first_flip_exact", empty()},
          {"flip_period_exact", empty()},
          {"twist_exact", empty()},
          {"refused", empty()}};
}

/// The book spun about z by the matrix model with Euler steps of `dt`, with or without the
/// polar factor, swept over ω_z = 0.5 and 1 measuring everything.
Csv sweep_z_spin(const std::filesystem::path& dir, bool normalize, double dt, int frames) {
  const std::string toml =
      std::string("[model]\nkind = \"rigid-matrix\"\nintegrator = \"euler\"\n") +
      "normalize = " + (normalize ? "true" : "false") +
      "\n[initial]\njiggle = 0\nangular_velocity = [0, 0, 1]\n[time]\ndt = " + full_precision(dt) +
      "\nsteps_per_frame = 1\nframes = " + std::to_string(frames) + "\n";
  return sweep(dir, "z-spin", toml, "initial.angular_velocity[2]=0.5:1:2", kAllMeasures);
}

// A steady spin about z with the matrix model, Euler and the polar factor: each step turns
// the book by atan(h) for the exact motion's h = ω dt (docs/physics.md §3), so after N steps
// the orientation error is N(h − atan h); ω and E stay constant; no flip, no period, no twist,
// and every exact column is empty (steady motion has no finite period).
TEST(CsvColumns, SweepRowsOfASteadySpinHoldTheEulerLagAndNothingElse) {
  test::ScratchDir dir;
  const Csv csv = sweep_z_spin(dir.path(), true, 0.1, 1001);
  ASSERT_EQ(csv.rows.size(), 2u);
  for (std::size_t r = 0; r < 2; ++r) {
    const double omega = 0.5 * static_cast<double>(r + 1), h = omega * 0.1;
    const double lag = 1000 * (h - std::atan(h));
    expect_row(csv, r, steady_spin_row(omega, near(lag, 1e-9), empty()));
  }
}

// The matrix model without the polar factor on a steady spin about z: R_n = (I + h[e_z]×)ⁿ
// is, in the xy plane, rⁿ times a turn by nφ (r = √(1 + h²), φ = atan h), z untouched, so
// the run diverges at the first step n where an entry, rⁿ·max(|cos nφ|, |sin nφ|), reaches
// the divergence limit 1e6 (docs/physics.md §9): t = n·dt. E = ½ ω² I_z all along (L stays
// along z), and a diverged run has no orientation error.
TEST(CsvColumns, SweepRowsOfADivergingRunDivergeAtTheClosedFormStep) {
  test::ScratchDir dir;
  const Csv csv = sweep_z_spin(dir.path(), false, 1.0, 201);
  ASSERT_EQ(csv.rows.size(), 2u);
  for (std::size_t r = 0; r < 2; ++r) {
    const double h = 0.5 * static_cast<double>(r + 1);
    const double radius = std::sqrt(1 + h * h), phi = std::atan(h);
    int n = 1;
    while (std::pow(radius, n) *
               std::max(std::abs(std::cos(n * phi)), std::abs(std::sin(n * phi))) <
           1e6)
      ++n;
    EXPECT_EQ(n, r == 0 ? 125 : 40);  // the closed form checked once by hand: 2^20 ≥ 1e6 > 2^19
    expect_row(csv, r, steady_spin_row(h, empty(), near(n * 1.0, 0.0)));
  }
}

// A sweep of ODE over time.dt from a subnormal step up (scenes/README.md, "Engine limits"):
// exactly the points below the smallest normal double, found here from the grid's own values,
// are refused, their row saying so with the key and ODE's reason in full (the reason's commas
// quoted, read back whole); every other point ran (a 4-frame spin about z does not diverge).
TEST(CsvColumns, SweepRowsOfPointsTheEngineRefusesSayWhyAndMeasureNothing) {
  test::ScratchDir dir;
  const std::string toml =
      "[model]\nkind = \"ode\"\n[initial]\njiggle = 0\nangular_velocity = [0, 0, 1]\n"
      "[time]\ndt = 0.01\nsteps_per_frame = 1\nframes = 4\n";
  const Csv csv = sweep(dir.path(), "ode-dt", toml, "time.dt=1e-322:1e-300:4:log", "diverged_at");
  ASSERT_EQ(csv.rows.size(), 4u);
  int refused = 0;
  for (std::size_t r = 0; r < 4; ++r) {
    // Log spaced from the start as read: 1e-322 is the subnormal 9.88e-323.
    const double start = std::log10(1e-322);
    const double dt = std::pow(10.0, start + (-300.0 - start) * static_cast<double>(r) / 3.0);
    const bool subnormal = dt < std::numeric_limits<double>::min();
    refused += subnormal;
    const std::string& cell = csv.rows[r].back();
    if (subnormal) {
      // "time.dt: ODE cannot step by a subnormal dt (below DBL_MIN, got <dt>): …", <dt> the
      // point's value (DBL_MIN to the 17 digits that tell it from its neighbours).
      const std::string head =
          "time.dt: ODE cannot step by a subnormal dt (below 2.2250738585072014e-308, got ";
      const std::string tail = "): its quaternion update cannot normalize";
      ASSERT_EQ(cell.rfind(head, 0), 0u) << cell;
      ASSERT_GT(cell.size(), head.size() + tail.size()) << cell;
      EXPECT_EQ(cell.substr(cell.size() - tail.size()), tail) << cell;
      const std::string got = cell.substr(head.size(), cell.size() - head.size() - tail.size());
      EXPECT_NEAR(std::strtod(got.c_str(), nullptr) / dt, 1.0, 1e-9) << got;  // stod: ERANGE
    }
    expect_row(csv, r,
               {{"time.dt", near(dt, 1e-9 * dt + 1e-322)},  // a few subnormal steps
                {"diverged_at", empty()},
                {"refused", subnormal ? text(cell) : empty()}});
  }
  EXPECT_EQ(refused, 2);  // 9.9e-323 and 2.1e-315 refused; 4.6e-308 and 1e-300 ran
}

/// "model integrator", as the accuracy table and the energy CSV name a method.
std::string label_of(const analysis::Method& m) {
  return std::string(physics::to_string(m.kind)) + " " +
         std::string(physics::to_string(m.integrator));
}

/// The largest |E/E0 − 1| (E by hand from ω and I_body) in each window of `per_window` steps
/// of `steps`, as the long-time energy plot takes it; shorter when the run diverges.
std::vector<double> energy_windows(const analysis::AccuracySettings& s, const analysis::Method& m,
                                   double dt, long steps, long per_window) {
  physics::ModelConfig config = s.model;
  config.kind = m.kind;
  config.integrator = m.integrator;
  auto sim = engines::make_model(s.body, config);
  sim->reset(s.initial);
  const double e0 = energy_by_hand(s.body.moments, sim->diagnostics().omega_body);
  std::vector<double> windows;
  double worst = 0.0;
  for (long i = 1; i <= steps; ++i) {
    sim->step(dt);
    if (!sim->finite()) break;
    worst = std::max(
        worst, std::abs(energy_by_hand(s.body.moments, sim->diagnostics().omega_body) / e0 - 1));
    if (i % per_window == 0) {
      windows.push_back(worst);
      worst = 0.0;
    }
  }
  return windows;
}

// `bookspin accuracy` on the book spun near x at 10× the original rate, two flip periods at
// two steps: every row of the accuracy CSV against this test's replay of that method at that
// step (the run's length from the closed-form flip period, the orientation error by
// Eigen::AngleAxisd against the exact R(t), the flips counted here, the exact flips from the
// closed form), and every column of the energy CSV against the windows replayed here.
TEST(CsvColumns, AccuracyAndEnergyCsvRowsMatchTheReplayAndTheClosedForm) {
  test::ScratchDir dir;
  const Eigen::Vector3d omega(1.14819, 0.3, 0.0);
  AccuracyRequest request;
  request.scene = scene::parse_scene_text(
      "[model]\nnormalize = true\n[initial]\njiggle = 0\nangular_velocity = [1.14819, 0.3, 0]\n",
      "accuracy.toml");
  request.flips = 2.0;
  request.dts = {0.05, 0.1};
  const AccuracyReport report = measure_accuracy(request);
  output::write_text_file(dir / "accuracy.csv", csv_text(accuracy_csv(report), "accuracy CSV"));
  output::write_text_file(dir / "energy.csv", csv_text(energy_csv(report), "energy CSV"));
  const scene::Scene& s = request.scene;
  const ClosedFormFlips exact = closed_form_flips(s.body.moments, omega);
  const physics::ExactRotation rotation(s.body.moments, omega);

  const Csv accuracy = read_csv(dir / "accuracy.csv");
  const auto methods = analysis::accuracy_methods();
  ASSERT_EQ(accuracy.rows.size(), methods.size() * request.dts.size());
  std::size_t r = 0;
  int diverged_rows = 0;
  for (const analysis::Method& m : methods) {
    for (double dt : request.dts) {
      SCOPED_TRACE(label_of(m) + " dt " + std::to_string(dt));
      const long steps = std::lround(request.flips * exact.half_period / dt);
      physics::ModelConfig config = s.model;
      config.kind = m.kind;
      config.integrator = m.integrator;
      const Replay run = replay(s.body, config, s.initial, dt, steps);
      const double t_end = static_cast<double>(steps) * dt;
      ExpectedRow row{
          {"model", text(std::string(physics::to_string(m.kind)))},
          {"integrator", text(std::string(physics::to_string(m.integrator)))},
          {"dt", near(dt, 0.0)},
          {"steps", text(std::to_string(steps))},
          {"t_end", relative(t_end, 1e-15)},
          {"energy_drift", near(run.energy_drift, 2e-6 * run.energy_drift + 1e-13)},
          {"L_drift", near(run.L_drift, 2e-6 * run.L_drift + 1e-13)},
          {"ns_per_step", positive()},
          {"diverged", text(run.diverged_at ? "1" : "0")},
          {"flips", text(std::to_string(run.flips.size()))},
      };
      diverged_rows += run.diverged_at ? 1 : 0;
      row["orientation_error_rad"] = empty();
      if (!run.diverged_at) {
        const double angle = angle_between(rotation.orientation(t_end), run.orientation);
        row["orientation_error_rad"] = near(angle, 2e-6 * angle + 1e-14);
      }
      row["flip_period"] = row["flip_period_error"] = empty();
      if (run.flips.size() >= 2) {
        const double period = (run.flips.back() - run.flips.front()) / (run.flips.size() - 1.0);
        const double error = std::abs(period / exact.half_period - 1);
        row["flip_period"] = relative(period, 1e-9);
        row["flip_period_error"] = near(error, 2e-6 * error + 1e-9);
      }
      row["first_flip"] = row["first_flip_error"] = empty();
      if (!run.flips.empty()) {
        const double error = std::abs(run.flips.front() / exact.first_flip - 1);
        row["first_flip"] = relative(run.flips.front(), 1e-9);
        row["first_flip_error"] = near(error, 2e-6 * error + 1e-9);
      }
      int flips_exact = 0;  // zeros of sn at first_flip + k·T/2 up to t_end
      while (exact.first_flip + flips_exact * exact.half_period <= t_end) ++flips_exact;
      row["flips_exact"] = text(std::to_string(flips_exact));
      expect_row(accuracy, r++, row);
    }
  }
  // Not a table of diverged runs: most rows have an orientation error to compare.
  EXPECT_LT(diverged_rows, 6);

  // The energy CSV: t at the end of each of the 400 windows of 100 flip periods at
  // dt = 1/60, and per rigid method the largest |E/E0 − 1| in each window.
  const Csv energy = read_csv(dir / "energy.csv");
  const double dt = 1.0 / 60.0;
  const long steps = std::lround(100 * exact.half_period / dt);
  const long per_window = std::max(1L, steps / 400);
  const std::size_t windows = static_cast<std::size_t>(steps / per_window);
  ASSERT_EQ(energy.rows.size(), windows);
  std::map<std::string, std::vector<double>> replayed;
  const analysis::AccuracySettings settings{s.body, s.initial, s.model, request.flips};
  for (const analysis::Method& m : analysis::rigid_methods())
    replayed[label_of(m)] = energy_windows(settings, m, dt, steps, per_window);
  std::vector<std::size_t> checked;  // every 37th window and the last
  for (std::size_t w = 0; w < windows; w += 37) checked.push_back(w);
  checked.push_back(windows - 1);
  for (std::size_t w : checked) {
    ExpectedRow row{{"t", relative(static_cast<double>((w + 1) * per_window) * dt, 1e-8)}};
    for (const auto& [label, errors] : replayed)
      row[label] = w < errors.size() ? near(errors[w], 2e-6 * errors[w] + 1e-13) : empty();
    expect_row(energy, w, row);
  }
}

/// One diagnostics row computed by hand (docs/physics.md §9) from a state: the matrix M that
/// places the corners, the world L, the rotation R of the pose, the corners at rest and now.
struct HandRow {
  Eigen::Vector3d omega_body, L;
  double energy_kinetic = 0.0, energy_potential = 0.0;
  Eigen::Vector3d cos_axis_L;
  double strain_max = 0.0, orthogonality_error = 0.0, quaternion_norm = 1.0;
  Eigen::Vector3d cos_principal_L;
  Eigen::Quaterniond pose = Eigen::Quaterniond::Identity();
  Eigen::Vector3d center_of_mass = Eigen::Vector3d::Zero();
};

/// The largest |ℓ/ℓ0 − 1| over the 28 corner pairs.
double strain_of(const physics::Corners& now, const physics::Corners& rest) {
  double worst = 0.0;
  for (int i = 0; i < 8; ++i)
    for (int j = i + 1; j < 8; ++j)
      worst = std::max(
          worst,
          std::abs((now.col(i) - now.col(j)).norm() / (rest.col(i) - rest.col(j)).norm() - 1));
  return worst;
}

/// The principal axes by moment, smallest first (the book: y, x, z).
std::array<int, 3> by_moment(const Eigen::Vector3d& moments) {
  std::array<int, 3> order{0, 1, 2};
  std::sort(order.begin(), order.end(), [&](int a, int b) { return moments[a] < moments[b]; });
  return order;
}

/// R(q) by the unit-quaternion formula, not divided by |q|² (docs/physics.md §4).
Eigen::Matrix3d unnormalized_rotation(const Eigen::Quaterniond& q) {
  const double w = q.w(), x = q.x(), y = q.y(), z = q.z();
  Eigen::Matrix3d M;
  M << 1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),  //
      2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),   //
      2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y);
  return M;
}

/// A rigid model's row with corners M·body_corners (M = R(q), perhaps not a rotation):
/// ω_world = M I⁻¹ Mᵀ L, ω_body = Mᵀ ω_world, E = ½ ω_worldᵀ (M I Mᵀ) ω_world, cosines from
/// M's columns, the pose the unit quaternion q/|q|.
HandRow rigid_row(const physics::Book& book, const Eigen::Quaterniond& q,
                  const Eigen::Vector3d& L) {
  const Eigen::Vector3d I = book.principal_moments();
  const Eigen::Matrix3d M = unnormalized_rotation(q);
  HandRow h;
  const Eigen::Vector3d omega_world = M * I.cwiseInverse().asDiagonal() * M.transpose() * L;
  h.omega_body = M.transpose() * omega_world;
  h.L = L;
  h.energy_kinetic = 0.5 * omega_world.dot(M * I.asDiagonal() * M.transpose() * omega_world);
  for (int d = 0; d < 3; ++d) h.cos_axis_L[d] = M.col(d).dot(L) / (M.col(d).norm() * L.norm());
  const auto order = by_moment(I);
  for (int k = 0; k < 3; ++k) h.cos_principal_L[k] = h.cos_axis_L[order[k]];
  h.strain_max = strain_of(M * book.body_corners(), book.body_corners());
  h.orthogonality_error = (M.transpose() * M - Eigen::Matrix3d::Identity()).norm();
  h.quaternion_norm = q.norm();
  h.pose = q.normalized();
  return h;
}

/// The particle book's row from its positions x and velocities v (3×8, particle mass m,
/// springs k between the rest corners): centre c, r = x − c, u = v − v̄, L = Σ m r × u,
/// I(t) = Σ m (|r|² 1 − r rᵀ), R the best-fit rotation of r onto the rest corners (Kabsch),
/// ω_body = Rᵀ I(t)⁻¹ L, E_kin = ½ m Σ |v|², E_pot = Σ ½ k (ℓ − ℓ0)².
HandRow particle_row(const physics::Book& book, const physics::Corners& x,
                     const physics::Corners& v, double k) {
  const double m = book.mass / 8;
  const physics::Corners rest = book.body_corners();
  HandRow h;
  h.center_of_mass = x.rowwise().mean();
  const Eigen::Vector3d v_mean = v.rowwise().mean();
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero(), H = Eigen::Matrix3d::Zero();
  h.L.setZero();
  for (int p = 0; p < 8; ++p) {
    const Eigen::Vector3d r = x.col(p) - h.center_of_mass;
    h.L += m * r.cross(v.col(p) - v_mean);
    inertia += m * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());
    H += r * rest.col(p).transpose();
    h.energy_kinetic += 0.5 * m * v.col(p).squaredNorm();
    for (int q = p + 1; q < 8; ++q) {
      const double stretch = (x.col(p) - x.col(q)).norm() - (rest.col(p) - rest.col(q)).norm();
      h.energy_potential += 0.5 * k * stretch * stretch;
    }
  }
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(H, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d R = svd.matrixU() * svd.matrixV().transpose();
  if (R.determinant() < 0) {
    Eigen::Matrix3d flip = Eigen::Matrix3d::Identity();
    flip(2, 2) = -1;
    R = svd.matrixU() * flip * svd.matrixV().transpose();
  }
  h.omega_body = R.transpose() * inertia.inverse() * h.L;
  for (int d = 0; d < 3; ++d) h.cos_axis_L[d] = R.col(d).dot(h.L) / h.L.norm();
  const auto order = by_moment(book.principal_moments());
  for (int i = 0; i < 3; ++i) h.cos_principal_L[i] = h.cos_axis_L[order[i]];
  h.strain_max = strain_of(x, rest);
  h.orthogonality_error = (R.transpose() * R - Eigen::Matrix3d::Identity()).norm();
  h.pose = Eigen::Quaterniond(R);
  return h;
}

/// The expected cells of a diagnostics row, every number within `tolerance`.
ExpectedRow diagnostics_expected(int frame, double t, const HandRow& h, double tolerance) {
  const Eigen::Quaterniond q = h.pose.w() < 0 ? Eigen::Quaterniond(-h.pose.coeffs()) : h.pose;
  const auto at = [tolerance](double value) { return near(value, tolerance); };
  return {{"frame", text(std::to_string(frame))},
          {"t", relative(t, 1e-15)},
          {"omega_x", at(h.omega_body.x())},
          {"omega_y", at(h.omega_body.y())},
          {"omega_z", at(h.omega_body.z())},
          {"L_x", at(h.L.x())},
          {"L_y", at(h.L.y())},
          {"L_z", at(h.L.z())},
          {"energy_kinetic", at(h.energy_kinetic)},
          {"energy_potential", at(h.energy_potential)},
          {"energy_total", at(h.energy_kinetic + h.energy_potential)},
          {"cos_x_L", at(h.cos_axis_L.x())},
          {"cos_y_L", at(h.cos_axis_L.y())},
          {"cos_z_L", at(h.cos_axis_L.z())},
          {"strain_max", at(h.strain_max)},
          {"orthogonality_error", at(h.orthogonality_error)},
          {"quaternion_norm", at(h.quaternion_norm)},
          {"cos_smallest_L", at(h.cos_principal_L[0])},
          {"cos_intermediate_L", at(h.cos_principal_L[1])},
          {"cos_largest_L", at(h.cos_principal_L[2])},
          {"q_w", at(q.w())},
          {"q_x", at(q.x())},
          {"q_y", at(q.y())},
          {"q_z", at(q.z())},
          {"com_x", at(h.center_of_mass.x())},
          {"com_y", at(h.center_of_mass.y())},
          {"com_z", at(h.center_of_mass.z())}};
}

/// The diagnostics CSV of `s` (the simulate job's rows) read back.
Csv diagnostics_csv(const scene::Scene& s) {
  std::stringstream out;
  write_diagnostics_rows(s, out);
  return read_csv(out);
}

// The quaternion model's diagnostics CSV against the model stepped here by its equations
// (docs/physics.md §4: q ← q + ½dt (0, ω) ⊗ q, ω = R(q) I⁻¹ R(q)ᵀ L), each row computed by
// hand (§9), with and without normalization: without it |q| grows, so R(q) is no rotation
// and the norm, orthogonality and strain columns carry values of their own.
TEST(CsvColumns, DiagnosticsCsvOfTheQuaternionModelIsItsEquationsByHand) {
  for (const bool normalize : {true, false}) {
    SCOPED_TRACE(normalize ? "normalized" : "not normalized");
    const std::string toml =
        std::string("[model]\nkind = \"rigid-quaternion\"\n") +
        "integrator = \"euler\"\nnormalize = " + (normalize ? "true" : "false") +
        "\n[initial]\njiggle = 0\nangular_velocity = [0.3, 0.2, 0.1]\n"
        "[time]\ndt = 0.05\nsteps_per_frame = 3\nframes = 40\n";
    const Csv csv = diagnostics_csv(scene::parse_scene_text(toml, "quaternion.toml"));
    ASSERT_EQ(csv.rows.size(), 40u);
    const physics::Book book;
    const Eigen::Vector3d L = book.principal_moments().cwiseProduct(Eigen::Vector3d(0.3, 0.2, 0.1));
    Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
    for (int frame = 0; frame < 40; ++frame) {
      if (frame > 0) {
        for (int n = 0; n < 3; ++n) {
          const Eigen::Matrix3d M = unnormalized_rotation(q);
          const Eigen::Vector3d omega =
              M * book.principal_moments().cwiseInverse().asDiagonal() * M.transpose() * L;
          q.coeffs() +=
              0.5 * 0.05 * (Eigen::Quaterniond(0.0, omega.x(), omega.y(), omega.z()) * q).coeffs();
          if (normalize) q.normalize();
        }
      }
      const HandRow h = rigid_row(book, q, L);
      if (!normalize && frame == 39) {
        EXPECT_GT(h.quaternion_norm, 1.001);  // the columns of a non-rotation hold real values
        EXPECT_GT(h.strain_max, 1e-3);
        EXPECT_GT(h.orthogonality_error, 1e-4);
      }
      expect_row(csv, static_cast<std::size_t>(frame),
                 diagnostics_expected(frame, frame * 3 * 0.05, h, 1e-12));
    }
  }
}

// The particle book's diagnostics CSV against each frame's positions and velocities, every
// column computed here from them (docs/physics.md §2, §9): the springs' energy, the strain,
// the centre of mass, L about it, the best-fit rotation and ω from I(t).
TEST(CsvColumns, DiagnosticsCsvOfTheParticleModelIsItsStateByHand) {
  const std::string toml =
      "[model]\nkind = \"particle\"\nintegrator = \"euler\"\n"
      "[initial]\njiggle = 0\nangular_velocity = [0.3, 0.2, 0.1]\n"
      "[time]\ndt = 0.02\nsteps_per_frame = 5\nframes = 30\n";
  const scene::Scene s = scene::parse_scene_text(toml, "particle.toml");
  const Csv csv = diagnostics_csv(s);
  ASSERT_EQ(csv.rows.size(), 30u);
  auto sim = engines::make_model(s.body, s.model);
  sim->reset(s.initial);
  const auto& particles = dynamic_cast<const physics::ParticleModel&>(*sim);
  for (int frame = 0; frame < 30; ++frame) {
    if (frame > 0)
      for (int n = 0; n < 5; ++n) sim->step(0.02);
    const HandRow h = particle_row(s.body.cage, particles.corners(), particles.velocities(),
                                   s.model.spring_constant);
    if (frame == 29) {
      EXPECT_GT(h.energy_potential, 1e-8);  // the springs stretch: their columns are not 0
      EXPECT_GT(h.strain_max, 1e-6);
    }
    expect_row(csv, static_cast<std::size_t>(frame),
               diagnostics_expected(frame, frame * 5 * 0.02, h, 1e-10));
  }
}

}  // namespace
}  // namespace bookspin::jobs
