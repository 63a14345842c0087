#pragma once
// The bench command's results: one row per measurement, printed on stdout as it arrives (a
// full bench takes minutes) and written as CSV at the end.
#include <filesystem>
#include <string>
#include <vector>

namespace bookspin::bench {

struct BenchRow {
  std::string section;  ///< pipeline, resolution, physics, memory
  std::string metric;   ///< what was measured
  double value = 0.0;
  std::string unit;  ///< s, frames/s, ns/step, rad, MiB, x (a ratio)
  std::string note;  ///< how it was measured
};

class BenchReport {
 public:
  /// Records `row` and prints it as a table line on stdout (the header before the first).
  void add(BenchRow row);
  /// A line of text in the table (a skipped section, a machine description).
  void remark(const std::string& text) const;
  /// section,metric,value,unit,note with a header line (common/csv_writer.hpp; value in %.9g,
  /// empty where it is not finite); throws OutputError.
  void write_csv(const std::filesystem::path& path) const;
  const std::vector<BenchRow>& rows() const { return rows_; }

 private:
  std::vector<BenchRow> rows_;
};

}  // namespace bookspin::bench
