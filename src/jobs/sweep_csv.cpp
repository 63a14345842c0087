#include "jobs/sweep_csv.hpp"

#include <algorithm>
#include <optional>
#include <string_view>

#include "common/csv_writer.hpp"
#include "common/errors.hpp"

namespace bookspin::jobs {

namespace {

/// A measure's cell: empty where the run does not reach it (no flip), else its value, checked
/// finite on the way out (common/number_text.hpp).
std::string cell(const std::optional<double>& v, std::string_view column) {
  return finite_text(v, "sweep CSV column " + std::string(column), NumberStyle::digits17);
}

}  // namespace

MeasureList parse_measures(const std::string& text) {
  MeasureList measures;
  std::vector<std::string> names;
  std::size_t start = 0;
  for (std::size_t comma; (comma = text.find(',', start)) != std::string::npos; start = comma + 1)
    names.push_back(text.substr(start, comma - start));
  names.push_back(text.substr(start));
  for (const std::string& name : names) {
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
  header.emplace_back(kRefusedColumn);
  return header;
}

std::vector<std::string> sweep_row_cells(const std::vector<double>& point,
                                         const MeasureList& measures,
                                         const analysis::RunMeasures& m) {
  std::vector<std::string> cells;
  for (double v : point) cells.push_back(finite_text(v, "sweep grid value", NumberStyle::digits17));
  for (const analysis::Measure* measure : measures)
    cells.push_back(cell(m.*(measure->value), measure->name));
  for (const analysis::Measure* measure : measures)
    if (measure->exact) cells.push_back(cell(m.*(measure->exact), measure->exact_name));
  cells.emplace_back();  // refused: no
  return cells;
}

std::vector<std::string> sweep_refused_cells(const std::vector<double>& point,
                                             const MeasureList& measures,
                                             const std::string& reason) {
  BOOKSPIN_ASSERT(!reason.empty());
  std::vector<std::string> cells = sweep_row_cells(point, measures, analysis::RunMeasures{});
  cells.back() = reason;  // every measure empty: nothing ran
  return cells;
}

std::vector<std::string> after(const std::string& first, const std::vector<std::string>& cells) {
  std::vector<std::string> line{first};
  line.insert(line.end(), cells.begin(), cells.end());
  return line;
}

void write_sweep_csv(const SweepTable& table, std::ostream& out) {
  out << csv_row(table.header) << '\n';
  for (const auto& [index, cells] : table.rows) out << csv_row(cells) << '\n';
}

}  // namespace bookspin::jobs
