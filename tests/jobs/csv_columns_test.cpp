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
#include <cmath>
#include <fstream>
#include <map>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "engines/models.hpp"
#include "jobs/closed_form_flips.hpp"
#include "jobs/sweep.hpp"
#include "physics/exact_solution.hpp"
#include "scene/scene.hpp"
#include "support/scratch.hpp"

namespace bookspin::jobs {
namespace {

constexpr double kPi = std::numbers::pi;

/// A CSV file read back as text cells.
struct Csv {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
};

std::vector<std::string> split_cells(const std::string& line) {
  std::vector<std::string> cells;
  std::size_t start = 0;
  for (std::size_t comma; (comma = line.find(',', start)) != std::string::npos; start = comma + 1)
    cells.push_back(line.substr(start, comma - start));
  cells.push_back(line.substr(start));
  return cells;
}

Csv read_csv(const std::filesystem::path& path) {
  std::ifstream in(path);
  Csv csv;
  std::string line;
  if (std::getline(in, line)) csv.header = split_cells(line);
  while (std::getline(in, line)) csv.rows.push_back(split_cells(line));
  return csv;
}

/// What one cell must hold: a number within a tolerance, an empty cell, or a text.
struct Expected {
  enum class Kind { number, empty, text } kind = Kind::empty;
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

/// The expected cells of one row, by column name.
using ExpectedRow = std::map<std::string, Expected>;

/// Compares every cell of `row` with the expected value of its column, looked up by the
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
      case Expected::Kind::number:
        ASSERT_FALSE(cell.empty());
        EXPECT_NEAR(std::stod(cell), e.value, e.tolerance);
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

/// A scene's run replayed here as a sweep runs it, (frames − 1)·steps_per_frame steps of dt
/// with t = n·dt, measured after every step by this test's own bookkeeping: the sign changes
/// of ω about the intermediate axis (the middle moment, sorted here) placed by linear
/// interpolation, the largest |E/E0 − 1| with E from ω and I_body, the first step that is not
/// finite, and the orientation at the end.
struct Replay {
  std::vector<double> flips;
  double energy_drift = 0.0;
  std::optional<double> diverged_at;
  double t_end = 0.0;
  Eigen::Matrix3d orientation = Eigen::Matrix3d::Identity();
};

Replay replay(const scene::Scene& s) {
  const Eigen::Vector3d& I = s.body.moments;
  int mid = 0;  // the axis whose moment lies between the two others
  for (int d = 0; d < 3; ++d)
    if ((I[d] - I[(d + 1) % 3]) * (I[d] - I[(d + 2) % 3]) <= 0.0) mid = d;
  auto sim = engines::make_model(s.body, s.model);
  sim->reset(s.initial);
  const double e0 = energy_by_hand(I, sim->diagnostics().omega_body);
  Replay r;
  double previous_t = 0.0, previous = sim->diagnostics().omega_body[mid];
  const long long steps = static_cast<long long>(s.frames - 1) * s.steps_per_frame;
  for (long long n = 1; n <= steps; ++n) {
    sim->step(s.dt);
    const double t = static_cast<double>(n) * s.dt;
    if (!sim->finite()) {
      r.diverged_at = t;
      break;
    }
    const physics::Diagnostics d = sim->diagnostics();
    r.energy_drift = std::max(r.energy_drift, std::abs(energy_by_hand(I, d.omega_body) / e0 - 1));
    const double now = d.omega_body[mid];
    if (now != 0.0 && previous != 0.0 && (now > 0.0) != (previous > 0.0))
      r.flips.push_back(previous_t + (t - previous_t) * previous / (previous - now));
    if (now != 0.0) {
      previous = now;
      previous_t = t;
    }
    r.t_end = t;
    r.orientation = sim->orientation();
  }
  return r;
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
  request.layout = [dir](const std::string& scene_name) {
    return SweepPaths{dir / (scene_name + "-sweep.csv"), dir / (scene_name + "-sweep.png"), {}};
  };
  const SweepResult result = run_sweep(request);
  EXPECT_EQ(result.written.size(), 2u);
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
                {"flip_period_exact", relative(exact.half_period, 1e-10)}});
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
                {"twist_exact", near(twist, 1e-9)}});
  }
}

// A steady spin about z with the matrix model, Euler and the polar factor: each step turns
// the book by atan(h) for the exact motion's h = ω dt (docs/physics.md §3), so after N steps
// the orientation error is N(h − atan h); ω and E stay constant; no flip, no period, no twist,
// and every exact column is empty (steady motion has no finite period).
TEST(CsvColumns, SweepRowsOfASteadySpinHoldTheEulerLagAndNothingElse) {
  test::ScratchDir dir;
  const std::string toml =
      "[model]\nkind = \"rigid-matrix\"\nintegrator = \"euler\"\nnormalize = true\n"
      "[initial]\njiggle = 0\nangular_velocity = [0, 0, 1]\n"
      "[time]\ndt = 0.1\nsteps_per_frame = 1\nframes = 1001\n";
  const Csv csv =
      sweep(dir.path(), "steady", toml, "initial.angular_velocity[2]=0.5:1:2", kAllMeasures);
  ASSERT_EQ(csv.rows.size(), 2u);
  for (std::size_t r = 0; r < 2; ++r) {
    const double omega = 0.5 * static_cast<double>(r + 1), h = omega * 0.1;
    const double lag = 1000 * (h - std::atan(h));
    expect_row(csv, r,
               {{"initial.angular_velocity[2]", near(omega, 1e-15)},
                {"first_flip", empty()},
                {"flip_period", empty()},
                {"energy_drift", near(0.0, 1e-13)},
                {"orientation_error", near(lag, 1e-9)},
                {"diverged_at", empty()},
                {"twist", empty()},
                {"first_flip_exact", empty()},
                {"flip_period_exact", empty()},
                {"twist_exact", empty()}});
  }
}

// The matrix model without the polar factor on a steady spin about z: R_n = (I + h[e_z]×)ⁿ
// is, in the xy plane, rⁿ times a turn by nφ (r = √(1 + h²), φ = atan h), z untouched, so
// the run diverges at the first step n where an entry, rⁿ·max(|cos nφ|, |sin nφ|), reaches
// the divergence limit 1e6 (docs/physics.md §9): t = n·dt. E = ½ ω² I_z all along (L stays
// along z), and a diverged run has no orientation error.
TEST(CsvColumns, SweepRowsOfADivergingRunDivergeAtTheClosedFormStep) {
  test::ScratchDir dir;
  const std::string toml =
      "[model]\nkind = \"rigid-matrix\"\nintegrator = \"euler\"\nnormalize = false\n"
      "[initial]\njiggle = 0\nangular_velocity = [0, 0, 1]\n"
      "[time]\ndt = 1\nsteps_per_frame = 1\nframes = 201\n";
  const Csv csv =
      sweep(dir.path(), "growing", toml, "initial.angular_velocity[2]=0.5:1:2", kAllMeasures);
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
    expect_row(csv, r,
               {{"initial.angular_velocity[2]", near(h, 1e-15)},
                {"first_flip", empty()},
                {"flip_period", empty()},
                {"energy_drift", near(0.0, 1e-13)},
                {"orientation_error", empty()},
                {"diverged_at", near(n * 1.0, 0.0)},
                {"twist", empty()},
                {"first_flip_exact", empty()},
                {"flip_period_exact", empty()},
                {"twist_exact", empty()}});
  }
}

}  // namespace
}  // namespace bookspin::jobs
