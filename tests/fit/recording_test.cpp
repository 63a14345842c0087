// The recording reader: phyphox's three CSV dialects, its folder, its Raw Data.csv and a zip of
// the folder, the pauses of meta/time.csv, a plain t,wx,wy,wz CSV, and bad input (one line
// naming file, row and column).
#include "fit/recording.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <optional>
#include <tuple>
#include <utility>
#include <vector>

#include "common/errors.hpp"
#include "common/number_text.hpp"
#include "support/scratch.hpp"
#include "synthetic_recording.hpp"
#include "zip_writer.hpp"

namespace bookspin::fit {
namespace {

test::SyntheticRecording small_recording() {
  return test::make_recording(test::phone_alone(),
                              {{{0.3, 14.0, 0.5}, 1.0}, {{0.3, 14.0, 0.5}, 1.0}});
}

void expect_same_samples(const GyroRecording& read, const test::SyntheticRecording& written) {
  ASSERT_EQ(read.t.size(), written.t.size());
  for (std::size_t i = 0; i < read.t.size(); i += 37) {
    EXPECT_NEAR(read.t[i], written.t[i], 1e-8 * (1 + written.t[i]));
    EXPECT_LT((read.omega[i] - written.omega[i]).norm(), 1e-7 * (1 + written.omega[i].norm()));
  }
  ASSERT_EQ(read.pauses.size(), written.pauses.size());
  EXPECT_NEAR(read.pauses[0], written.pauses[0], 1e-8);
}

TEST(Recording, ReadsEachPhyphoxDialectFromItsFolder) {
  const test::SyntheticRecording written = small_recording();
  const auto dir = bookspin::test::fresh_dir("fit/dialects");
  for (auto [dialect, name] :
       {std::pair{test::Dialect::comma, "comma"}, std::pair{test::Dialect::tab, "tab"},
        std::pair{test::Dialect::semicolon, "semicolon"}}) {
    const auto folder = dir / (std::string("Gyroscope rotation rate ") + name);
    test::write_export(folder, written, dialect);
    const GyroRecording by_folder = read_recording(folder);
    expect_same_samples(by_folder, written);
    // A folder's name is the recording's, its spaces kept (common/file_name.hpp).
    EXPECT_EQ(by_folder.name, std::string("Gyroscope rotation rate ") + name);
    expect_same_samples(read_recording(folder / "Raw Data.csv"), written);
  }
}

TEST(Recording, ReadsAZipOfTheFolder) {
  const test::SyntheticRecording written = small_recording();
  const auto dir = bookspin::test::fresh_dir("fit/zip");
  const auto path = dir / "toss.zip";
  test::write_zip(path, {{"toss/Raw Data.csv", test::raw_data_csv(written, test::Dialect::comma)},
                         {"toss/meta/time.csv", test::time_csv(written)}});
  const GyroRecording read = read_recording(path);
  expect_same_samples(read, written);
  EXPECT_EQ(read.name, "toss");
}

TEST(Recording, ReadsAPlainCsv) {
  const GyroRecording read = parse_gyro_csv(
      "t,wx,wy,wz\n0,1,2,3\n0.01,1.5,2,3\n0.02,1,2,3\n0.03,1,2,3\n0.04,1,2,3\n"
      "0.05,1,2,3\n0.06,1,2,3\n0.07,1,2,3\n0.08,1,2,3\n0.09,1,2,-3e-1\n",
      "plain.csv", "plain");
  ASSERT_EQ(read.t.size(), 10u);
  EXPECT_DOUBLE_EQ(read.omega[1][0], 1.5);
  EXPECT_DOUBLE_EQ(read.omega[9][2], -0.3);
  EXPECT_TRUE(read.pauses.empty());
}

/// The one line of the InputError that parsing `text` throws.
std::string error_of(const std::string& text) {
  try {
    parse_gyro_csv(text, "bad.csv", "bad");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

std::string rows(int n) {
  std::string text;
  for (int i = 0; i < n; ++i) text += std::to_string(0.01 * (i + 1)) + ",1,2,3\n";
  return text;
}

TEST(Recording, BadInputNamesFileRowAndColumn) {
  EXPECT_EQ(error_of("a,b,c\n1,2,3\n"),
            "bad.csv:1: header: not a gyroscope recording: expected phyphox's \"Time (s)\", "
            "\"Gyroscope x (rad/s)\", ... or t,wx,wy,wz");
  EXPECT_EQ(error_of("\"Time (s)\",\"Linear Acceleration x (m/s^2)\",\"y\",\"z\"\n" + rows(10))
                .substr(0, 20),
            "bad.csv:1: header: n");
  EXPECT_EQ(error_of("t,wx,wy,wz\n0,1,2,3\n" + rows(10) + "0.05,1,2,3\n"),
            "bad.csv:13: t: time does not increase (0.05 after the previous row's)");
  EXPECT_EQ(error_of("t,wx,wy,wz\n" + rows(3) + "0.5,1,nan,3\n" + "0.6,1,1,1\n"),
            "bad.csv:5: wy: not a finite number: \"nan\"");
  EXPECT_EQ(error_of("t,wx,wy,wz\n" + rows(3) + "0.5,1,fast,3\n"),
            "bad.csv:5: wy: not a number: \"fast\"");
  EXPECT_EQ(error_of("t,wx,wy,wz\n" + rows(3) + "0.5,1,2\n"),
            "bad.csv:5: a row of 3 cells, expected 4");
  EXPECT_EQ(error_of("t,wx,wy,wz\n" + rows(3)),
            "bad.csv: a gyroscope recording of 3 samples; at least 10 are needed");
  EXPECT_EQ(error_of(""), "bad.csv: not a gyroscope recording: the file is empty");
}

TEST(Recording, AMissingFileOrAFolderWithoutRawDataIsBadInput) {
  const auto dir = bookspin::test::fresh_dir("fit/missing");
  EXPECT_THROW(read_recording(dir / "nothing.csv"), InputError);
  EXPECT_THROW(read_recording(dir), InputError);
  std::ofstream(dir / "not.zip") << "plain text";
  EXPECT_THROW(read_recording(dir / "not.zip"), InputError);
}

TEST(Recording, AByteOrderMarkBeforeTheHeaderIsRead) {
  // Spreadsheets write a UTF-8 byte-order mark before the header: read past, as any CSV's.
  const std::string bom = "\xEF\xBB\xBF";
  const GyroRecording plain = parse_gyro_csv(bom + "t,wx,wy,wz\n0,1,2,3\n" + rows(9), "p.csv", "p");
  EXPECT_EQ(plain.t.size(), 10u);
  EXPECT_DOUBLE_EQ(plain.omega[0][2], 3.0);
  const GyroRecording phyphox = parse_gyro_csv(
      bom +
          "\"Time (s)\",\"Gyroscope x (rad/s)\",\"Gyroscope y (rad/s)\",\"Gyroscope z (rad/s)\"\n" +
          rows(10),
      "r.csv", "r");
  EXPECT_EQ(phyphox.t.size(), 10u);
  EXPECT_EQ(parse_time_csv(bom + "event,experiment time\nPAUSE,1.5\n", "time.csv"),
            std::vector<double>{1.5});
}

TEST(Recording, ALoneCrEndsALineAsLfAndCrLfDo) {
  // Some exporters still end lines with CR alone (the old Mac convention): read alike.
  const std::string lf = "t,wx,wy,wz\n0,1,2,3\n" + rows(9);
  std::string cr = lf, crlf;
  for (char& c : cr)
    if (c == '\n') c = '\r';
  for (char c : lf) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  const GyroRecording a = parse_gyro_csv(lf, "lf.csv", "lf");
  for (const std::string& text : {cr, crlf}) {
    const GyroRecording b = parse_gyro_csv(text, "x.csv", "x");
    EXPECT_EQ(b.t, a.t);
    ASSERT_EQ(b.omega.size(), a.omega.size());
    EXPECT_EQ(b.omega.back(), a.omega.back());
  }
  // The rows named in an error count lone CRs as line ends too.
  std::string bad = cr;
  bad.replace(bad.find("0.03"), 4, "0.0x");
  EXPECT_EQ(error_of(bad), "bad.csv:5: t: not a number: \"0.0x0000\"");
}

std::string read_error(const std::filesystem::path& path) {
  try {
    read_recording(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(Recording, AZipIsOneExportNotEmptyAndNoBomb) {
  const auto dir = bookspin::test::fresh_dir("fit/bad-zips");
  const std::string raw = test::raw_data_csv(small_recording(), test::Dialect::comma);
  test::write_zip(dir / "two.zip", {{"morning/Raw Data.csv", raw}, {"evening/Raw Data.csv", raw}});
  EXPECT_EQ(read_error(dir / "two.zip"),
            (dir / "two.zip").string() +
                ": holds 2 exports (\"morning/Raw Data.csv\", \"evening/Raw Data.csv\"): which "
                "one? Unzip it and give that export's folder");
  test::write_zip(dir / "empty.zip", {});
  EXPECT_EQ(read_error(dir / "empty.zip"),
            (dir / "empty.zip").string() + ": an empty zip (no file in it)");
  std::ofstream(dir / "nothing.zip").flush();
  EXPECT_EQ(read_error(dir / "nothing.zip"),
            (dir / "nothing.zip").string() + ": an empty file, not a zip file");
  // An entry that claims 4 GiB is refused on its claim, before a byte is inflated.
  test::write_zip(dir / "bomb.zip", {{"toss/Raw Data.csv", "t,wx,wy,wz\n"}},
                  std::uint64_t{4} << 30);
  EXPECT_EQ(read_error(dir / "bomb.zip"),
            (dir / "bomb.zip").string() +
                ": toss/Raw Data.csv: inflates to more than 256 MiB, more than a recording (a "
                "damaged zip, or not phyphox's)");
}

}  // namespace
}  // namespace bookspin::fit

namespace bookspin::fit {
namespace {

/// `written` as a whitespace-separated text export: '#' notes before the header and between
/// rows, the header `header` (its ω columns in `unit`'s scale: 1 rad/s each).
std::string text_export(const test::SyntheticRecording& written, const std::string& header,
                        double unit) {
  std::string text =
      "# exported by a gyroscope app\n#   sample rate: 415 Hz (nominal)\n" + header + "\n";
  char row[160];
  for (std::size_t i = 0; i < written.t.size(); ++i) {
    std::snprintf(row, sizeof row, "%.9f   %.9e\t%.9e  %.9e\n", written.t[i],
                  written.omega[i][0] / unit, written.omega[i][1] / unit,
                  written.omega[i][2] / unit);
    text += row;
    if (i == 10) text += "# the phone was picked up here\n";
  }
  return text;
}

// A text export with '#' notes and a unicode header is read as its numbers say; one in degrees
// per second that its header states is read in rad/s.
TEST(Recording, ReadsAWhitespaceSeparatedExportWithCommentsAndAUnicodeHeader) {
  const test::SyntheticRecording written = small_recording();
  const auto expect_samples = [&](const GyroRecording& read) {
    ASSERT_EQ(read.t.size(), written.t.size());
    for (std::size_t i = 0; i < read.t.size(); i += 7) {
      EXPECT_NEAR(read.t[i], written.t[i], 1e-8 * (1 + written.t[i]));
      EXPECT_LT((read.omega[i] - written.omega[i]).norm(), 1e-7 * (1 + written.omega[i].norm()));
    }
  };
  for (const std::string header : {"t (s)  ωₓ (rad/s)  ωᵧ (rad/s)  ω_z (rad/s)", "time  wx  wy  wz",
                                   "t(s)  ω_x(rad/s)  ω_y(rad/s)  ω_z(rad/s)"}) {
    const GyroRecording read =
        parse_gyro_csv(text_export(written, header, 1.0), "phone.txt", "phone");
    expect_samples(read);
  }
  const double degree = 3.14159265358979323846 / 180.0;
  expect_samples(parse_gyro_csv(
      text_export(written, "t (s)  ωₓ (°/s)  ωᵧ (°/s)  ω_z (°/s)", degree), "phone.txt", "phone"));
}

// A gyroscope app's text export as it writes it: its header the last '#' comment before the
// numbers, a time without its unit (seconds), ω's axes with modifier-letter and subscript
// names (ₓ U+2093, ᵧ U+1D67, ᶻ U+1DBB) and a fifth column, |ω|, checked against the three
// axes (it was "not a gyroscope recording").
TEST(Recording, ATextExportWithItsHeaderInACommentAndATotalColumnIsRead) {
  const test::SyntheticRecording written = small_recording();
  const auto with_total = [&](double total_scale) {
    std::string text = "#time  ωₓ (rad/s)  ωᵧ (rad/s)  ωᶻ (rad/s)  ω_total (rad/s)\n";
    char row[200];
    for (std::size_t i = 0; i < written.t.size(); ++i) {
      const Eigen::Vector3d& w = written.omega[i];
      std::snprintf(row, sizeof row, "%.6f\t%.5f\t%.5f\t%.5f\t%.5f\n", written.t[i], w[0], w[1],
                    w[2], total_scale * w.norm());
      text += row;
    }
    return text;
  };
  const GyroRecording read = parse_gyro_csv(with_total(1.0), "phone.txt", "phone");
  ASSERT_EQ(read.t.size(), written.t.size());
  for (std::size_t i = 0; i < read.t.size(); i += 7) {
    EXPECT_NEAR(read.t[i], written.t[i], 1e-6);
    EXPECT_LT((read.omega[i] - written.omega[i]).norm(), 1e-4);
  }
  // |ω| that is not the three axes' (another unit, another column): refused at its first row.
  const std::string wrong = error_of(with_total(180.0 / M_PI));
  EXPECT_EQ(wrong.rfind("bad.csv:2: ω_total (rad/s): |ω| is ", 0), 0u) << wrong;
  EXPECT_NE(wrong.find("the columns do not hold what the header says"), std::string::npos) << wrong;
  // The same header as a line of its own, and as a comment before a comment.
  EXPECT_EQ(error_of("time  ωₓ (rad/s)  ωᵧ (rad/s)  ωᶻ (rad/s)  ω_total (rad/s)\n" +
                     std::string("0.1 1 2 2 3\n0.2 1 2 2 3\n")),
            "bad.csv: a gyroscope recording of 2 samples; at least 10 are needed");
  EXPECT_EQ(error_of("# app v2\n#time  ωₓ (rad/s)  ωᵧ (rad/s)  ωᶻ (rad/s)\n0.1 1 2 2\n"),
            "bad.csv: a gyroscope recording of 1 samples; at least 10 are needed");
  // A fifth column that is not |ω| is not read as it.
  EXPECT_NE(error_of("#time  ωₓ (rad/s)  ωᵧ (rad/s)  ωᶻ (rad/s)  T (K)\n" + rows(10))
                .find("not a gyroscope recording"),
            std::string::npos);
}

// The |ω| column's own allowance, a printed value's rounding (1 % and 0.01 rad/s): the same
// samples with |ω| printed to 2, 3 or 5 decimals read alike (a still phone's 0.0037 rad/s printed
// "0.00" is rounding, not another unit), and so does |ω| 0.0099 rad/s off; 0.0102 rad/s off at
// rest (past 1 % of 0.014 and 0.01) is refused at its first row.
TEST(Recording, TheTotalColumnIsCheckedToItsPrintedRoundingAndNoFurther) {
  std::vector<Eigen::Vector3d> omega;
  for (int i = 0; i < 40; ++i)
    omega.emplace_back(i < 20 ? Eigen::Vector3d(0.003, -0.002, 0.001)
                              : Eigen::Vector3d(1.5 + 0.1 * i, -12.0, 0.4));
  const auto text = [&](int decimals, double off) {
    std::string csv = "t,wx,wy,wz,|w|\n";
    char row[200];
    for (std::size_t i = 0; i < omega.size(); ++i) {
      const Eigen::Vector3d& w = omega[i];
      std::snprintf(row, sizeof row, "%.3f,%.6f,%.6f,%.6f,%.*f\n", 0.01 * i, w[0], w[1], w[2],
                    decimals, w.norm() + off);
      csv += row;
    }
    return csv;
  };
  const GyroRecording five = parse_gyro_csv(text(5, 0.0), "ok.csv", "ok");
  for (int decimals : {2, 3}) {
    const GyroRecording read = parse_gyro_csv(text(decimals, 0.0), "ok.csv", "ok");
    EXPECT_EQ(read.omega, five.omega) << decimals;
  }
  EXPECT_EQ(parse_gyro_csv(text(5, 0.0099), "ok.csv", "ok").omega, five.omega);
  const std::string past = error_of(text(5, 0.0102));
  EXPECT_EQ(past.rfind("bad.csv:2: |w|: |ω| is ", 0), 0u) << past;
}

// One axis in °/s beside two in rad/s (a column converted by hand under phyphox's header, or a
// text export's) is named at reading, by the |ω| column the export writes beside the axes:
// taken in °/s, that axis makes the norm agree (it ended in "the fit did not converge").
TEST(Recording, MixedUnitsAreNamedAtReadingByTheNormColumn) {
  const test::SyntheticRecording written = small_recording();
  for (int axis = 0; axis < 3; ++axis) {
    test::SyntheticRecording mixed = written;
    for (Eigen::Vector3d& w : mixed.omega) w[axis] *= 180.0 / M_PI;
    std::string text = test::raw_data_csv(mixed, test::Dialect::comma);
    // The Absolute column as the phone wrote it: the norm in rad/s.
    std::string fixed;
    std::size_t at = 0;
    for (std::size_t row = 0; at < text.size(); ++row) {
      const std::size_t end = text.find('\n', at);
      std::string line = text.substr(at, end - at);
      if (row > 0) {
        char cell[64];
        std::snprintf(cell, sizeof cell, "%.9E", written.omega[row - 1].norm());
        line = line.substr(0, line.rfind(',') + 1) + cell;
      }
      fixed += line + "\n";
      at = end + 1;
    }
    const std::string error = error_of(fixed);
    const std::string column = std::string("Gyroscope ") + "xyz"[axis] + " (rad/s)";
    EXPECT_NE(error.find("mixed units? " + column + " holds °/s, not the unit its header says"),
              std::string::npos)
        << error;
    EXPECT_EQ(error.rfind("bad.csv:", 0), 0u) << error;
  }
  // The export as written reads.
  EXPECT_EQ(parse_gyro_csv(test::raw_data_csv(written, test::Dialect::semicolon), "ok.csv", "ok")
                .t.size(),
            written.t.size());
}

// Stamps a double cannot tell apart (1e15 + 0.011, 1e15 + 0.021: both read as 1e15, whose step
// is 0.125 s) are refused saying so: they do increase, in the file. Stamps that truly repeat or
// go back, however written, are "time does not increase".
TEST(Recording, StampsADoubleCannotTellApartAreRefusedSayingSo) {
  std::string text = "t,wx,wy,wz\n";
  for (int i = 0; i < 8; ++i)
    text += "1000000000000000.0" + std::to_string(11 + 10 * i) + ",1,2,3\n";
  EXPECT_EQ(error_of(text),
            "bad.csv:3: t: time 1000000000000000.021 is after the previous row's "
            "1000000000000000.011 in the file, but a double cannot tell them apart: both read as "
            "1e+15 s, where a double's step is 0.125 s (subtract the first time from every time, "
            "or write them as offsets)");
  // However its exponent is written: e15, e+15, E+015.
  for (const char* exponent : {"e15", "e+15", "E+015"})
    EXPECT_NE(
        error_of("t,wx,wy,wz\n1e15,1,2,3\n1.00000000000000001" + std::string(exponent) + ",1,2,3\n")
            .find("a double cannot tell them apart"),
        std::string::npos)
        << exponent;
  for (const char* later : {"0.5", "0.50", "5e-1", "0.4999", "-0.6"})
    EXPECT_EQ(error_of("t,wx,wy,wz\n0.5,1,2,3\n" + std::string(later) + ",1,2,3\n"),
              "bad.csv:3: t: time does not increase (" + std::string(later) +
                  " after the previous row's)")
        << later;
  // A decimal comma's stamps compared as written too.
  EXPECT_NE(error_of("t;wx;wy;wz\n1000000000000000,011;1;2;3\n1000000000000000,021;1;2;3\n")
                .find("a double cannot tell them apart"),
            std::string::npos);
}

// The times' unit: a header that names it (ms, µs, ns) is converted to seconds, the same samples
// as in seconds to rounding; under a plain `t`, times whose median step is seconds or more (a
// phone samples every 1–40 ms) are refused naming the unit that puts the step within a
// gyroscope's, at every rate from 25 Hz to 10 kHz, through the file door and the arrays' door.
TEST(Recording, TimesInAnotherUnitAreConvertedWhereNamedAndRefusedNamingItWhereNot) {
  const test::SyntheticRecording written = small_recording();
  const GyroRecording seconds =
      parse_gyro_csv(test::raw_data_csv(written, test::Dialect::comma), "s.csv", "s");
  for (const auto& [unit, per_second] :
       {std::pair<const char*, double>{"ms", 1e3}, {"µs", 1e6}, {"us", 1e6}, {"ns", 1e9}}) {
    std::string text = "t (" + std::string(unit) + "),wx,wy,wz\n";
    std::string bare = "t,wx,wy,wz\n";
    char row[160];
    for (std::size_t i = 0; i < seconds.t.size(); ++i) {
      std::snprintf(row, sizeof row, "%.17g,%.17g,%.17g,%.17g\n", seconds.t[i] * per_second,
                    seconds.omega[i][0], seconds.omega[i][1], seconds.omega[i][2]);
      text += row;
      bare += row;
    }
    const GyroRecording read = parse_gyro_csv(text, "u.csv", "u");
    ASSERT_EQ(read.t.size(), seconds.t.size()) << unit;
    for (std::size_t i = 0; i < read.t.size(); ++i)
      ASSERT_NEAR(read.t[i], seconds.t[i], 1e-12 * (1 + seconds.t[i])) << unit << " row " << i;
    const std::string said = error_of(bare);
    const std::string expected_unit = per_second == 1e3 ? "ms" : per_second == 1e6 ? "µs" : "ns";
    EXPECT_EQ(said.find("bad.csv:1: t: the samples lie "), 0u) << said;
    EXPECT_NE(said.find("are the times in " + expected_unit + "?"), std::string::npos) << said;
  }
  // At 25 Hz, 100 Hz, 1 kHz and 10 kHz in ms: each named; in seconds, each read.
  for (double rate : {25.0, 100.0, 1000.0, 10000.0}) {
    std::vector<double> t_s, t_ms;
    std::vector<Eigen::Vector3d> omega;
    for (int i = 0; i < 50; ++i) {
      t_s.push_back(i / rate);
      t_ms.push_back(1e3 * i / rate);
      omega.emplace_back(1.0, 2.0, 3.0);
    }
    EXPECT_NO_THROW(samples_recording("ok", t_s, omega)) << rate;
    if (1e3 / rate > kMaxSampleStep) {
      try {
        samples_recording("anna", t_ms, omega);
        ADD_FAILURE() << "times in ms read as seconds at " << rate << " Hz";
      } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("anna: t: the samples lie"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("in ms?"), std::string::npos) << e.what();
      }
    }
  }
}

// Quoted cells as RFC 4180 reads them: a header's names, and meta/device.csv's cells holding
// the separator ("BMI160, Bosch") before its range row.
TEST(Recording, QuotedCellsAreReadAsACsvReaderReadsThem) {
  const GyroRecording read = parse_gyro_csv(
      "\"t\",\"wx\",\"wy\",\"wz\"\n" + rows(9) + "\"0.5\",\"1\",\" 2 \",3\n", "q.csv", "q");
  ASSERT_EQ(read.t.size(), 10u);
  EXPECT_EQ(read.omega[9], Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(
      parse_device_csv("\"property\",\"value\"\n\"gyroscope Name\",\"BMI160, \"\"Bosch\"\"\"\n"
                       "\"gyroscope\nRemark\",\"two, lines\"\n\"gyroscope Range\",\"34.906586\"\n",
                       "device.csv"),
      34.906586);
  try {
    parse_device_csv("\"property\",\"value\"\n\"a\",\"b\n\"gyroscope Range\",\"34.9\"\"\n",
                     "device.csv");
    ADD_FAILURE() << "an unclosed quote was read";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(),
                 "device.csv:2: a quoted cell opens on this row and is not closed by the end of "
                 "the file");
  }
}

// A whitespace-separated table it cannot read is refused naming that dialect and what it expects.
TEST(Recording, AWhitespaceSeparatedTableOfOtherColumnsIsRefusedNamingTheDialect) {
  EXPECT_EQ(error_of("# accelerometer\nt (s)  ax (m/s^2)  ay (m/s^2)  az (m/s^2)\n" + rows(10)),
            "bad.csv:2: header: not a gyroscope recording: a whitespace-separated table whose 4 "
            "column names are not time (s) and ω about x, y, z (rad/s or °/s), as \"t (s)  ωₓ "
            "(rad/s)  ωᵧ (rad/s)  ω_z (rad/s)\"");
  // ω in a unit it does not know is not read as rad/s.
  EXPECT_NE(error_of("t (s)  ωₓ (rpm)  ωᵧ (rpm)  ω_z (rpm)\n" + rows(10)).find("whitespace"),
            std::string::npos);
}

// The times' unit is judged by the median step: a recording in seconds paused and resumed (20
// minutes, an hour) has one step that long and is no more "in another unit" than without it,
// wherever the pause falls (the mean step would be seconds; the median is the rate's).
TEST(Recording, APauseOfMinutesDoesNotMakeSecondsAnotherUnit) {
  std::vector<double> t;
  std::vector<Eigen::Vector3d> omega;
  for (int i = 0; i < 200; ++i) t.push_back(0.01 * i), omega.emplace_back(0.1, 0.2, 0.3);
  ASSERT_EQ(time_unit_cause(t), "");
  for (double pause : {60.0, 1200.0, 3600.0})
    for (std::size_t at : {std::size_t{1}, std::size_t{100}, std::size_t{199}}) {
      std::vector<double> paused = t;
      for (std::size_t i = at; i < paused.size(); ++i) paused[i] += pause;
      EXPECT_EQ(time_unit_cause(paused), "") << pause << " s at " << at;
      EXPECT_NO_THROW(samples_recording("paused", paused, omega)) << pause << " s at " << at;
      std::string text = "t,wx,wy,wz\n";
      for (double s : paused) text += std::to_string(s) + ",0.1,0.2,0.3\n";
      EXPECT_NO_THROW(parse_gyro_csv(text, "p.csv", "p")) << pause << " s at " << at;
    }
}

// A header's µ is read as micro whichever of the two characters it is: the micro sign (U+00B5)
// or the Greek small letter mu (U+03BC) that many keyboards and fonts give for it; the same
// samples either way, and as "us".
TEST(Recording, AHeadersGreekMuIsMicroAsTheMicroSignIs) {
  std::string body;
  for (int i = 0; i < 20; ++i) body += std::to_string(10000 * i) + ",0.1,0.2,0.3\n";
  const GyroRecording us = parse_gyro_csv("t (us),wx,wy,wz\n" + body, "u.csv", "u");
  for (const char* unit : {"\u00b5s", "\u03bcs"}) {
    const GyroRecording read =
        parse_gyro_csv("t (" + std::string(unit) + "),wx,wy,wz\n" + body, "m.csv", "m");
    EXPECT_EQ(read.t, us.t) << unit;
    EXPECT_DOUBLE_EQ(read.t[1], 0.01) << unit;
  }
}

// A quote left open names the line its cell closes on, whatever the file's line ends: a Windows
// (CRLF) recording counts each "\r\n" once, as LF and a lone CR do, in a data row and the header.
TEST(Recording, AQuoteLeftOpenNamesTheSameLineWhateverTheLineEnds) {
  std::string lf = "\"t\",\"wx\",\"wy\",\"wz\"\n";
  for (int i = 0; i < 12; ++i) {
    lf += '"';
    lf += std::to_string(0.01 * i);
    lf += "\",\"1\",\"2\",\"3";
    if (i != 6) lf += '"';
    lf += '\n';
  }
  const auto ends = [](const std::string& text, const std::string& end) {
    std::string out;
    for (char c : text) out += c == '\n' ? end : std::string(1, c);
    return out;
  };
  const std::string said = error_of(lf);
  EXPECT_EQ(said,
            "bad.csv:8: wz: a quote opens a cell on this row (\"3\" and the line's end) and closes "
            "it on line 9: a quote left open?");
  EXPECT_EQ(error_of(ends(lf, "\r\n")), said);
  EXPECT_EQ(error_of(ends(lf, "\r")), said);
  // Two blank lines after the open quote: the cell closes two lines further on, counted once.
  std::string spaced = lf;
  spaced.insert(spaced.find("3\n") + 2, "\n\n");
  const std::string further = error_of(spaced);
  EXPECT_NE(further.find("closes it on line 11"), std::string::npos) << further;
  EXPECT_EQ(error_of(ends(spaced, "\r\n")), further);
}

// A quote left open in the header row is named as a data row's is (not "not a gyroscope
// recording": the header's last name ran on into the rows).
TEST(Recording, AQuoteLeftOpenInTheHeaderIsNamedAsInARow) {
  const std::string open = "\"t\",\"wx\",\"wy\",\"wz\n" + rows(12) + "\"0.5\",1,2,3\n";
  const std::string said = error_of(open);
  EXPECT_EQ(said.find("bad.csv:1: header: a quote opens a cell on this row (\"wz\" and the line's "
                      "end) and closes it on line "),
            0u)
      << said;
  EXPECT_NE(said.find("a quote left open?"), std::string::npos) << said;
  std::string crlf;
  for (char c : open) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  EXPECT_EQ(error_of(crlf), said);
}

// Times in one unit under a header naming another: the likely unit is the one that puts the
// step within a gyroscope's, told in the header's terms (µs under "t (ms)", not ms again).
TEST(Recording, TimesInAnotherUnitThanTheHeadersNameTheLikelyUnit) {
  for (const auto& [header, per_second, likely] :
       {std::tuple<const char*, double, const char*>{"t (ms)", 1e6, "µs"},
        {"t (ms)", 1e9, "ns"},
        {"t (us)", 1e9, "ns"},
        {"t (s)", 1e3, "ms"}}) {
    std::string text = std::string(header) + ",wx,wy,wz\n";
    for (int i = 0; i < 20; ++i) text += std::to_string(0.01 * i * per_second) + ",0.1,0.2,0.3\n";
    const std::string said = error_of(text);
    EXPECT_NE(said.find("are the times in " + std::string(likely) + "?"), std::string::npos)
        << header << ": " << said;
    EXPECT_NE(said.find("(\"t (" + std::string(likely) + ")\")"), std::string::npos)
        << header << ": " << said;
  }
}

// A number past the largest double is said to be so, in a recording's cell (not "not a
// number") and at the arrays' door (an infinity a float made of it), in the words the options
// and flipcheck's motion reader use.
TEST(Recording, ANumberBeyondTheDoublesIsSaidToBeSo) {
  EXPECT_EQ(error_of("t,wx,wy,wz\n" + rows(3) + "0.5,1,1e400,3\n" + rows(8)),
            "bad.csv:5: wy: \"1e400\" is beyond the largest finite number (about 1.8e308)");
  EXPECT_EQ(error_of("t;wx;wy;wz\n0,5;1;-2,5e308;3\n" + std::string("0,6;1;2;3\n")),
            "bad.csv:2: wy: \"-2,5e308\" is beyond the largest finite number (about 1.8e308)");
  EXPECT_EQ(error_of("t,wx,wy,wz\n" + rows(3) + "0.5,1,1e-400x,3\n"),
            "bad.csv:5: wy: not a number: \"1e-400x\"");
  std::vector<double> t;
  std::vector<Eigen::Vector3d> omega;
  for (int i = 0; i < 12; ++i) t.push_back(0.01 * i), omega.emplace_back(1, 2, 3);
  omega[4][1] = HUGE_VAL;
  try {
    samples_recording("arrays", t, omega);
    ADD_FAILURE() << "an infinity was read";
  } catch (const InputError& e) {
    // A value, not text (Python's float("2e308")): named as any infinity is.
    EXPECT_STREQ(e.what(), "arrays: omega[4]: inf is not a finite number");
  }
  // Below the smallest double: named so, not "not a number" (it would read as 0).
  EXPECT_EQ(error_of("t,wx,wy,wz\n" + rows(3) + "0.5,1,1e-400,3\n" + rows(8)),
            "bad.csv:5: wy: \"1e-400\" is below the smallest positive number (about 4.9e-324): it "
            "would read as 0");
  EXPECT_TRUE(beyond_doubles("2e308"));
  EXPECT_TRUE(beyond_doubles("-1e400"));
  for (const char* text : {"1e308", "inf", "1e-400", "0x1p9999", "e400", "1e400x", ""})
    EXPECT_FALSE(beyond_doubles(text)) << text;
  EXPECT_TRUE(below_doubles("1e-400"));
  EXPECT_TRUE(below_doubles("-0.0001e-320"));
  for (const char* text : {"0", "0e-999", "-0.000", "1e-310", "2e308", "nan", "1e-400x", ""})
    EXPECT_FALSE(below_doubles(text)) << text;
}

}  // namespace
}  // namespace bookspin::fit
