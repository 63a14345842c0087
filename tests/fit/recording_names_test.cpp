// A class's recordings named in its own alphabets (docs/phone-lab.md, "Names"): each file's name,
// Japanese, Greek, Cyrillic, German (written decomposed, as a Mac names it), Arabic, an emoji,
// is its recording's name in NFC in every table row, chart, scene name and title of the pooled
// fit, and the names stay apart.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "fit/pool.hpp"
#include "fit/recording.hpp"
#include "fit/report.hpp"
#include "support/scratch.hpp"
#include "synthetic_recording.hpp"

namespace bookspin::fit {
namespace {

struct Named {
  std::string file;  ///< the file's name as written on disk
  std::string name;  ///< the recording's name the fit gives it
};

const std::vector<Named> kNamed = {
    {"太郎.csv", "太郎"},
    {"花子.csv", "花子"},
    {"Αθηνά ρίψη.csv", "Αθηνά ρίψη"},
    {"Юлия.csv", "Юлия"},
    {"Wurf u\u0308ber dem Bett.csv", "Wurf \u00fcber dem Bett"},  // NFD on disk, NFC named
    {"تجربة.csv", "تجربة"},
    {"🎲 würfel.csv", "🎲 würfel"},
};

/// The second cell of each row of a toss table's CSV text (its recording), unquoted.
std::vector<std::string> recording_cells(const std::string& csv) {
  std::vector<std::string> cells;
  std::istringstream rows(csv);
  std::string row;
  std::getline(rows, row);  // the header
  while (std::getline(rows, row)) {
    if (row.empty()) continue;
    const std::size_t comma = row.find(',');
    cells.push_back(row.substr(comma + 1, row.find(',', comma + 1) - comma - 1));
  }
  return cells;
}

TEST(RecordingNames, EveryAlphabetReachesEveryTableChartAndScene) {
  const std::vector<test::SyntheticToss> throws = {
      {{1.0, 18.0, 1.2}, 1.3},   {{-1.2, 17.0, 1.5}, 1.2}, {{0.8, 16.0, -1.0}, 1.2},
      {{1.1, -17.5, 0.9}, 1.25}, {{-0.9, 16.5, 1.1}, 1.3}, {{0.7, -18.0, -1.2}, 1.2},
      {{1.3, 17.2, -0.8}, 1.25}};
  const bookspin::test::ScratchDir dir;
  std::vector<GyroRecording> read;
  for (std::size_t i = 0; i < kNamed.size(); ++i) {
    const test::SyntheticRecording r =
        test::make_recording(test::phone_alone(), {throws[i]}, static_cast<unsigned>(41 + i));
    std::ofstream(dir.path() / kNamed[i].file) << test::raw_data_csv(r, test::Dialect::comma);
    read.push_back(read_recording(dir.path() / kNamed[i].file));
    EXPECT_EQ(read.back().name, kNamed[i].name);
  }
  const GyroRecording pooled = pool_recordings(read);
  std::vector<std::string> expected;
  for (const Named& n : kNamed) expected.push_back(n.name);
  std::sort(expected.begin(), expected.end());
  std::vector<std::string> parts;
  for (const RecordingPart& part : pooled.parts) parts.push_back(part.name);
  EXPECT_EQ(parts, expected);  // the canonical order: by name, as bytes
  EXPECT_EQ(pooled.name, expected.front() + "-and-6-more");
  const FitReport report = fit_report(pooled, {});
  EXPECT_EQ(report.recording, pooled.name);
  std::vector<std::string> rows = recording_cells(report.toss_csv);
  ASSERT_EQ(rows.size(), kNamed.size()) << report.toss_csv;
  std::sort(rows.begin(), rows.end());
  EXPECT_EQ(rows, expected);
  ASSERT_EQ(report.tosses.size(), kNamed.size());
  for (const TossReport& toss : report.tosses) {
    EXPECT_NE(std::find(expected.begin(), expected.end(), toss.chart.recording), expected.end())
        << toss.chart.recording;
    ASSERT_TRUE(toss.scene.has_value());
    EXPECT_EQ(toss.scene->title.rfind(toss.chart.recording + ", toss ", 0), 0u)
        << toss.scene->title;
    EXPECT_EQ(toss.scene->name.rfind(pooled.name + "-toss", 0), 0u) << toss.scene->name;
    EXPECT_NE(toss.scene_text.find(toss.chart.recording), std::string::npos);
  }
}

}  // namespace
}  // namespace bookspin::fit
