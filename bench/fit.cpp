// Bench section: `bookspin fit`'s work on a long phone-toss recording (a phyphox `Raw Data.csv`
// at 500 Hz, made here from the exact motion with noise and bias) against reading the file
// alone, both timed in this run.
#include "fit/fit.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <string>

#include "bench/clock.hpp"
#include "bench/sections.hpp"
#include "physics/exact_solution.hpp"

namespace bookspin::bench {

namespace {

double wall_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

/// `minutes` of tosses of a phone taped on a book (moments 1 : 1.6 : 2.3, axes turned 20°),
/// each 1.2 s rest, a 0.15 s throw with spikes, a 1.2 s free flight of the exact motion about
/// the intermediate axis (ω0 varied toss to toss), a 0.12 s catch; `rate` Hz with ±10 %
/// jitter, noise 0.01 rad/s and a bias; written as phyphox's comma dialect. Returns the
/// number of tosses.
const Eigen::Vector3d kMoments(1.0, 1.6, 2.3);
const Eigen::Matrix3d kAxes =
    Eigen::AngleAxisd(20.0 * M_PI / 180.0, Eigen::Vector3d(1, 2, 3).normalized())
        .toRotationMatrix();

int write_recording(const std::filesystem::path& path, double minutes, double rate) {
  const Eigen::Vector3d& moments = kMoments;
  const Eigen::Matrix3d& axes = kAxes;
  const Eigen::Vector3d bias(0.021, -0.014, 0.008);
  std::mt19937 random(44);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::ofstream out(path, std::ios::binary);
  out << "\"Time (s)\",\"Gyroscope x (rad/s)\",\"Gyroscope y (rad/s)\",\"Gyroscope z "
         "(rad/s)\",\"Absolute (rad/s)\"\n";
  const double end = 60.0 * minutes;
  double t = 0.0;
  int tosses = 0;
  char line[160];
  const auto sample = [&](const Eigen::Vector3d& w) {
    const Eigen::Vector3d m =
        w + bias + 0.01 * Eigen::Vector3d(gauss(random), gauss(random), gauss(random));
    std::snprintf(line, sizeof line, "%.9E,%.9E,%.9E,%.9E,%.9E\n", t, m[0], m[1], m[2], m.norm());
    out << line;
    t += (1.0 + 0.1 * uniform(random)) / rate;
  };
  while (t < end) {
    const double rest_end = t + 1.2;
    while (t < rest_end) sample(Eigen::Vector3d::Zero());
    const Eigen::Vector3d w0(0.5 + 0.2 * uniform(random), 12.0 + 2.0 * uniform(random),
                             0.4 + 0.2 * uniform(random));
    const physics::ExactRotation exact(moments, w0, physics::ExactParts::omega_only);
    const double throw_start = t;
    while (t < throw_start + 0.15)
      sample((t - throw_start) / 0.15 * (axes * w0) +
             4.0 * Eigen::Vector3d(gauss(random), gauss(random), gauss(random)));
    const double flight_start = t;
    while (t < flight_start + 1.2) sample(axes * exact.omega_body(t - flight_start));
    const Eigen::Vector3d w_end = axes * exact.omega_body(1.2);
    const double catch_start = t;
    while (t < catch_start + 0.12)
      sample((1.0 - (t - catch_start) / 0.12) * w_end +
             6.0 * Eigen::Vector3d(gauss(random), gauss(random), gauss(random)));
    ++tosses;
  }
  const double final_rest = t + 1.2;
  while (t < final_rest) sample(Eigen::Vector3d::Zero());
  if (!out.flush()) throw std::runtime_error("bench: cannot write " + path.string());
  return tosses;
}

}  // namespace

void bench_fit(const BenchContext& context) {
  BenchReport& report = *context.report;
  const BenchOptions& options = context.options;
  const auto dir = context.scratch / "fit";
  std::filesystem::create_directories(dir);
  const auto csv = dir / "Raw Data.csv";
  const int tosses = write_recording(csv, options.fit_minutes, 500.0);
  char what[160];
  std::snprintf(what, sizeof what, "%.3g min at 500 Hz, %d tosses", options.fit_minutes, tosses);
  // The floor: the file read alone, best of three (it is short); the fit timed once.
  double read = 0.0;
  std::size_t samples = 0;
  for (int r = 0; r < 3; ++r) {
    const double start = wall_seconds();
    const fit::GyroRecording recording = fit::read_recording(csv);
    const double seconds = wall_seconds() - start;
    samples = recording.t.size();
    if (r == 0 || seconds < read) read = seconds;
  }
  const double start = wall_seconds(), cpu_start = process_cpu_seconds();
  const fit::GyroRecording recording = fit::pool_recordings({fit::read_recording(csv)});
  const fit::FlightSearch search = fit::find_flights(recording);
  const double found = wall_seconds();
  const fit::FitResult result = fit::fit_recording(recording, search);
  const double fitted = wall_seconds(), cpu = process_cpu_seconds() - cpu_start;
  const std::string note = std::string(what) + ", " + std::to_string(samples) + " samples, " +
                           std::to_string(result.tosses.size()) + " flights found";
  report.add({"fit", "read Raw Data.csv alone (the floor), wall clock", read, "s", note});
  report.add({"fit", "read, find the flights and fit, wall clock", fitted - start, "s", note});
  report.add({"fit", "read, find the flights and fit, CPU time of every thread", cpu, "s", note});
  // What the fit found against the truth, so that a faster fit is seen to be as good.
  double ratio_error = 0.0, axis_error = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double truth = kMoments[i] / kMoments[2];
    ratio_error = std::max(ratio_error, std::abs(result.body.ratios[i] - truth) / truth);
    const double c = std::abs(result.body.axes.col(i).dot(kAxes.col(i)));
    axis_error = std::max(axis_error, std::acos(std::min(1.0, c)) * 180.0 / M_PI);
  }
  report.add({"fit", "moment ratios' largest relative error", ratio_error, "fraction", note});
  report.add({"fit", "principal axes' largest error", axis_error, "deg", note});
  report.add({"fit", "find the flights / floor", (found - start - read) / read, "x", note});
  report.add({"fit", "read, find and fit / floor", (fitted - start) / read, "x", note});
}

}  // namespace bookspin::bench
