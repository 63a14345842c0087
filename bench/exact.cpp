// Bench section: the exact motion's evaluation per row (docs/physics.md §8, "How the code
// evaluates ω(t)"): ExactRotation::state(), from constants formed once per motion, against
// its BoostReference, the evaluation as it was (Boost's jacobi_elliptic twice and ellint_rj once a
// row), both timed in this run on the same rows; and jobs::exact_motion_at, what
// bookspin.exact_motion runs beneath Python, per row.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "bench/clock.hpp"
#include "bench/sections.hpp"
#include "jobs/exact_motion.hpp"
#include "physics/exact_solution.hpp"

namespace bookspin::bench {

namespace {

struct Motion {
  const char* name;
  Eigen::Vector3d moments, omega0;
};

// Both cases, a book's x spin with a jiggle (k = 0.99996) and a start near the separatrix.
const Motion kMotions[] = {
    {"(2, 1, 3), case A", {2.0, 1.0, 3.0}, {0.3, -0.5, 0.7}},
    {"(2, 1, 3), case B", {2.0, 1.0, 3.0}, {-0.6, 0.9, 0.2}},
    {"book, x spin with a 1e-3 jiggle", {0.0041667, 0.0016667, 0.0058333}, {0.114819, 1e-3, 1e-3}},
    {"(2, 1, 3), k' = 3e-6 (near the separatrix)", {2.0, 1.0, 3.0}, {1.0, 1e-6, 2e-6}},
};

constexpr long kRows = 100000;  // times 0 to 1000, every 0.01
constexpr int kRepetitions = 5;

double rows_checksum = 0.0;  // keeps the evaluations from being optimised away

template <typename Evaluate>
double best_us_per_row(Evaluate&& evaluate) {
  return 1e-3 * best_ns_per_step(
                    kRows, kRepetitions, [] {},
                    [&](long rows) {
                      for (long n = 0; n < rows; ++n)
                        rows_checksum += evaluate(0.01 * static_cast<double>(n));
                    });
}

}  // namespace

void bench_exact(const BenchContext& context) {
  BenchReport& report = *context.report;
  const std::string note = std::to_string(kRows) +
                           " rows, t = 0 to 1000 every 0.01, thread CPU time, best of " +
                           std::to_string(kRepetitions);
  double worst_now = 0.0, worst_before = 0.0, worst_ratio = 1e300;
  std::vector<double> times(kRows);
  for (long n = 0; n < kRows; ++n) times[n] = 0.01 * static_cast<double>(n);
  for (const Motion& m : kMotions) {
    const physics::ExactRotation exact(m.moments, m.omega0);
    const physics::ExactRotation::BoostReference boost = exact.boost_reference();
    const double before = best_us_per_row([&](double t) { return boost.state(t).q[0]; });
    const double now = best_us_per_row([&](double t) { return exact.state(t).q[0]; });
    const std::string name = m.name;
    report.add({"exact", name + ": state(), per-motion constants", now, "us/row", note});
    report.add({"exact", name + ": Boost, as before", before, "us/row", note});
    report.add({"exact", name + ": before / now", before / now, "x", note});
    worst_now = std::max(worst_now, now);
    worst_before = std::max(worst_before, before);
    worst_ratio = std::min(worst_ratio, before / now);
  }
  // What bookspin.exact_motion runs with the GIL released: checks, the rows, their vector.
  const Motion& book = kMotions[2];
  double at = 0.0;
  for (int r = 0; r < kRepetitions; ++r) {
    const double start = thread_cpu_seconds();
    const auto rows = jobs::exact_motion_at(book.moments, book.omega0, times, {});
    const double us = (thread_cpu_seconds() - start) * 1e6 / static_cast<double>(kRows);
    rows_checksum += rows.back().q[0];
    if (r == 0 || us < at) at = us;
  }
  report.add({"exact", std::string(book.name) + ": jobs::exact_motion_at (Python's work)", at,
              "us/row", note});
  report.add({"exact", "slowest motion: state()", worst_now, "us/row", note});
  report.add({"exact", "slowest motion: Boost, as before", worst_before, "us/row", note});
  report.add({"exact", "least speed-up", worst_ratio, "x", note});
  if (!std::isfinite(rows_checksum)) report.remark("exact: a row was not finite");
}

}  // namespace bookspin::bench
