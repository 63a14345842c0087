// `bookspin simulate`: CSV format, determinism and errors (docs/physics.md §9).
#include <gtest/gtest.h>

#include <sstream>

#include "support/cli_runner.hpp"
#include "support/flip_timer.hpp"

namespace bookspin::cli {
namespace {

using namespace bookspin::test;  // the shared runner (tests/support)

constexpr const char* kHeader =
    "frame,t,omega_x,omega_y,omega_z,L_x,L_y,L_z,energy_kinetic,energy_potential,energy_total,"
    "cos_x_L,cos_y_L,cos_z_L,strain_max,orthogonality_error,quaternion_norm,"
    "cos_smallest_L,cos_intermediate_L,cos_largest_L,q_w,q_x,q_y,q_z,com_x,com_y,com_z";

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

TEST(SimulateCommand, WritesOneRowPerFrameWithTheDocumentedColumns) {
  const auto dir = fresh_dir("simulate_rows");
  const auto csv = dir / "out.csv";
  const CliResult r = run_bookspin("simulate " + scene_path("fig09-matrix-unstable-x") +
                                   " --set time.frames=25 --csv " + csv.string());
  ASSERT_EQ(r.status, 0) << r.output;
  const auto lines = lines_of(read_file(csv));
  ASSERT_EQ(lines.size(), 26u);
  EXPECT_EQ(lines[0], kHeader);
  EXPECT_EQ(lines[1].rfind("0,0,", 0), 0u) << lines[1];  // frame 0 is the initial state
  // frame n holds the state after n × steps_per_frame steps: t = 24 × 30 / 60.
  EXPECT_EQ(lines[25].rfind("24,12,", 0), 0u) << lines[25];
}

TEST(SimulateCommand, SameSceneAndSeedGiveBitIdenticalCsv) {
  const auto dir = fresh_dir("simulate_determinism");
  for (const char* scene : {"fig05-particle-unstable-x", "fig09-matrix-unstable-x",
                            "fig11-quaternion-no-normalization"}) {
    const std::string base = "simulate " + scene_path(scene) + " --set time.frames=200 --csv ";
    ASSERT_EQ(run_bookspin(base + (dir / "a.csv").string()).status, 0);
    ASSERT_EQ(run_bookspin(base + (dir / "b.csv").string()).status, 0);
    const std::string a = read_file(dir / "a.csv");
    EXPECT_GT(a.size(), 10000u);
    EXPECT_EQ(a, read_file(dir / "b.csv")) << scene;
  }
}

TEST(SimulateCommand, DifferentSeedGivesDifferentJiggle) {
  const auto dir = fresh_dir("simulate_seed");
  const std::string base =
      "simulate " + scene_path("fig09-matrix-unstable-x") + " --set time.frames=5 --csv ";
  ASSERT_EQ(run_bookspin(base + (dir / "a.csv").string()).status, 0);
  ASSERT_EQ(run_bookspin(base + (dir / "b.csv").string() + " --set initial.seed=99").status, 0);
  EXPECT_NE(read_file(dir / "a.csv"), read_file(dir / "b.csv"));
}

TEST(SimulateCommand, DivergenceKeepsTheRowsSoFarAndWarns) {
  const auto dir = fresh_dir("simulate_diverge");
  const auto csv = dir / "out.csv";
  const CliResult r =
      run_bookspin("simulate " + scene_path("fig08-particle-neither") + " --csv " + csv.string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("diverged at t = "), std::string::npos) << r.output;
  const auto lines = lines_of(read_file(csv));
  EXPECT_GT(lines.size(), 100u);
  EXPECT_LT(lines.size(), 451u);
  EXPECT_EQ(lines.back().find("nan"), std::string::npos);
  EXPECT_EQ(lines.back().find("inf"), std::string::npos);
}

TEST(SimulateCommand, ImplicitMidpointThatCannotConvergeStopsWithItsReason) {
  // dt = 20 time units turns the book by more than a radian per step: the fixed-point
  // iteration of the implicit midpoint rule cannot converge, and the run must say so.
  const auto csv = fresh_dir("simulate-midpoint") / "out.csv";
  const CliResult r = run_bookspin("simulate " + scene_path("exact-unstable-x") +
                                   " --set 'model.kind=\"rigid-matrix\"'"
                                   " --set 'model.integrator=\"implicit-midpoint\"'"
                                   " --set time.dt=20 --csv " +
                                   csv.string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("simulation diverged at t = 20; implicit midpoint:"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("did not converge"), std::string::npos) << r.output;
  EXPECT_EQ(lines_of(read_file(csv)).size(), 2u);  // the header and the initial state
}

TEST(SimulateCommand, HelpDocumentsEveryOption) {
  const CliResult r = run_bookspin("simulate --help");
  ASSERT_EQ(r.status, 0);
  for (const char* word : {"SCENE", "--set", "--csv", "--help"})
    EXPECT_NE(r.output.find(word), std::string::npos) << word;
}

struct BadInput {
  std::string label;  ///< test name
  std::string args;
  std::string expected;  ///< a fragment of the one-line message
};
// gtest prints parameters into the names ctest registers; print a stable text, not bytes.
[[maybe_unused]] void PrintTo(const BadInput& p, std::ostream* out) { *out << p.label; }

class SimulateErrors : public ::testing::TestWithParam<BadInput> {};

TEST_P(SimulateErrors, ExitTwoWithOneLineNamingTheProblem) {
  const CliResult r = run_bookspin("simulate " + GetParam().args + " --csv /dev/null");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  EXPECT_NE(r.output.find(GetParam().expected), std::string::npos) << r.output;
}

// One case a line: test name | arguments after `simulate` ({FIG05} = the fig05 scene) |
// a fragment of the one-line message.
constexpr const char* kBadInputs = R"(
negative_dt     | {FIG05} --set time.dt=-1            | --set time.dt: must be > 0
nan_dt          | {FIG05} --set time.dt=nan           | --set time.dt: must be finite
beyond_dt       | {FIG05} --set time.dt=2e308         | --set time.dt: "2e308" is beyond the largest finite number (about 1.8e308)
beyond_neg_dt   | {FIG05} --set time.dt=-2e308        | --set time.dt: "-2e308" is beyond the largest finite number (about 1.8e308)
below_dt        | {FIG05} --set time.dt=1e-400        | --set time.dt: "1e-400" is below the smallest positive number (about 4.9e-324): it would read as 0
unquoted_string | {FIG05} --set model.kind=particle   | --set model.kind: value is not valid TOML
unknown_model   | {FIG05} --set 'model.kind="soft"'   | --set model.kind: unknown model 'soft'
unknown_key     | {FIG05} --set model.colour=1        | --set model.colour: unknown key
short_array     | {FIG05} --set book.size=[1,2]       | --set book.size: expected an array of 3 numbers
float_frames    | {FIG05} --set time.frames=1.5       | --set time.frames: expected an integer
no_equals       | {FIG05} --set nonsense              | --set nonsense: expected key=value
missing_file    | /no/such/scene.toml                 | /no/such/scene.toml: scene file not found
no_scene        |                                     | SCENE is required
unknown_flag    | {FIG05} --bogus                     | --bogus
)";

std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(' ');
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(' ') - first + 1);
}

std::vector<BadInput> bad_inputs() {
  std::vector<BadInput> cases;
  std::istringstream table(kBadInputs);
  for (std::string line; std::getline(table, line);) {
    if (line.empty()) continue;
    const auto bar1 = line.find('|'), bar2 = line.find('|', bar1 + 1);
    std::string args = trimmed(line.substr(bar1 + 1, bar2 - bar1 - 1));
    if (const auto at = args.find("{FIG05}"); at != std::string::npos)
      args.replace(at, 7, scene_path("fig05-particle-unstable-x"));
    cases.push_back({trimmed(line.substr(0, bar1)), args, trimmed(line.substr(bar2 + 1))});
  }
  return cases;
}

TEST(SimulateErrors, TheTableParsesIntoEveryCase) {
  const auto cases = bad_inputs();
  ASSERT_EQ(cases.size(), 14u);
  EXPECT_EQ(cases.front().label, "negative_dt");
  EXPECT_EQ(cases.front().args, scene_path("fig05-particle-unstable-x") + " --set time.dt=-1");
  EXPECT_EQ(cases[12].args, "");  // no_scene
}

INSTANTIATE_TEST_SUITE_P(BadSetValues, SimulateErrors, ::testing::ValuesIn(bad_inputs()),
                         [](const auto& info) { return info.param.label; });

/// The values of one column of a CSV with a header.
std::vector<double> column(const std::string& csv, const std::string& name) {
  const auto lines = lines_of(csv);
  std::vector<double> values;
  if (lines.empty()) return values;
  int index = -1, at = 0;
  std::istringstream header(lines[0]);
  for (std::string field; std::getline(header, field, ','); ++at)
    if (field == name) index = at;
  for (std::size_t row = 1; row < lines.size() && index >= 0; ++row) {
    std::istringstream in(lines[row]);
    std::string field;
    for (int k = 0; k <= index; ++k) std::getline(in, field, ',');
    values.push_back(std::stod(field));
  }
  return values;
}

TEST(SimulateCommand, TheTHandleFlipsAgainAndAgain) {
  // Spun about its intermediate axis, the T-handle turns over every half period: the
  // intermediate axis reverses against L (docs/physics.md §12) at least four times in its scene.
  const auto dir = fresh_dir("simulate_t_handle");
  const CliResult r = run_bookspin("simulate " + scene_path("t-handle-dzhanibekov") + " --csv " +
                                   (dir / "t.csv").string());
  ASSERT_EQ(r.status, 0) << r.output;
  const auto c = column(read_file(dir / "t.csv"), "cos_intermediate_L");
  ASSERT_GT(c.size(), 100u);
  test::FlipTimer timer;
  for (std::size_t i = 0; i < c.size(); ++i) timer.sample(static_cast<double>(i), c[i]);
  EXPECT_GE(timer.count(), 4u);
}

TEST(SimulateCommand, ALatticeRunPrintsItsInertiaNextToTheBodys) {
  const auto dir = fresh_dir("simulate_lattice_note");
  const CliResult r = run_bookspin(
      "simulate " + scene_path("t-handle-dzhanibekov") +
      " --set model.kind='\"particle\"' --set model.lattice_cells=6 --set time.frames=2 --csv " +
      (dir / "t.csv").string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("lattice: 6 cells along the longest side, "), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find(" against the body's 0.209"), std::string::npos) << r.output;
  // The book is one cell: no lattice line.
  const CliResult book = run_bookspin("simulate " + scene_path("fig05-particle-unstable-x") +
                                      " --set time.frames=2 --csv " + (dir / "b.csv").string());
  ASSERT_EQ(book.status, 0) << book.output;
  EXPECT_EQ(book.output.find("lattice:"), std::string::npos) << book.output;
}

}  // namespace
}  // namespace bookspin::cli
