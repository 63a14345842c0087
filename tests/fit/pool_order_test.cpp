// A pooled set is a set (docs/phone-lab.md, "A class's recordings"): the recordings of one body
// given in any order (a command line's, a dropped folder's) give the same tosses, numbers, names
// and outputs to the last digit, on the real recordings in ../shared/recordings-real/ (skipped,
// saying why, where absent) and on synthetic ones.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "common/text_file.hpp"
#include "fit/pool.hpp"
#include "fit/recording.hpp"
#include "fit/report.hpp"
#include "real_recordings.hpp"
#include "support/scratch.hpp"
#include "synthetic_recording.hpp"
#include "zip_writer.hpp"

namespace bookspin::fit {
namespace {

/// Every value a door presents, `b`'s against `a`'s, to the last bit: the name, the tables' and
/// summary's text, every toss's flight, numbers, chart and scene; the source (the paths read)
/// unless the files were read from elsewhere (`same_files` false).
void expect_same_report(const FitReport& a, const FitReport& b, bool same_files = true) {
  EXPECT_EQ(a.recording, b.recording);
  if (same_files) {
    EXPECT_EQ(a.source, b.source);
  }
  EXPECT_EQ(a.toss_csv, b.toss_csv);
  EXPECT_EQ(a.body_csv, b.body_csv);
  EXPECT_EQ(a.summary, b.summary);
  EXPECT_EQ(a.dropped, b.dropped);
  EXPECT_EQ(a.result.body.ratios, b.result.body.ratios);
  EXPECT_EQ(a.result.body.axes, b.result.body.axes);
  EXPECT_EQ(a.result.body.ratio_sigma, b.result.body.ratio_sigma);
  ASSERT_EQ(a.tosses.size(), b.tosses.size());
  for (std::size_t k = 0; k < a.tosses.size(); ++k) {
    SCOPED_TRACE("toss " + std::to_string(k + 1));
    const TossFit &x = a.result.tosses[k], &y = b.result.tosses[k];
    EXPECT_EQ(x.flight.t_start, y.flight.t_start);
    EXPECT_EQ(x.flight.t_end, y.flight.t_end);
    EXPECT_EQ(x.omega0, y.omega0);
    EXPECT_EQ(x.drag_rate, y.drag_rate);
    EXPECT_EQ(x.half_period_measured, y.half_period_measured);
    EXPECT_EQ(x.half_period_predicted, y.half_period_predicted);
    EXPECT_EQ(x.half_period_predicted_sigma, y.half_period_predicted_sigma);
    EXPECT_EQ(x.not_predicted, y.not_predicted);
    EXPECT_EQ(a.tosses[k].chart.recording, b.tosses[k].chart.recording);
    EXPECT_EQ(a.tosses[k].chart.t, b.tosses[k].chart.t);
    EXPECT_EQ(a.tosses[k].chart.curve, b.tosses[k].chart.curve);
    EXPECT_EQ(a.tosses[k].scene_text, b.tosses[k].scene_text);
    EXPECT_EQ(a.tosses[k].measured_csv, b.tosses[k].measured_csv);
  }
}

/// `recordings` pooled and fitted in the order given, then in each order of `orders` (indices
/// into `recordings`): every report the same as the first.
void expect_any_order_same(const std::vector<GyroRecording>& recordings,
                           const std::vector<std::vector<int>>& orders) {
  const FitReport first = fit_report(pool_recordings(recordings), {});
  ASSERT_FALSE(first.tosses.empty());
  for (const std::vector<int>& order : orders) {
    std::vector<GyroRecording> given;
    std::string said;
    for (int i : order) given.push_back(recordings.at(i)), said += recordings.at(i).name + " ";
    SCOPED_TRACE("given as " + said);
    expect_same_report(first, fit_report(pool_recordings(given), {}));
  }
}

// The bare phone's three recordings and the plate's four, each set in three other orders.
TEST(PoolOrder, RealRecordingsInAnyOrderGiveTheSameAnswerToTheLastDigit) {
  REQUIRE_REAL_RECORDINGS();
  const std::vector<std::vector<std::string>> sets = {
      {"12-10-56", "12-13-01", "12-13-51"}, {"12-22-44", "12-29-59", "12-38-00", "12-44-51"}};
  for (const std::vector<std::string>& names : sets) {
    std::vector<GyroRecording> recordings;
    for (const std::string& name : names) recordings.push_back(read_recording(real_dir() / name));
    SCOPED_TRACE(names.front() + " and the others");
    if (names.size() == 3)
      expect_any_order_same(recordings, {{2, 1, 0}, {1, 2, 0}, {2, 0, 1}});
    else
      expect_any_order_same(recordings, {{3, 2, 1, 0}, {1, 3, 0, 2}, {2, 0, 3, 1}});
  }
}

// Three students' recordings of one phone, one throw each and biases of their own; one of them
// on a clock 100 s ahead. Every order of the three.
TEST(PoolOrder, SyntheticRecordingsInAnyOrderGiveTheSameAnswerToTheLastDigit) {
  const std::vector<test::SyntheticToss> throws = {
      {{1.0, 18.0, 1.2}, 1.3}, {{-1.2, 17.0, 1.5}, 1.2}, {{0.8, -16.0, -1.0}, 1.25}};
  const Eigen::Vector3d biases[3] = {
      {0.021, -0.014, 0.008}, {-0.03, 0.02, 0.011}, {0.005, 0.04, -0.025}};
  std::vector<GyroRecording> recordings;
  for (int s = 0; s < 3; ++s) {
    test::SyntheticRecording rec =
        test::make_recording(test::phone_alone(), {throws[s]}, 301 + s, 0.01);
    for (Eigen::Vector3d& w : rec.omega) w += biases[s] - rec.bias;
    if (s == 1)
      for (double& t : rec.t) t += 100.0;
    recordings.push_back(test::as_read(rec, "student" + std::to_string(s + 1)));
  }
  expect_any_order_same(recordings, {{0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}});
}

// Two recordings given the same name (one export's folder name in two places): their order is
// still one, by their samples.
TEST(PoolOrder, RecordingsOfOneNameAreOrderedByTheirSamples) {
  const std::vector<test::SyntheticToss> throws = {{{1.0, 18.0, 1.2}, 1.3},
                                                   {{-1.2, 17.0, 1.5}, 1.2}};
  const GyroRecording a =
      test::as_read(test::make_recording(test::phone_alone(), {throws[0]}, 11), "export");
  GyroRecording b =
      test::as_read(test::make_recording(test::phone_alone(), {throws[1]}, 12), "export");
  b.source = "elsewhere/export.csv";
  const GyroRecording ab = pool_recordings({a, b}), ba = pool_recordings({b, a});
  EXPECT_EQ(ab.t, ba.t);
  EXPECT_EQ(ab.omega, ba.omega);
  EXPECT_EQ(ab.source, ba.source);
  ASSERT_EQ(ab.parts.size(), 2u);
  EXPECT_EQ(ab.parts[0].source, ba.parts[0].source);
  // Told apart: the second in the canonical order takes "-2", given in either order.
  EXPECT_EQ(ab.parts[0].name, "export");
  EXPECT_EQ(ab.parts[1].name, "export-2");
  EXPECT_EQ(ba.parts[1].name, "export-2");
}

// Files whose names are made file-safe alike ("anna:b.csv", "anna*b.csv") beside "anna b.csv"
// (a name of its own: a space is kept) and one already called "anna-b-2": each recording keeps a
// name of its own in every table row and file name (the later alike takes the first free
// suffix, "-3"), however the four are given; the toss rows name four recordings.
TEST(PoolOrder, RecordingsNamedAlikeAreToldApartInEveryTable) {
  const std::vector<test::SyntheticToss> throws = {{{1.0, 18.0, 1.2}, 1.3},
                                                   {{-1.2, 17.0, 1.5}, 1.2},
                                                   {{0.8, 16.0, -1.0}, 1.2},
                                                   {{1.1, -17.5, 0.9}, 1.25}};
  const bookspin::test::ScratchDir dir;
  const char* files[] = {"anna b.csv", "anna:b.csv", "anna*b.csv", "anna-b-2.csv"};
  std::vector<GyroRecording> read;
  for (int i = 0; i < 4; ++i) {
    const test::SyntheticRecording r = test::make_recording(
        test::phone_alone(), {throws[static_cast<std::size_t>(i)]}, static_cast<unsigned>(21 + i));
    std::ofstream(dir.path() / files[i]) << test::raw_data_csv(r, test::Dialect::comma);
    read.push_back(read_recording(dir.path() / files[i]));
  }
  EXPECT_EQ(read[0].name, "anna b");  // a name of its own
  EXPECT_EQ(read[1].name, "anna-b");  // file-safe alike
  EXPECT_EQ(read[2].name, "anna-b");
  for (const std::vector<int>& order :
       std::vector<std::vector<int>>{{0, 1, 2, 3}, {3, 2, 1, 0}, {1, 3, 2, 0}}) {
    std::vector<GyroRecording> given;
    for (int i : order) given.push_back(read[static_cast<std::size_t>(i)]);
    const GyroRecording pooled = pool_recordings(given);
    std::vector<std::string> names;
    for (const RecordingPart& part : pooled.parts) names.push_back(part.name);
    std::sort(names.begin(), names.end());
    EXPECT_EQ(std::adjacent_find(names.begin(), names.end()), names.end());
    EXPECT_EQ(names, (std::vector<std::string>{"anna b", "anna-b", "anna-b-2", "anna-b-3"}));
    const FitReport report = fit_report(pooled, {});
    std::vector<std::string> named;  // each toss row's second cell, its recording
    std::istringstream rows(report.toss_csv);
    std::string row;
    std::getline(rows, row);  // the header
    while (std::getline(rows, row)) {
      if (row.empty()) continue;
      const std::size_t comma = row.find(',');
      named.push_back(row.substr(comma + 1, row.find(',', comma + 1) - comma - 1));
    }
    EXPECT_EQ(named.size(), 4u);
    std::sort(named.begin(), named.end());
    EXPECT_EQ(named, names);
  }
}

}  // namespace
}  // namespace bookspin::fit

namespace bookspin::fit {
namespace {

namespace fs = std::filesystem;

// A set is a set however it is given (docs/phone-lab.md, "A class's recordings"): the real
// session's seven recordings, one of them phyphox's single-sensor CSV ("Gyroscope rotation rate
// … .csv" alone in its folder), given as their folders, as the files themselves (the CSV and
// each Raw Data.csv), as zips of the exports beside that CSV, as the page writes a dropped
// folder's files ("<folder>/<file>" read from a folder of their own), and as the folders in
// reverse: the same recording names, tosses and numbers to the last digit.
TEST(PoolOrder, OneSetGivenFiveWaysGivesOneAnswer) {
  REQUIRE_REAL_RECORDINGS();
  const std::vector<std::string> names = {"12-10-56", "12-13-01", "12-13-51", "12-22-44",
                                          "12-29-59", "12-38-00", "12-44-51"};
  const fs::path work = fs::temp_directory_path() / ("pool-order-" + std::to_string(::getpid()));
  fs::remove_all(work);
  std::vector<GyroRecording> folders, files, zips, dropped, reversed;
  for (const std::string& name : names) {
    const fs::path folder = real_dir() / name;
    folders.push_back(read_recording(folder));
    fs::path csv = folder / "Raw Data.csv";
    if (!fs::exists(csv))
      for (const fs::directory_entry& e : fs::directory_iterator(folder))
        if (e.path().extension() == ".csv") csv = e.path();
    files.push_back(read_recording(csv));
    // The page: the dropped folder's file written under a folder of the same name.
    const fs::path page = work / "page" / name;
    fs::create_directories(page);
    fs::copy_file(csv, page / csv.filename());
    if (fs::exists(folder / "meta")) fs::copy(folder / "meta", page / "meta");
    dropped.push_back(read_recording(page / csv.filename()));
    // A zip of each phyphox export (its Raw Data.csv and meta/), the single CSV as it is.
    if (csv.filename() == "Raw Data.csv") {
      std::vector<std::pair<std::string, std::string>> entries = {
          {"Raw Data.csv", read_text_file(csv, "test")}};
      for (const char* meta : {"meta/time.csv", "meta/device.csv"})
        if (fs::exists(folder / meta))
          entries.emplace_back(meta, read_text_file(folder / meta, "test"));
      fs::create_directories(work / "zips");
      test::write_zip(work / "zips" / (name + ".zip"), entries);
      zips.push_back(read_recording(work / "zips" / (name + ".zip")));
    } else {
      zips.push_back(read_recording(csv));
    }
  }
  reversed.assign(folders.rbegin(), folders.rend());
  const FitReport first = fit_report(pool_recordings(folders), {});
  ASSERT_FALSE(first.tosses.empty());
  for (const auto& [way, given] :
       {std::pair{"files", &files}, std::pair{"zips", &zips},
        std::pair{"a dropped folder", &dropped}, std::pair{"folders in reverse", &reversed}}) {
    SCOPED_TRACE(std::string("given as ") + way);
    std::vector<std::string> given_names;
    for (const GyroRecording& r : *given) given_names.push_back(r.name);
    std::vector<std::string> sorted = given_names;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(sorted, names);
    expect_same_report(first, fit_report(pool_recordings(*given), {}), given != &dropped);
  }
  fs::remove_all(work);
}

}  // namespace
}  // namespace bookspin::fit
