#include "common/csv_writer.hpp"

#include <algorithm>
#include <stdexcept>

#include "common/errors.hpp"

namespace bookspin {

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) quoted.append(c == '"' ? "\"\"" : std::string(1, c));
  return quoted + "\"";
}

std::string csv_row(const std::vector<std::string>& cells) {
  std::string line;
  for (std::size_t i = 0; i < cells.size(); ++i)
    line.append(i ? "," : "").append(csv_field(cells[i]));
  return line;
}

std::vector<std::string> csv_cells(const std::string& line) {
  std::vector<std::string> cells(1);
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (c == ',') {
      cells.emplace_back();
    } else if (c == '"' && cells.back().empty() && (i == 0 || line[i - 1] == ',')) {
      // A quoted cell: up to the quote not doubled, which must end the cell.
      for (++i;; ++i) {
        if (i >= line.size()) throw std::invalid_argument("a quoted cell is not closed");
        if (line[i] != '"') {
          cells.back() += line[i];
        } else if (i + 1 < line.size() && line[i + 1] == '"') {
          cells.back() += '"';
          ++i;
        } else {
          break;
        }
      }
      if (i + 1 < line.size() && line[i + 1] != ',')
        throw std::invalid_argument("text after a quoted cell's closing quote");
    } else {
      cells.back() += c;
    }
  }
  return cells;
}

std::vector<std::vector<std::string>> csv_lines(const std::string& text) {
  std::vector<std::vector<std::string>> lines;
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t end = std::min(text.find('\n', at), text.size());
    lines.push_back(csv_cells(text.substr(at, end - at)));
    at = end + 1;
  }
  return lines;
}

std::string csv_text(const CsvTable& table, std::string_view what) {
  std::string out = csv_row(table.columns) + '\n';
  for (const auto& row : table.rows) {
    BOOKSPIN_ASSERT(row.size() == table.columns.size());
    for (std::size_t i = 0; i < row.size(); ++i) {
      if (i) out += ',';
      if (const auto* text = std::get_if<std::string>(&row[i])) {
        out += csv_field(*text);
        continue;
      }
      const CsvNumber& number = std::get<CsvNumber>(row[i]);
      if (!number.value) continue;
      const std::string name = std::string(what) + " column " + table.columns[i];
      out += number.format ? finite_text(*number.value, name, number.format)
                           : finite_text(*number.value, name, number.style);
    }
    out += '\n';
  }
  return out;
}

}  // namespace bookspin
