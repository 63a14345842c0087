#include "bench/report.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <fstream>

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

// CSV fields: quoted when they hold a comma or a quote.
std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + '"';
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
  out << "section,metric,value,unit,note\n";
  for (const BenchRow& r : rows_) {
    char value[32];
    std::snprintf(value, sizeof value, "%.9g", r.value);
    out << csv_field(r.section) << ',' << csv_field(r.metric) << ',' << value << ','
        << csv_field(r.unit) << ',' << csv_field(r.note) << '\n';
  }
  out.close();
  if (!out) throw_output_error("cannot write", path, errno);
  file.commit();
}

}  // namespace bookspin::bench
