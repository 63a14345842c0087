#include "output/csv_writer.hpp"

#include <cstdio>

#include "common/errors.hpp"
#include "output/finite_number.hpp"

namespace bookspin::output {

namespace {

/// `text` as one CSV field: as it is, or quoted with its quotes doubled where it must be.
std::string field(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) quoted.append(c == '"' ? "\"\"" : std::string(1, c));
  return quoted + "\"";
}

}  // namespace

std::string csv_text(const CsvTable& table, std::string_view what) {
  std::string out;
  for (std::size_t i = 0; i < table.columns.size(); ++i)
    out.append(i ? "," : "").append(field(table.columns[i]));
  out += '\n';
  for (const auto& row : table.rows) {
    BOOKSPIN_ASSERT(row.size() == table.columns.size());
    for (std::size_t i = 0; i < row.size(); ++i) {
      if (i) out += ',';
      if (const auto* text = std::get_if<std::string>(&row[i])) {
        out += field(*text);
        continue;
      }
      const CsvNumber& number = std::get<CsvNumber>(row[i]);
      if (!number.value) continue;
      const double value = finite(*number.value, std::string(what) + " column " + table.columns[i]);
      char cell[64];
      std::snprintf(cell, sizeof cell, number.format, value);
      out += cell;
    }
    out += '\n';
  }
  return out;
}

}  // namespace bookspin::output
