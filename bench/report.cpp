#include "bench/report.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <fstream>

#include "common/csv_writer.hpp"
#include "output/atomic_output.hpp"

namespace bookspin::bench {

namespace {

// Wide enough for "rigid-quaternion implicit-midpoint, orientation error".
constexpr const char* kLine = "%-10s  %-56s %12s %-8s %s\n";

std::string format_value(double value) {
  char text[32];
  if (!std::isfinite(value)) return "n/a";
  const double magnitude = std::abs(value);
  const char* pattern = magnitude != 0.0 && (magnitude < 1e-2 || magnitude >= 1e7) ? "%.3e"
                        : magnitude < 10.0                                         ? "%.3f"
                                                                                   : "%.1f";
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

}  // namespace

void BenchReport::add(BenchRow row) {
  if (rows_.empty()) std::printf(kLine, "section", "measurement", "value", "unit", "note");
  std::printf(kLine, row.section.c_str(), row.metric.c_str(), format_value(row.value).c_str(),
              row.unit.c_str(), row.note.c_str());
  std::fflush(stdout);
  rows_.push_back(std::move(row));
}

void BenchReport::remark(const std::string& text) const {
  std::printf("# %s\n", text.c_str());
  std::fflush(stdout);
}

void BenchReport::write_csv(const std::filesystem::path& path) const {
  output::AtomicFile file(path);
  std::ofstream out(file.temp_path(), std::ios::binary);
  CsvTable table{{"section", "metric", "value", "unit", "note"}, {}};
  for (const BenchRow& r : rows_) {
    // A measurement that could not be made (n/a on the screen) is an empty cell.
    const auto value = std::isfinite(r.value) ? std::optional<double>(r.value) : std::nullopt;
    table.rows.push_back({r.section, r.metric, CsvNumber{value, "%.9g"}, r.unit, r.note});
  }
  out << csv_text(table, "bench CSV");
  out.close();
  if (!out) throw_output_error("cannot write", path, errno);
  file.commit();
}

}  // namespace bookspin::bench
