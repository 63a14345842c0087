// The gyroscope's range as the export states it (fit/recording.hpp parse_device_csv,
// fit/saturation.hpp; docs/phone-lab.md "Saturation"): phyphox for Android writes
// `meta/device.csv`, a "property","value" table whose row "gyroscope Range" is Android's
// Sensor.getMaximumRange() in rad/s. The files here are written by hand in that layout; the
// recordings are synthetic tosses (synthetic_recording.hpp) clipped by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "common/errors.hpp"
#include "fit/pool.hpp"
#include "fit/recording.hpp"
#include "fit/saturation.hpp"
#include "support/scratch.hpp"
#include "synthetic_recording.hpp"
#include "zip_writer.hpp"

namespace bookspin::fit {
namespace {

// An Android export's device.csv as phyphox writes it: device rows, then per sensor its eight
// rows (Name, Vendor, Range, Resolution, MinDelay, MaxDelay, Power, Version).
std::string android_device_csv(char separator, const std::string& gyro_range) {
  const std::string s(1, separator);
  std::string text = "\"property\"" + s + "\"value\"\n";
  for (const char* row : {"version", "build", "fileFormat", "deviceModel", "deviceBrand"})
    text += "\"" + std::string(row) + "\"" + s + "\"x\"\n";
  text += "\"accelerometer Range\"" + s + "\"78.4532\"\n";
  text += "\"gyroscope Name\"" + s + "\"LSM6DSO Gyroscope\"\n";
  text += "\"gyroscope Range\"" + s + "\"" + gyro_range + "\"\n";
  text += "\"gyroscope Resolution\"" + s + "\"0.0012217305\"\n";
  return text;
}

TEST(DeviceCsv, TheGyroscopesRangeIsReadInEveryDialectAndNothingWhereItIsNotStated) {
  for (char separator : {',', '\t', ';'})
    EXPECT_DOUBLE_EQ(*parse_device_csv(android_device_csv(separator, "34.906586"), "device.csv"),
                     34.906586)
        << "separator " << separator;
  // phyphox for iOS writes device rows only; Android with no gyroscope writes "null".
  EXPECT_FALSE(parse_device_csv("\"property\",\"value\"\n\"deviceModel\",\"iPhone14,2\"\n", "d")
                   .has_value());
  EXPECT_FALSE(parse_device_csv(android_device_csv(',', "null"), "d").has_value());
  EXPECT_FALSE(parse_device_csv("", "d").has_value());
  try {
    parse_device_csv(android_device_csv(',', "fast"), "export/meta/device.csv");
    FAIL() << "a range that is not a number was taken";
  } catch (const InputError& e) {
    // The header is line 1; 5 device rows, the accelerometer's and the gyroscope's name: line 9.
    EXPECT_NE(std::string(e.what()).find("export/meta/device.csv:9"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("gyroscope Range"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parse_device_csv(android_device_csv(',', "-34.9"), "d"), InputError);
}

TEST(DeviceCsv, AnExportFoldersRangeReachesTheRecording) {
  const test::SyntheticRecording rec =
      test::make_recording(test::phone_alone(), {{{0.3, 14.0, 0.5}, 1.2}}, 3);
  const auto dir = bookspin::test::fresh_dir("fit/device-csv") / "Gyroscope rotation rate";
  test::write_export(dir, rec, test::Dialect::comma);
  EXPECT_FALSE(read_recording(dir).gyroscope_range.has_value());  // device rows only
  std::ofstream(dir / "meta" / "device.csv", std::ios::binary)
      << android_device_csv(',', "17.453293");
  EXPECT_DOUBLE_EQ(*read_recording(dir).gyroscope_range, 17.453293);
  EXPECT_DOUBLE_EQ(*read_recording(dir / "Raw Data.csv").gyroscope_range, 17.453293);
  // A zip of the export, its device.csv tab-separated.
  const auto path = dir.parent_path() / "export.zip";
  test::write_zip(path, {{"export/Raw Data.csv", test::raw_data_csv(rec, test::Dialect::comma)},
                         {"export/meta/device.csv", android_device_csv('\t', "8.726646")}});
  EXPECT_DOUBLE_EQ(*read_recording(path).gyroscope_range, 8.726646);
}

const std::vector<test::SyntheticToss> kTosses{
    {{0.3, 14.0, 0.5}, 1.2}, {{-0.4, 13.0, 0.6}, 1.1}, {{0.5, -15.0, -0.3}, 1.3}};

/// `recording` with every component clipped to ±range.
GyroRecording clipped(GyroRecording recording, double range) {
  for (Eigen::Vector3d& w : recording.omega) w = w.cwiseMax(-range).cwiseMin(range);
  return recording;
}

/// The `n`-th largest |ω_i| of `recording`'s samples (n = 1: the top).
double nth_top(const GyroRecording& recording, std::size_t n) {
  std::vector<double> tops;
  for (const Eigen::Vector3d& w : recording.omega) tops.push_back(w.cwiseAbs().maxCoeff());
  std::sort(tops.rbegin(), tops.rend());
  return tops[n - 1];
}

// Clipped where only two samples of the whole recording reach: too short a run to be found
// from the samples (kMinFlatSamples is 3), but the range the export states marks both, and the
// samples within 0.1 % of it; a sample above the stated range means it is not the range.
TEST(Saturation, TheRangeThatDeviceCsvStatesMarksEvenAShortClip) {
  const GyroRecording recording =
      test::as_read(test::make_recording(test::phone_alone(), kTosses, 11));
  const double range = nth_top(recording, 3);
  GyroRecording clip = clipped(recording, range);
  ASSERT_FALSE(find_saturation(pool_recordings({clip})).range.has_value())
      << "found from the samples alone";
  clip.gyroscope_range = range;
  const Saturation found = find_saturation(pool_recordings({clip}));
  ASSERT_TRUE(found.range.has_value());
  EXPECT_DOUBLE_EQ(*found.range, range);
  int marked = 0;
  for (std::size_t i = 0; i < clip.omega.size(); ++i) {
    const bool at = clip.omega[i].cwiseAbs().maxCoeff() >= range * (1.0 - 1e-3);
    EXPECT_EQ(found.at_range[i], at) << "sample " << i;
    marked += at;
  }
  EXPECT_GE(marked, 3);  // the two clipped and the one at the range
  // A stated range the samples exceed is not the range: nothing found (no flat run either).
  clip.gyroscope_range = 0.5 * range;
  EXPECT_FALSE(find_saturation(pool_recordings({clip})).range.has_value());
}

// Two recordings, each with its own bias and its own range, pooled: each recording is searched
// on its own samples as measured, with its own stated range, and every clipped sample is found
// where it lies in the pooled recording. a is clipped for tens of samples (found from its samples);
// b only where its two fastest samples reach, which only its stated range shows.
TEST(Saturation, PooledRecordingsAreSearchedEachOnItsOwn) {
  // Named a and b: pooled in that order (pool_recordings orders them by name).
  GyroRecording a = test::as_read(test::make_recording(test::phone_alone(), kTosses, 5), "a");
  GyroRecording b = test::as_read(test::make_recording(test::phone_alone(), kTosses, 6), "b");
  a.source = "a.csv";
  b.source = "b.csv";
  for (Eigen::Vector3d& w : b.omega) w += Eigen::Vector3d(0.05, -0.04, 0.03);  // b's own bias
  // The tosses turn at 13–15 rad/s about the intermediate axis: a clipped at 12.
  const double range_a = 12.0, range_b = nth_top(b, 3);
  a = clipped(a, range_a);
  b = clipped(b, range_b);
  b.gyroscope_range = range_b;
  std::vector<bool> expected;
  for (const Eigen::Vector3d& w : a.omega) expected.push_back(w.cwiseAbs().maxCoeff() == range_a);
  for (const Eigen::Vector3d& w : b.omega)
    expected.push_back(w.cwiseAbs().maxCoeff() >= range_b * (1.0 - 1e-3));
  const GyroRecording pooled = pool_recordings({a, b});
  const Saturation found = find_saturation(pooled);
  ASSERT_TRUE(found.range.has_value());
  EXPECT_DOUBLE_EQ(*found.range, std::max(range_a, range_b));
  ASSERT_EQ(found.at_range.size(), expected.size());
  int in_a = 0, in_b = 0;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(found.at_range[i], expected[i]) << "sample " << i;
    (i < a.omega.size() ? in_a : in_b) += expected[i];
  }
  EXPECT_GT(in_a, 10);
  EXPECT_GE(in_b, 3);
}

// One phone's two recordings, no range stated (an iPhone's export): a's only peak is one sample
// at 17.4533 rad/s (±1000 °/s's band) between neighbours at 5 rad/s, which alone reads as a spike
// cut flat; b's smooth peak reaches 33.7 rad/s. Pooled, the gyroscope that read 33.7 did not stop
// at 17.45: a's range is refuted and nothing is marked. Given b's own stated range (another
// phone's), a's clip stands, and the note names a, not b.
TEST(Saturation, ARangeAnotherRecordingOfThePhoneReadsPastIsNoRange) {
  const auto recording = [](const std::string& name, double peak, bool spike) {
    std::vector<double> t;
    std::vector<Eigen::Vector3d> omega;
    for (int i = 0; i < 200; ++i) {
      t.push_back(0.01 * i);
      const double swing = spike ? 5.0 * std::sin(0.05 * i) : peak * std::sin(0.02 * i);
      omega.emplace_back(0.3, swing, -0.2);
    }
    if (spike) omega[100].y() = peak;
    GyroRecording r = samples_recording(name, t, omega);
    r.source = name + ".csv";
    return r;
  };
  const GyroRecording a = recording("a", 17.4533, true), b = recording("b", 33.7, false);
  const Saturation alone = find_saturation(pool_recordings({a}));
  ASSERT_TRUE(alone.range.has_value());
  EXPECT_DOUBLE_EQ(*alone.range, kFullScales[2]);
  EXPECT_EQ(std::count(alone.at_range.begin(), alone.at_range.end(), true), 1);

  const GyroRecording pooled = pool_recordings({a, b});
  const Saturation both = find_saturation(pooled);
  EXPECT_FALSE(both.range.has_value());
  EXPECT_EQ(std::count(both.at_range.begin(), both.at_range.end(), true), 0);
  EXPECT_EQ(saturation_note(both, pooled.parts, {0, 0}), "");

  GyroRecording other_phone = b;
  other_phone.gyroscope_range = 34.906586;
  const GyroRecording two_phones = pool_recordings({a, other_phone});
  const Saturation apart = find_saturation(two_phones);
  ASSERT_TRUE(apart.range.has_value());
  EXPECT_EQ(std::count(apart.at_range.begin(), apart.at_range.end(), true), 1);
  EXPECT_EQ(saturation_note(apart, two_phones.parts, {1, 0}),
            "the gyroscope saturated at ±17.4533 rad/s (1000 °/s, a standard full scale) in a (1 "
            "sample); 1 of them in the tosses, left out of the fit");
}

}  // namespace
}  // namespace bookspin::fit
