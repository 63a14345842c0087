// `bookspin fit REC1 REC2 …` run as a program: a class's one-throw recordings of one phone
// fitted as one body (docs/phone-lab.md, "A class's recordings").
#include <gtest/gtest.h>

#include "fit/synthetic_recording.hpp"
#include "support/cli_runner.hpp"

namespace bookspin::cli {
namespace {

namespace fs = std::filesystem;

TEST(FitPooled, SeveralRecordingsAreOneBodyAndEachTossNamesItsRecording) {
  const fs::path dir = bookspin::test::fresh_dir("cli/fit/pooled");
  const std::vector<fit::test::SyntheticToss> throws = {
      {{1.0, 18.0, 1.2}, 1.3}, {{-1.2, 17.0, 1.5}, 1.2}, {{0.8, -16.0, -1.0}, 1.25}};
  std::string args;
  for (int s = 0; s < 3; ++s) {
    const std::string name = "student" + std::to_string(s + 1);
    fit::test::write_export(
        dir / name, fit::test::make_recording(fit::test::phone_alone(), {throws[s]}, 301 + s),
        fit::test::Dialect::comma);
    args += " '" + (dir / name).string() + "'";
  }
  const std::string command = "fit" + args + " -o '" + (dir / "out").string() + "'";
  const auto result = bookspin::test::run_bookspin(command);
  ASSERT_EQ(result.status, 0) << result.output;
  for (const char* line : {"bias of student1 ", "bias of student3 ", "kept toss 1: student1 ",
                           "kept toss 3: student3 "})
    EXPECT_NE(result.output.find(line), std::string::npos) << line << "\n" << result.output;
  const std::string csv =
      read_text_file(dir / "out" / "student1-and-2-more-fit.csv", "the pooled CSV");
  EXPECT_EQ(csv.substr(0, csv.find('\n')).rfind("toss,recording,t_start,t_end,", 0), 0u) << csv;
  EXPECT_NE(csv.find("\n3,student3,"), std::string::npos) << csv;
  for (const char* name : {"student1-and-2-more-fit-body.csv", "student1-and-2-more-toss3.png",
                           "student1-and-2-more/fit-manifest.json"})
    EXPECT_TRUE(fs::exists(dir / "out" / name)) << name;
  EXPECT_NE(bookspin::test::run_bookspin(command).output.find("up to date"), std::string::npos);
  // A recording given twice: one line, exit 2, nothing written.
  const auto twice = bookspin::test::run_bookspin("fit '" + (dir / "student1").string() + "' '" +
                                                  (dir / "student1").string() + "' -o '" +
                                                  (dir / "twice").string() + "'");
  EXPECT_EQ(twice.status, 2) << twice.output;
  EXPECT_NE(twice.output.find("given twice"), std::string::npos) << twice.output;
  EXPECT_FALSE(fs::exists(dir / "twice"));
}

}  // namespace
}  // namespace bookspin::cli
