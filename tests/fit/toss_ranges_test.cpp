// The tosses given by hand (--tosses; docs/phone-lab.md, "The flights by hand") on a recording
// made here: 100 samples 10 ms apart (t = 0, 0.01, ..., 0.99 s), a pause at 0.5 s. The limits
// are counted by hand: a toss needs 10 samples, never spans a pause, never shares an instant.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <tuple>

#include "common/errors.hpp"
#include "fit/fit_options.hpp"
#include "fit/flights.hpp"
#include "fit/pool.hpp"
#include "fit/recording.hpp"
#include "fit/report.hpp"

namespace bookspin::fit {
namespace {

/// The recording `name` (from `name`.csv) not yet pooled, turning at `omega` throughout.
GyroRecording unpooled(const std::string& name, const Eigen::Vector3d& omega) {
  GyroRecording recording;
  recording.name = name;
  recording.source = name + ".csv";
  for (int i = 0; i < 100; ++i) {
    recording.t.push_back(0.01 * i);
    recording.omega.push_back(omega);
  }
  recording.pauses = {0.505};
  return recording;
}

GyroRecording hundred_samples() {
  return pool_recordings({unpooled("hand", Eigen::Vector3d(0.01, -0.02, 0.03))});
}

std::string error_of(const GyroRecording& recording,
                     const std::vector<std::pair<double, double>>& ranges) {
  try {
    hand_flights(recording, ranges);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

/// parse_toss_ranges's one line for `text`, or "no error".
std::string parse_error(const std::string& text, const std::string& option = "--tosses") {
  try {
    parse_toss_ranges(text, option);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

using Ranges = std::vector<std::pair<double, double>>;

// The ranges as written, in the order given, each number as the compiler reads its literal;
// spaces around a number are allowed (the page's placeholder has them), and a blank text is
// no range at all (the flights are then found).
TEST(TossRanges, TheTextIsReadAsWritten) {
  EXPECT_EQ(parse_toss_ranges("1.82:2.71, 2.88:3.22"), (Ranges{{1.82, 2.71}, {2.88, 3.22}}));
  EXPECT_EQ(parse_toss_ranges("10.4:11.5,23.0:24.0"), (Ranges{{10.4, 11.5}, {23.0, 24.0}}));
  EXPECT_EQ(parse_toss_ranges(" 3 : 4 ,1e0:2.5e0"), (Ranges{{3.0, 4.0}, {1.0, 2.5}}));
  EXPECT_EQ(parse_toss_ranges("-0.5:0.25"), (Ranges{{-0.5, 0.25}}));
  EXPECT_TRUE(parse_toss_ranges("").empty());
  EXPECT_TRUE(parse_toss_ranges("  \t ").empty());
}

// A range that is not two numbers is one line naming the option (or the page's field) and the
// part at fault, trimmed.
TEST(TossRanges, TextThatIsNotRangesIsOneLineNamingTheOption) {
  EXPECT_EQ(parse_error("a:b"), "--tosses: \"a\" is not a number");
  EXPECT_EQ(parse_error("1:b"), "--tosses: \"b\" is not a number");
  EXPECT_EQ(parse_error("1.5"), "--tosses: \"1.5\" is not START:END");
  EXPECT_EQ(parse_error("1:2:3"), "--tosses: \"1:2:3\" is not START:END");
  EXPECT_EQ(parse_error("1:2,"), "--tosses: \"\" is not START:END");
  EXPECT_EQ(parse_error("1:2, 3"), "--tosses: \"3\" is not START:END");
  EXPECT_EQ(parse_error(":2"), "--tosses: \"\" is not a number");
  EXPECT_EQ(parse_error("nan:2"), "--tosses: \"nan\" is not a finite time (s)");
  EXPECT_EQ(parse_error("1:inf"), "--tosses: \"inf\" is not a finite time (s)");
  EXPECT_EQ(parse_error("1:1e309"),
            "--tosses: \"1e309\" is beyond the largest finite number (about 1.8e308)");
  EXPECT_EQ(parse_error("1,5:2", "flights by hand"),
            "flights by hand: \"1\" is not START:END (a decimal comma? write 1.5:2)");
}

// A decimal comma (a French or German student's "2,93") splits a number in two: the line says
// so and gives the text meant; where no such reading makes sense there is no hint.
TEST(TossRanges, ADecimalCommaIsNamedWithTheTextMeant) {
  EXPECT_EQ(parse_error("2,93:3,58", "flights by hand"),
            "flights by hand: \"2\" is not START:END (a decimal comma? write 2.93:3.58)");
  EXPECT_EQ(parse_error(" 1,82 : 2,71 , 2,88:3,22"),
            "--tosses: \"1\" is not START:END (a decimal comma? write 1.82 : 2.71 , 2.88:3.22)");
  EXPECT_EQ(parse_error("2,93"), "--tosses: \"2\" is not START:END");  // 2.93 is no range
  EXPECT_EQ(parse_error("1:2,a"), "--tosses: \"a\" is not START:END");
  EXPECT_EQ(parse_toss_ranges("1:2,3:4"), (Ranges{{1.0, 2.0}, {3.0, 4.0}}));  // commas between
}

// Ranges given as numbers (Python's pairs) meet the same judge as the text's: an end that is
// not finite is refused as such, whichever end and whichever door, before the recording is
// looked at (2.0:inf fitted 2.0–8.52 s through the landing; nan:2.9 was "the end is not after
// the start").
TEST(TossRanges, AnEndThatIsNotFiniteIsRefusedAsSuchByEveryDoor) {
  const GyroRecording recording = hundred_samples();
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const Reader reader : {Reader::command_line, Reader::page, Reader::python}) {
    const std::string name = tosses_name(reader);
    const auto hand_error = [&](const Ranges& ranges) {
      try {
        hand_flights(recording, ranges, name);
      } catch (const InputError& e) {
        return std::string(e.what());
      }
      return std::string("no error");
    };
    // An infinite value is named as the text "inf" is, at every door (Python's float of "2e308"
    // included: its text is gone before the fit sees it).
    EXPECT_EQ(hand_error({{0.2, inf}}), name + ": \"inf\" is not a finite time (s)");
    EXPECT_EQ(hand_error({{nan, 0.29}}), name + ": \"nan\" is not a finite time (s)");
    EXPECT_EQ(hand_error({{0.1, 0.3}, {-inf, 0.05}}), name + ": \"-inf\" is not a finite time (s)");
    // The text says the same cause for the same values, quoting the text as given.
    EXPECT_EQ(parse_error("0.2:inf", name), name + ": \"inf\" is not a finite time (s)");
    EXPECT_EQ(parse_error("0.2:Infinity", name), name + ": \"Infinity\" is not a finite time (s)");
    EXPECT_EQ(parse_error("nan:0.29", name), hand_error({{nan, 0.29}}));
    EXPECT_EQ(parse_error("0.2:2e308", name),
              name + ": \"2e308\" is beyond the largest finite number (about 1.8e308)");
    EXPECT_EQ(parse_error("1e-400:0.29", name),
              name +
                  ": \"1e-400\" is below the smallest positive number (about 4.9e-324): it would "
                  "read as 0");
  }
  EXPECT_EQ(tosses_name(Reader::python), std::string("tosses"));
}

// A time far beyond the recording is refused with its few digits, not 309 of them.
TEST(TossRanges, AHugeTimeIsPrintedInItsShortestForm) {
  const GyroRecording recording = hundred_samples();
  EXPECT_EQ(error_of(recording, {{1e308, 1.5e308}}),
            "--tosses 1e+308:1.5e+308: 0 samples of hand.csv in it; a toss needs at least 10");
  EXPECT_EQ(error_of(recording, {{1e308, 1e307}}),
            "--tosses 1e+308:1e+307: the end is not after the start");
  EXPECT_EQ(toss_time_text(2.93), "2.930");
  EXPECT_EQ(toss_time_text(-999999.5), "-999999.500");
  EXPECT_EQ(toss_time_text(1234567.25), "1234567.25");
}

// The fit's other options that the command line and Python both take, read and judged by one
// reader each (fit_options.hpp), naming each door's argument.
TEST(FitOptions, MomentsAndDragAreJudgedAlikeNamingEachDoorsArgument) {
  const auto moments_error = [](const std::string& text, const std::string& name) {
    try {
      parse_moments(text, name);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const auto values_error = [](const Eigen::Vector3d& m, const std::string& name) {
    try {
      check_moments(m, name);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(parse_moments(" 1, 2.5 ,3e0", "--moments"), Eigen::Vector3d(1, 2.5, 3));
  EXPECT_EQ(moments_error("1,2", "--moments"), "--moments: expected I1,I2,I3");
  EXPECT_EQ(moments_error("1,a,3", "--moments"), "--moments: \"a\" is not a number");
  // A moment past the largest double: its text named so where the door read it ("2e308");
  // the infinity a float made of it (Python's reader) named as the text "inf" is.
  const std::string beyond =
      " is beyond the largest finite number (about 1.8e308): not a positive finite number";
  EXPECT_EQ(moments_error("1,1,2e308", "--moments"), "--moments: \"2e308\"" + beyond);
  EXPECT_EQ(moments_error("1,1,-2e308", "--moments"), "--moments: \"-2e308\"" + beyond);
  EXPECT_EQ(values_error({1, 1, HUGE_VAL}, "moments"),
            "moments: \"inf\" is not a positive finite number");
  EXPECT_EQ(
      moments_error("1,1,1e-400", "--moments"),
      "--moments: \"1e-400\" is below the smallest positive number (about 4.9e-324): it would "
      "read as 0: not a positive finite number");
  EXPECT_EQ(moments_error("1,1,inf", "--moments"),
            "--moments: \"inf\" is not a positive finite number");
  for (const auto& [text, values, cause] :
       std::initializer_list<std::tuple<const char*, Eigen::Vector3d, const char*>>{
           {"1,2,-1", {1, 2, -1}, "\"-1\" is not a positive finite number"},
           {"0,2,3", {0, 2, 3}, "\"0\" is not a positive finite number"},
           {"nan,2,3", {std::nan(""), 2, 3}, "\"nan\" is not a positive finite number"}}) {
    EXPECT_EQ(moments_error(text, "--moments"), std::string("--moments: ") + cause) << text;
    EXPECT_EQ(values_error(values, "moments"), std::string("moments: ") + cause) << text;
  }
  // The triangle inequality, in any order; a flat body's equality, typed in decimals, holds.
  const std::string no_body =
      ": no rigid body has these principal moments (the two smaller sum to at least the largest)";
  EXPECT_EQ(values_error({1e-300, 1, 1e300}, "moments"), "moments: 1e-300 + 1 < 1e+300" + no_body);
  EXPECT_EQ(moments_error("3,1,1.5", "--moments"), "--moments: 1 + 1.5 < 3" + no_body);
  EXPECT_EQ(values_error({0.1, 0.3, 0.2}, "moments"), "no error");
  EXPECT_EQ(values_error({1, 2, 3}, "moments"), "no error");
  EXPECT_EQ(values_error({1, 1, 2.0000001}, "moments"), "moments: 1 + 1 < 2.0000001" + no_body);
  EXPECT_EQ(parse_drag_option("quadratic", "drag"), physics::DragLaw::quadratic);
  for (const Reader reader : {Reader::command_line, Reader::page, Reader::python}) {
    const std::string name = fit_option_names(reader).drag;
    try {
      parse_drag_option("cubic", name);
      ADD_FAILURE() << "cubic was taken";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()), name + ": \"cubic\" is not none, linear or quadratic");
    }
  }
}

// "2:1" is read (it is two numbers); the recording's judge refuses it as reversed, naming the
// option it was given under, as every other refusal of a range.
TEST(TossRanges, AReversedRangeIsRefusedByTheRecordingsJudge) {
  const GyroRecording recording = hundred_samples();
  const std::string field = tosses_name(Reader::page);
  const Ranges ranges = parse_toss_ranges("0.3:0.2", field);
  EXPECT_EQ(ranges, (Ranges{{0.3, 0.2}}));
  try {
    hand_flights(recording, ranges, field);
    ADD_FAILURE() << "a reversed range was taken";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "flights by hand 0.300:0.200: the end is not after the start");
  }
  EXPECT_EQ(error_of(recording, parse_toss_ranges("2:1")),
            "--tosses 2.000:1.000: the end is not after the start");
}

// The report names the flights by hand in its reader's terms: the option for the command
// line, the field for the page; with two recordings pooled it refuses them in those terms.
TEST(TossRanges, TheReportNamesTheFlightsByHandInItsReadersTerms) {
  const GyroRecording one = hundred_samples();
  FitRequest request;
  request.tosses = {{0.095, 0.185}};
  for (const Reader reader : {Reader::command_line, Reader::page}) {
    request.reader = reader;
    const std::string name = reader == Reader::page ? "flights by hand" : "--tosses";
    try {
      fit_report(one, request);
      ADD_FAILURE() << "nine samples were fitted";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()),
                name + " 0.095:0.185: 9 samples of hand.csv in it; a toss needs at least 10");
    }
    const GyroRecording two =
        pool_recordings({unpooled("hand", Eigen::Vector3d(0.01, -0.02, 0.03)),
                         unpooled("other", Eigen::Vector3d(0.02, 0.01, -0.01))});
    try {
      fit_report(two, request);
      ADD_FAILURE() << "flights by hand were fitted in two recordings";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()),
                name + ": with one recording only (the times are that recording's)");
    }
  }
}

// 0.095–0.195 s holds the samples at 0.10, ..., 0.19 s: ten, the fewest a toss may have; one
// fewer (to 0.185 s) is refused with the count.
TEST(TossRanges, TenSamplesAreATossAndNineAreNot) {
  const GyroRecording recording = hundred_samples();
  const FlightSearch ten = hand_flights(recording, {{0.095, 0.195}});
  ASSERT_EQ(ten.flights.size(), 1u);
  EXPECT_EQ(ten.flights[0].first, 10);
  EXPECT_EQ(ten.flights[0].last, 19);
  EXPECT_EQ(error_of(recording, {{0.095, 0.185}}),
            "--tosses 0.095:0.185: 9 samples of hand.csv in it; a toss needs at least 10");
}

// A range across the pause (0.505 s) is refused, naming the first sample after it; ranges on
// either side of it are tosses.
TEST(TossRanges, ARangeAcrossAPauseIsRefused) {
  const GyroRecording recording = hundred_samples();
  EXPECT_EQ(error_of(recording, {{0.395, 0.605}}),
            "--tosses 0.395:0.605: spans a pause or a gap of hand.csv (at 0.510 s)");
  EXPECT_EQ(hand_flights(recording, {{0.295, 0.495}, {0.515, 0.715}}).flights.size(), 2u);
}

}  // namespace
}  // namespace bookspin::fit
