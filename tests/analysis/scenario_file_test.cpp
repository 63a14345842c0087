// The scenario file's reader (analysis/scenario_file.hpp) where JSON leaves a choice: a key
// given twice and a string's escapes read as JSON.parse and Python's json read them, so that
// the npm package (which hands the reader an object written as JSON) and the command line see
// one scenario.
#include "analysis/scenario_file.hpp"

#include <gtest/gtest.h>

#include <string>

#include "common/errors.hpp"

namespace bookspin::analysis {
namespace {

const char* const kBox =
    R"({"scenario": "box", "mass": 2, "principal_moments": [1, 2, 3],
        "omega0_body": [0.1, 2, 0.05], "dt": 0.01, "steps": 100})";

void expect_same(const Scenario& a, const Scenario& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.body.cage.mass, b.body.cage.mass);
  EXPECT_EQ(a.body.moments, b.body.moments);
  EXPECT_EQ(a.initial.omega0_body, b.initial.omega0_body);
  EXPECT_EQ(a.dt, b.dt);
  EXPECT_EQ(a.steps, b.steps);
}

// Of a key given twice the last counts, whichever of the two is the bad one; the name's
// escapes (\u006f is "o") are read as the characters they stand for.
TEST(ScenarioFile, AKeyGivenTwiceCountsItsLastValueAndEscapesReadAsTheirCharacters) {
  const Scenario box = scenario_from_json(kBox, "box.json");
  EXPECT_EQ(box.name, "box");
  EXPECT_EQ(box.body.cage.mass, 2.0);
  EXPECT_EQ(box.steps, 100);
  const std::string body = std::string(kBox).substr(1);  // without its opening brace
  expect_same(scenario_from_json(R"({"scenario": "b\u006fx", "mass": -1, "steps": 2.5, )" + body,
                                 "twice.json"),
              box);
  try {
    scenario_from_json(
        std::string(kBox).substr(0, std::string(kBox).size() - 1) + R"(, "mass": -1})",
        "last-bad.json");
    ADD_FAILURE() << "a bad mass given last was taken";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("box: mass: -1"), std::string::npos) << e.what();
  }
}

// A NUL typed into a string is named where it stands, a control character at its line and
// column, as any other; only a file whose NULs say it is no text (UTF-16, binary) is said to be
// so (it was "not a text file" for one NUL in a name).
TEST(ScenarioFile, ANulInAStringIsAControlCharacterAtItsLineAndColumn) {
  const std::string nul_in_name = std::string("{\"scenario\": \"bo") + '\0' + "x\",\n \"mass\": 2}";
  std::string said;
  try {
    scenario_from_json(nul_in_name, "nul.json");
  } catch (const InputError& e) {
    said = e.what();
  }
  EXPECT_NE(said.find("a control character"), std::string::npos) << said;
  EXPECT_NE(said.find("line 1, column 17"), std::string::npos) << said;
  EXPECT_EQ(said.find("not a text file"), std::string::npos) << said;
  // UTF-16 (every other byte a NUL) is still said to be so.
  std::string utf16 = "\xff\xfe";
  for (const char c : std::string(kBox)) utf16 += std::string(1, c) + '\0';
  try {
    scenario_from_json(utf16, "le.json");
    ADD_FAILURE() << "UTF-16 taken";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not a text file"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace bookspin::analysis
