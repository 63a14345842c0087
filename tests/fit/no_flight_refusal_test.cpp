// Where the finder finds no flight (docs/phone-lab.md, "How the flights are found"), the refusal
// says why in the data's terms (each stretch dropped, with its times and reason) and names the
// door's way to give the flights by hand: --tosses on the command line, the "Flights by hand"
// field on the page, tosses= in Python.
#include <gtest/gtest.h>

#include <string>

#include "common/errors.hpp"
#include "fit/pool.hpp"
#include "fit/report.hpp"

namespace bookspin::fit {
namespace {

/// 3 s at rest, then 0.2 s turning at 10 rad/s (too short a flight to fit), then rest: 100 Hz.
GyroRecording too_short() {
  std::vector<double> t;
  std::vector<Eigen::Vector3d> omega;
  for (int i = 0; i < 600; ++i) {
    t.push_back(0.01 * i);
    const bool turning = t.back() >= 3.0 && t.back() < 3.2;
    omega.push_back(turning ? Eigen::Vector3d(1.0, 10.0, 0.5) : Eigen::Vector3d(0.01, 0, -0.01));
  }
  return pool_recordings({samples_recording("short", t, omega)});
}

std::string refusal(Reader reader) {
  FitRequest request;
  request.reader = reader;
  try {
    fit_report(too_short(), request);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no refusal";
  return "";
}

TEST(NoFlightRefusal, SaysWhyInTheDataAndNamesTheDoorsHandRange) {
  const std::string cli = refusal(Reader::command_line), page = refusal(Reader::page),
                    python = refusal(Reader::python);
  for (const std::string& line : {cli, page, python}) {
    EXPECT_NE(line.find("no free flight found ("), std::string::npos) << line;
    EXPECT_NE(line.find(" s: "), std::string::npos) << line;  // a stretch's times and why
  }
  EXPECT_NE(cli.find("--tosses START:END"), std::string::npos) << cli;
  EXPECT_NE(page.find("\"Flights by hand (s)\" field"), std::string::npos) << page;
  EXPECT_EQ(page.find("--tosses"), std::string::npos) << page;
  EXPECT_NE(python.find("tosses=[(START, END)"), std::string::npos) << python;
  EXPECT_EQ(python.find("--tosses"), std::string::npos) << python;
}

}  // namespace
}  // namespace bookspin::fit
