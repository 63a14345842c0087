#pragma once
// A table's CSV text, as the command line writes it (csv_text), read back into rows of values
// keyed by the header's columns: what the doors that present a table (the explorer's lab,
// web/fit_bindings.cpp; the Python module, python/fit.cpp) each turn into their own values.
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "common/csv_writer.hpp"
#include "common/number_text.hpp"

namespace bookspin {

/// A cell read back: empty (std::monostate), a number (read_number: the very number its text
/// reads as), or text.
using CsvValue = std::variant<std::monostate, double, std::string>;

/// The rows of `text` after its header (csv_lines), each as (column, value) pairs in the
/// header's order. Throws std::invalid_argument as csv_lines.
inline std::vector<std::vector<std::pair<std::string, CsvValue>>> csv_keyed_rows(
    const std::string& text) {
  const std::vector<std::vector<std::string>> lines = csv_lines(text);
  std::vector<std::vector<std::pair<std::string, CsvValue>>> rows;
  for (std::size_t r = 1; r < lines.size(); ++r) {
    std::vector<std::pair<std::string, CsvValue>> row;
    for (std::size_t c = 0; c < lines[0].size() && c < lines[r].size(); ++c) {
      const std::string& cell = lines[r][c];
      CsvValue value;
      if (cell.empty())
        value = std::monostate{};
      else if (const std::optional<double> number = read_number(cell))
        value = *number;
      else
        value = cell;
      row.emplace_back(lines[0][c], std::move(value));
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace bookspin
