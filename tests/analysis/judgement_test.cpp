// The judge judges the whole motion (docs/flipcheck.md, "What judge measures"): the orientation
// at every row (the largest error, with its row) and the direction of L in the world, not only
// |L| and the last row; rows too far apart to show the exact motion's turn-overs are refused,
// never judged "0 turn-overs"; and a scenario no judgement can be made of is refused by field.
#include "analysis/judgement.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "analysis/conformance.hpp"
#include "common/errors.hpp"
#include "physics/exact_solution.hpp"
#include "scene/scene.hpp"
#include "support/scenario_rows.hpp"

namespace bookspin::analysis {
namespace {

constexpr double kPi = std::numbers::pi;

using scenario_rows::exact_rows;
using scenario_rows::scenario;

bool has_failure(const Conformance& c, const std::string& start) {
  for (const std::string& f : c.failures)
    if (f.rfind(start, 0) == 0) return true;
  return false;
}

// A visibly wrong motion: every row between the first and the last turned 90° about the world z
// axis. Its energy and |L| are the exact ones to round-off and so is its last row, but the body
// points elsewhere all along and its L (along world x) is turned to y: it fails on both, each
// at its row.
TEST(Judgement, TheExactMotionTurnedBetweenItsEndsFailsOnOrientationAndLsDirection) {
  const Scenario s = scenario("book-intermediate-0.05");
  std::vector<MotionSample> rows = exact_rows(s, 1);
  const Eigen::Quaterniond turn(Eigen::AngleAxisd(kPi / 2, Eigen::Vector3d::UnitZ()));
  for (std::size_t i = 1; i + 1 < rows.size(); ++i) rows[i].q = turn * rows[i].q;
  const Conformance c = judge_motion(s, rows);
  EXPECT_FALSE(c.pass());
  EXPECT_LT(c.energy_drift, 1e-13);
  EXPECT_LT(c.L_drift, 1e-13);
  EXPECT_NEAR(c.orientation_error, kPi / 2, 1e-9);
  EXPECT_GT(c.orientation_error_step, 0);
  EXPECT_LT(c.orientation_error_step, s.steps);
  EXPECT_NEAR(c.L_direction_error, kPi / 2, 1e-6);
  EXPECT_TRUE(has_failure(c, "orientation error 1.57 rad at step ")) << verdict_line(c);
  EXPECT_TRUE(has_failure(c, "L turned 1.57 rad at step ")) << verdict_line(c);
}

// q's order (docs/flipcheck.md, "What judge measures"): the exact motion written as common
// engines write q, its columns qw, qx, qy, qz holding x, y, z, w, is told so first, before ω:
// read so, q(0) = (0, 0, 0, 1) is a half turn from the scenario's identity, and ω given in the
// world frame is read into the body frame through that q (motion_csv.hpp), so ω(0) is off too
// ("starts 2 off the scenario's omega0" was its first words, 46 turn-overs against 6). Planted
// back (no q line, or it after ω's), this fails.
TEST(Judgement, AQuaternionWrittenXyzwIsNamedSoBeforeAnyOmegaComplaint) {
  const Scenario s = scenario("book-intermediate-0.05");
  std::vector<MotionSample> rows = exact_rows(s, 1);
  for (MotionSample& row : rows) {
    const Eigen::Quaterniond q = row.q;
    const Eigen::Vector3d omega_world = q * row.omega_body;
    row.q = Eigen::Quaterniond(q.x(), q.y(), q.z(), q.w());  // the columns as written
    row.omega_body = row.q.normalized().conjugate() * omega_world;
  }
  const Conformance c = judge_motion(s, rows);
  ASSERT_FALSE(c.pass());
  EXPECT_TRUE(c.q_written_xyzw);
  EXPECT_NEAR(c.start_orientation_error, kPi, 1e-12);
  EXPECT_EQ(c.failures.front(),
            "q is written x, y, z, w: bookspin reads w, x, y, z (columns qw, qx, qy, qz), so q "
            "at step 0 reads (0, 0, 0, 1), 3.14 rad from the scenario's orientation (1, 0, 0, "
            "0); read as x, y, z, w, q is the exact motion's within 0.1 rad at every row")
      << verdict_line(c);
  EXPECT_TRUE(has_failure(c, "starts ")) << verdict_line(c);
}

// A q(0) turned away from the scenario's orientation, in no order of its components the exact
// motion's: the whole motion turned a quarter about body x. Told first, by its components and
// its angle; not called x, y, z, w. The exact motion itself has no such line. Planted back (no
// q line), this fails.
TEST(Judgement, AStartTurnedFromTheScenariosOrientationIsToldFirst) {
  const Scenario s = scenario("book-intermediate-0.05");
  std::vector<MotionSample> rows = exact_rows(s, 1);
  EXPECT_TRUE(judge_motion(s, rows).pass());
  const Eigen::Quaterniond turn(Eigen::AngleAxisd(kPi / 2, Eigen::Vector3d::UnitX()));
  for (MotionSample& row : rows) row.q = row.q * turn;
  const Conformance c = judge_motion(s, rows);
  ASSERT_FALSE(c.pass());
  EXPECT_FALSE(c.q_written_xyzw);
  EXPECT_EQ(c.failures.front(),
            "q at step 0 is (0.707, 0.707, 0, 0), 1.57 rad from the scenario's orientation (1, "
            "0, 0, 0) (limit 0.1 rad)")
      << verdict_line(c);
}

// A failure names where it starts and where it is worst: the exact motion with every row from
// step 1000 on turned about world z by an angle growing from 0.2 rad (past the orientation
// limit 0.1 and L's 0.01 at once) to 0.2 + 1e-3·2000 rad at the last step, 3000: each failure
// is worst at 3000 and starts at 1000 (it named the worst step alone). Energy drift and |L| drift
// are kept: neither is named. Planted back (the first step taken as the worst), this fails.
TEST(Judgement, AFailureNamesTheStepItStartsAndTheStepItIsWorst) {
  const Scenario s = scenario("book-intermediate-0.05");
  std::vector<MotionSample> rows = exact_rows(s, 1);
  ASSERT_EQ(rows.back().step, 3000);
  for (std::size_t n = 1000; n < rows.size(); ++n) {
    const double angle = 0.2 + 1e-3 * static_cast<double>(n - 1000);
    rows[n].q = Eigen::Quaterniond(Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ())) * rows[n].q;
  }
  const Conformance c = judge_motion(s, rows);
  EXPECT_FALSE(c.pass());
  EXPECT_EQ(c.orientation_past, 1000);
  EXPECT_EQ(c.L_direction_past, 1000);
  EXPECT_EQ(c.orientation_error_step, 3000);
  EXPECT_FALSE(c.energy_drift_past.has_value());
  EXPECT_TRUE(has_failure(c,
                          "orientation error 2.2 rad at step 3000 (limit 0.1; past it from "
                          "step 1000)"))
      << verdict_line(c);
  EXPECT_TRUE(has_failure(c, "L turned ")) << verdict_line(c);
  for (const std::string& f : c.failures) {
    if (f.rfind("L turned", 0) == 0) {
      EXPECT_NE(f.find("(limit 0.01; past it from step 1000)"), std::string::npos) << f;
    }
  }
  // Energy drifting from its first step on, worst at the last: both named.
  std::vector<MotionSample> gaining = exact_rows(s, 1);
  for (MotionSample& row : gaining) row.omega_body *= 1.0 + 1e-5 * static_cast<double>(row.step);
  const Conformance e = judge_motion(s, gaining);
  EXPECT_EQ(e.energy_drift_step, 3000);
  ASSERT_TRUE(e.energy_drift_past.has_value());
  EXPECT_GT(*e.energy_drift_past, 400);
  EXPECT_LT(*e.energy_drift_past, 600);  // (1 + 1e-5 n)² − 1 passes 0.01 at n ≈ 499
  EXPECT_TRUE(has_failure(e, "energy drift 0.0609 at step 3000 (limit 0.01; past it from step "))
      << verdict_line(e);
}

// An engine whose body stops turning over after its first turn-over (each row from then on
// the row just after it: E and |L| kept) counts one of the exact motion's six, said in the
// singular: "1 turn-over, exact 6", not "1 turn-overs".
TEST(Judgement, ACountOfOneTurnOverIsSaidInTheSingular) {
  const Scenario s = scenario("book-intermediate-0.05");
  std::vector<MotionSample> rows = exact_rows(s, 1);
  const Conformance exact = judge_motion(s, rows);
  ASSERT_TRUE(exact.first_flip.has_value());
  ASSERT_EQ(exact.flips_exact, 6);
  const auto after = static_cast<std::size_t>(*exact.first_flip / s.dt) + 50;
  for (std::size_t n = after + 1; n < rows.size(); ++n) {
    rows[n].q = rows[after].q;
    rows[n].omega_body = rows[after].omega_body;
  }
  const Conformance c = judge_motion(s, rows);
  EXPECT_EQ(c.flips, 1);
  EXPECT_TRUE(has_failure(c, "1 turn-over, exact 6")) << verdict_line(c);
}

// One middle row turned by θ about L itself: L keeps its direction, the body does not. The
// orientation is judged at every row, so the largest error is θ, at that row.
TEST(Judgement, OneMiddleRowTurnedAboutLIsTheLargestOrientationErrorAtItsRow) {
  const Scenario s = scenario("mujoco-test-box");
  const Eigen::Vector3d L_axis = s.body.moments.cwiseProduct(start_omega(s)).normalized();
  for (const double theta : {0.05, 0.3}) {
    std::vector<MotionSample> rows = exact_rows(s, 1);
    rows[217].q = Eigen::Quaterniond(Eigen::AngleAxisd(theta, L_axis)) * rows[217].q;
    const Conformance c = judge_motion(s, rows);
    EXPECT_NEAR(c.orientation_error, theta, 1e-12);
    EXPECT_EQ(c.orientation_error_step, 217);
    EXPECT_LT(c.L_direction_error, 1e-12);
    EXPECT_EQ(c.pass(), theta <= 0.1) << verdict_line(c);
  }
}

// An engine that precesses L: every row turned about the world z axis by ε·t/t_end, so that L
// (along world x here) turns by up to ε while |L|, E and the turn-overs stay exact. ε = 0.02
// rad keeps the orientation within its 0.1 rad, and fails L's direction (0.01 rad); ε = 0.005
// passes both.
TEST(Judgement, AnEngineThatPrecessesLFailsOnLsDirectionAlone) {
  const Scenario s = scenario("book-intermediate-0.05");
  for (const double epsilon : {0.005, 0.02}) {
    std::vector<MotionSample> rows = exact_rows(s, 1);
    for (MotionSample& row : rows) {
      const double angle = epsilon * static_cast<double>(row.step) / static_cast<double>(s.steps);
      row.q = Eigen::Quaterniond(Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ())) * row.q;
    }
    const Conformance c = judge_motion(s, rows);
    SCOPED_TRACE(verdict_line(c));
    EXPECT_NEAR(c.L_direction_error, epsilon, 1e-3 * epsilon);
    EXPECT_EQ(c.L_direction_error_step, s.steps);
    EXPECT_LT(c.L_drift, 1e-13);
    EXPECT_EQ(c.flips, c.flips_exact);
    EXPECT_LE(c.orientation_error, 0.1);
    EXPECT_EQ(c.pass(), epsilon < 0.01);
    EXPECT_EQ(has_failure(c, "L turned "), epsilon > 0.01);
  }
}

// The exact motion written every 1000th step (4 rows) cannot show its 6 turn-overs: refused
// with that reason and a stride that shows them, never judged "0 turn-overs"; rows at that
// stride pass.
TEST(Judgement, RowsTooFarApartToShowTheTurnOversAreRefusedNamingAStrideThatShowsThem) {
  const Scenario s = scenario("book-intermediate-0.05");
  try {
    const Conformance c = judge_motion(s, exact_rows(s, 1000));
    ADD_FAILURE() << "judged: " << verdict_line(c);
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("rows every 1000 steps (50 time units) are too far apart to judge the "
                         "turn-overs: the exact motion at these rows shows ",
                         0),
              0u)
        << what;
    const std::size_t at = what.find("write a row at least every ");
    ASSERT_NE(at, std::string::npos) << what;
    const long long fine = std::stoll(what.substr(at + 27));
    ASSERT_GE(fine, 1);
    ASSERT_LT(fine, 1000);
    // A stride that divides the steps at or below the one named passes.
    long long stride = fine;
    while (s.steps % stride != 0) --stride;
    const Conformance c = judge_motion(s, exact_rows(s, stride));
    EXPECT_TRUE(c.pass()) << stride << ": " << verdict_line(c);
    EXPECT_EQ(c.flips, 6);
  }
  // A stable spin has no turn-over to miss: its coarse rows are judged.
  const Scenario spin = scenario("book-largest-axis");
  EXPECT_TRUE(judge_motion(spin, exact_rows(spin, 10000)).pass());
}

/// The scenario with one field changed by `edit`, checked: the refusal's text, "" for none.
template <typename Edit>
std::string refusal(Edit edit) {
  Scenario s = scenario("mujoco-test-box");
  edit(s);
  try {
    check_scenario(s);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// Every field is honoured or refused by name: a step count the exact motion cannot carry
// (10^12 gave "exact -2147483647 turn-overs"), an ω0 of 1e200 or a dt of 1e300 (rows of NaN),
// a moment or a mass that is not finite and positive, a body at rest.
TEST(Judgement, AScenarioNoJudgementCanBeMadeOfIsRefusedNamingItsField) {
  EXPECT_EQ(refusal([](Scenario&) {}), "");
  const auto starts = [](const std::string& text, const std::string& start) {
    return text.rfind(start, 0) == 0;
  };
  EXPECT_PRED2(starts, refusal([](Scenario& s) { s.steps = 1'000'000'000'000; }),
               "mujoco-test-box: steps: 1000000000000: must be from 1 to 10^7");
  EXPECT_PRED2(starts, refusal([](Scenario& s) { s.steps = 0; }), "mujoco-test-box: steps: 0");
  EXPECT_PRED2(starts, refusal([](Scenario& s) {
                 s.initial.omega0_body = {1e200, 2, 3};
               }),
               "mujoco-test-box: omega0_body[0]: 1e+200 is beyond ±1e6");
  EXPECT_PRED2(starts, refusal([](Scenario& s) {
                 s.initial.omega0_body = {-2e6, 2, 3};
               }),
               "mujoco-test-box: omega0_body[0]: -2e+06 is beyond ±1e6");
  EXPECT_PRED2(starts, refusal([](Scenario& s) { s.dt = 1e300; }),
               "mujoco-test-box: dt: 1e+300 over 500 steps turns the body by");
  EXPECT_PRED2(starts, refusal([](Scenario& s) { s.dt = -0.01; }), "mujoco-test-box: dt: -0.01");
  EXPECT_PRED2(starts,
               refusal([](Scenario& s) { s.dt = std::numeric_limits<double>::quiet_NaN(); }),
               "mujoco-test-box: dt: nan");
  EXPECT_PRED2(starts, refusal([](Scenario& s) { s.body.moments.y() = 0.0; }),
               "mujoco-test-box: principal_moments[1]: 0 (about body y)");
  EXPECT_PRED2(starts, refusal([](Scenario& s) { s.body.cage.mass = -1.0; }),
               "mujoco-test-box: mass: -1");
  EXPECT_PRED2(starts, refusal([](Scenario& s) {
                 s.initial.omega0_body.setZero();
                 s.initial.jiggle = 0.0;
               }),
               "mujoco-test-box: omega0_body: the body is at rest");
}

// A scenario's name becomes OUT/<name>.json and OUT/<name>/: letters, digits, '-', '_', '.',
// the first a letter or digit, so no name leaves OUT or breaks a line.
TEST(Judgement, AScenarioNameIsLettersDigitsDashUnderscoreAndDot) {
  for (const char* good : {"book-intermediate-0.05", "a", "A_b.c-9", "0"})
    EXPECT_EQ(scenario_name_problem(good), "") << good;
  for (const std::string& bad :
       {std::string(""), std::string("../escaped"), std::string(".."), std::string("."),
        std::string("a/b"), std::string("a\nb"), std::string("a b"), std::string("-x"),
        std::string(".hidden"), std::string("nul\0x", 5), std::string(129, 'a'),
        std::string("caf\xc3\xa9")})
    EXPECT_NE(scenario_name_problem(bad), "") << bad;
  Scenario s = scenario("mujoco-test-box");
  s.name = "../escaped";
  try {
    check_scenario(s);
    ADD_FAILURE() << "../escaped taken";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "flipcheck: scenario name \"../escaped\" starts with '.' at byte 1 (a scenario's "
              "name is ASCII letters, digits, '-', '_' and '.', the first a letter or a digit: a "
              "name every engine's tools write as a file's name)");
  }
  s.name = std::string("a\nb", 3);
  try {
    check_scenario(s);
    ADD_FAILURE() << "a newline taken";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("a\\x0ab"), std::string::npos) << e.what();
  }
}

// A name of a million characters is cut in its message, its length said: one short line, not
// the whole name echoed (docs/flipcheck.md, "What a scenario may be").
TEST(Judgement, ALongScenarioNameIsCutInItsMessageWithItsLength) {
  Scenario s = scenario("mujoco-test-box");
  // Up to 4096 bytes (PATH_MAX) named whole: 300 characters were cut to 60, the name lost.
  s.name = std::string(300, 'a');
  try {
    check_scenario(s);
    ADD_FAILURE() << "a name of 300 characters taken";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "flipcheck: scenario name \"" + std::string(300, 'a') +
                                         "\" is 300 characters long (at most 128)");
  }
  s.name = std::string(1000000, 'a');
  try {
    check_scenario(s);
    ADD_FAILURE() << "a name of 10^6 characters taken";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "flipcheck: scenario name \"" + std::string(60, 'a') +
                                         "\xe2\x80\xa6\" (1000000 characters) is 1000000 "
                                         "characters long (at most 128)");
  }
}

// The judgement CSV has the new columns, and the kit's rules hold the new limits.
TEST(Judgement, TheTableAndTheRulesCarryTheWholeMotionsMeasures) {
  const Scenario s = scenario("mujoco-test-box");
  const Conformance c = judge_motion(s, exact_rows(s, 1));
  const CsvTable table = judgement_table(s, "", {{"run.csv", "run", c}});
  for (const char* column : {"orientation_error", "orientation_error_step", "L_direction_error",
                             "L_direction_error_step"}) {
    bool found = false;
    for (const std::string& name : table.columns) found = found || name == column;
    EXPECT_TRUE(found) << column;
  }
  const std::string rules = judge_rules();
  EXPECT_NE(rules.find("L_direction 0.01\n"), std::string::npos) << rules;
  EXPECT_NE(rules.find("sampling_first_flip 0.01\n"), std::string::npos) << rules;
}

// The row the page and the npm package present (judgement_row) is the command line's table row:
// the same text, each cell read back as written, a motion name holding a comma and quotes
// included, the verdict, the failures and the line of the same judgement, passing or failing.
TEST(Judgement, OneMotionsRowIsTheCommandLinesRowReadBackCellByCell) {
  const Scenario s = scenario("book-intermediate-0.05");
  std::vector<MotionSample> turned = exact_rows(s, 1);
  const Eigen::Quaterniond turn(Eigen::AngleAxisd(kPi / 2, Eigen::Vector3d::UnitZ()));
  for (std::size_t i = 1; i + 1 < turned.size(); ++i) turned[i].q = turn * turned[i].q;
  const std::string sha(64, 'a');
  const std::string name = "run \"a\", b.csv";
  for (const std::vector<MotionSample>& rows : {exact_rows(s, 1), turned}) {
    const Conformance c = judge_motion(s, rows);
    const CsvTable table = judgement_table(s, sha, {{name, name, c}});
    const JudgementRow row = judgement_row(s, sha, rows, name);
    EXPECT_EQ(row.csv, csv_text(table, "flipcheck judge CSV"));
    EXPECT_EQ(row.columns, table.columns);
    ASSERT_EQ(row.cells.size(), table.columns.size());
    const auto cell = [&](const std::string& column) {
      for (std::size_t i = 0; i < row.columns.size(); ++i)
        if (row.columns[i] == column) return row.cells[i];
      return std::string("(no column ") + column + ")";
    };
    EXPECT_EQ(cell("motion"), name);
    EXPECT_EQ(cell("scenario"), s.name);
    EXPECT_EQ(cell("scenario_sha256"), sha);
    EXPECT_EQ(cell("verdict"), c.pass() ? "pass" : "fail");
    EXPECT_EQ(row.pass, c.pass());
    EXPECT_EQ(row.failures, c.failures);
    EXPECT_EQ(row.line, verdict_line(c));
  }
  EXPECT_FALSE(judgement_row(s, sha, turned, name).pass);
  EXPECT_TRUE(judgement_row(s, sha, exact_rows(s, 1), name).pass);
}

// A name in another script is refused stating the true rule (ASCII), not "must start with a
// letter" (回 is one) nor a bare byte; at the scene door (scenario_of) naming scene.name, the
// name as it reads.
TEST(Judgement, ANameInAnotherScriptIsToldTheRuleAndTheSceneKey) {
  for (const std::string& name : {std::string("\xe5\x9b\x9e\xe8\xbb\xa2"),
                                  std::string("b\xc3\xbck-\xcf\x89"), std::string("my scenario")}) {
    const std::string why = scenario_name_problem(name);
    EXPECT_NE(why.find("a scenario's name is ASCII letters, digits"), std::string::npos) << why;
    EXPECT_EQ(why.find("must start with a letter"), std::string::npos) << why;
  }
  EXPECT_NE(scenario_name_problem("b\xc3\xbck")
                .find("holds a character beyond ASCII (byte 0xc3) "
                      "at byte 2"),
            std::string::npos);
  EXPECT_NE(scenario_name_problem("my scenario").find("holds ' ' at byte 3"), std::string::npos);
}

}  // namespace
}  // namespace bookspin::analysis
