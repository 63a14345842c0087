#include "jobs/sweep_csv.hpp"

#include <algorithm>
#include <optional>
#include <string_view>

#include "common/errors.hpp"
#include "output/finite_number.hpp"

namespace bookspin::jobs {

namespace {

/// A measure's cell: empty where the run does not reach it (no flip), else its value, checked
/// finite on the way out (output/finite_number.hpp).
std::string cell(const std::optional<double>& v, std::string_view column) {
  return v ? full_precision(output::finite(*v, "sweep CSV column " + std::string(column)))
           : std::string();
}

}  // namespace

MeasureList parse_measures(const std::string& text) {
  MeasureList measures;
  for (const std::string& name : csv_cells(text)) {
    const analysis::Measure* found = analysis::find_measure(name);
    if (!found) {
      throw InputError("--measure " + text + ": unknown measure '" + name + "' (" +
                       analysis::measure_names() + ")");
    }
    if (std::find(measures.begin(), measures.end(), found) != measures.end())
      throw InputError("--measure " + text + ": '" + name + "' is given twice");
    measures.push_back(found);
  }
  return measures;
}

std::vector<std::string> sweep_csv_header(const std::vector<VaryRange>& ranges,
                                          const MeasureList& measures) {
  std::vector<std::string> header;
  for (const auto& r : ranges) header.push_back(r.key);
  for (const analysis::Measure* m : measures) header.emplace_back(m->name);
  for (const analysis::Measure* m : measures)
    if (m->exact) header.emplace_back(m->exact_name);
  return header;
}

std::vector<std::string> sweep_row_cells(const std::vector<double>& point,
                                         const MeasureList& measures,
                                         const analysis::RunMeasures& m) {
  std::vector<std::string> cells;
  for (double v : point) cells.push_back(full_precision(output::finite(v, "sweep grid value")));
  for (const analysis::Measure* measure : measures)
    cells.push_back(cell(m.*(measure->value), measure->name));
  for (const analysis::Measure* measure : measures)
    if (measure->exact) cells.push_back(cell(m.*(measure->exact), measure->exact_name));
  return cells;
}

std::string csv_line(const std::vector<std::string>& cells, const std::string& first) {
  std::string line = first;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (i > 0 || !first.empty()) line += ',';
    line += cells[i];
  }
  return line;
}

std::vector<std::string> csv_cells(const std::string& line) {
  std::vector<std::string> cells;
  std::size_t start = 0;
  for (std::size_t comma; (comma = line.find(',', start)) != std::string::npos; start = comma + 1)
    cells.push_back(line.substr(start, comma - start));
  cells.push_back(line.substr(start));
  return cells;
}

void write_sweep_csv(const SweepTable& table, std::ostream& out) {
  out << csv_line(table.header) << '\n';
  for (const auto& [index, cells] : table.rows) out << csv_line(cells) << '\n';
}

}  // namespace bookspin::jobs
