// `bookspin fit REC1 REC2 …` run as a program: a class's one-throw recordings of one phone
// fitted as one body (docs/phone-lab.md, "A class's recordings").
#include <gtest/gtest.h>

#include <fstream>

#include "common/text_file.hpp"
#include "fit/synthetic_recording.hpp"
#include "output/png_writer.hpp"
#include "scene/scene.hpp"
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

// Recordings named in six alphabets (docs/phone-lab.md, "Names"): each keeps its name, in NFC,
// in the lines printed, the table's rows and every output file's name, and the files it writes
// open again: the tables, each toss's chart (a PNG) and scene (read back as a scene, its title
// naming the toss's recording).
TEST(FitPooled, NamesInAnyAlphabetNameEveryOutput) {
  const fs::path dir = bookspin::test::fresh_dir("cli/fit/names");
  const std::vector<std::pair<std::string, std::string>> named = {
      {"太郎", "太郎"},   {"Αθηνά", "Αθηνά"},
      {"Юлия", "Юлия"},   {"Wurf u\u0308ber dem Bett", "Wurf \u00fcber dem Bett"},  // NFD on disk
      {"تجربة", "تجربة"}, {"🎲 würfel", "🎲 würfel"}};
  const std::vector<fit::test::SyntheticToss> throws = {
      {{1.0, 18.0, 1.2}, 1.3},   {{-1.2, 17.0, 1.5}, 1.2}, {{0.8, -16.0, -1.0}, 1.25},
      {{1.1, -17.5, 0.9}, 1.25}, {{-0.9, 16.5, 1.1}, 1.3}, {{0.7, -18.0, -1.2}, 1.2}};
  std::string args;
  for (std::size_t s = 0; s < named.size(); ++s) {
    const fs::path file = dir / (named[s].first + ".csv");
    std::ofstream(file, std::ios::binary)
        << fit::test::raw_data_csv(fit::test::make_recording(fit::test::phone_alone(), {throws[s]},
                                                             static_cast<unsigned>(331 + s)),
                                   fit::test::Dialect::comma);
    args += " '" + file.string() + "'";
  }
  const auto result =
      bookspin::test::run_bookspin("fit" + args + " -o '" + (dir / "out").string() + "'");
  ASSERT_EQ(result.status, 0) << result.output;
  // The canonical order is by name as bytes: the German first.
  const std::string pool = "Wurf \u00fcber dem Bett-and-5-more";
  const std::string csv = read_text_file(dir / "out" / (pool + "-fit.csv"), "the pooled CSV");
  for (const auto& [file, name] : named) {
    EXPECT_NE(result.output.find("bias of " + name + " "), std::string::npos) << name;
    EXPECT_NE(csv.find("," + name + ","), std::string::npos) << name << "\n" << csv;
  }
  EXPECT_TRUE(fs::exists(dir / "out" / (pool + "-fit-body.csv")));
  for (int k = 1; k <= static_cast<int>(named.size()); ++k) {
    const std::string toss = pool + "-toss" + std::to_string(k);
    EXPECT_GT(output::read_png(dir / "out" / (toss + ".png")).width, 0) << toss;
    const scene::Scene scene = scene::parse_scene(dir / "out" / (toss + ".toml"), {});
    EXPECT_EQ(scene.name, toss);
    const auto named_in_title = std::count_if(named.begin(), named.end(), [&](const auto& n) {
      return scene.title.rfind(n.second + ", toss ", 0) == 0;
    });
    EXPECT_EQ(named_in_title, 1) << scene.title;
  }
}

}  // namespace
}  // namespace bookspin::cli
