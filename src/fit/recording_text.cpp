#include "fit/recording_text.hpp"

#include <algorithm>
#include <cctype>

#include "common/errors.hpp"
#include "common/number_text.hpp"
#include "common/text_lines.hpp"

namespace bookspin::fit::recording_text {

std::vector<std::pair<int, std::vector<std::string>>> csv_rows(std::string_view text,
                                                               char separator,
                                                               const std::string& file) {
  std::vector<std::pair<int, std::vector<std::string>>> rows;
  int number = 1;
  std::size_t at = 0;
  while (at < text.size()) {
    const TextLine line = next_line(text, at);
    const std::size_t first = line.line.find_first_not_of(" \t");
    if (first == std::string_view::npos || line.line[first] == '#') {
      ++number;
      at = line.next;
      continue;
    }
    CsvRecord record = next_csv_record(text, at, separator);
    if (record.unclosed)
      throw InputError(file, number, "",
                       "a quoted cell opens on this row and is not closed by the end of the file");
    rows.emplace_back(number, std::move(record.cells));
    number += record.lines;
    at = record.next;
  }
  return rows;
}

std::string lower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

std::vector<std::pair<int, std::string_view>> lines_of(std::string_view text) {
  std::vector<std::pair<int, std::string_view>> lines;
  int number = 0;
  std::size_t begin = 0;
  while (begin < text.size()) {
    const TextLine next = next_line(text, begin);  // "\r\n", "\n" or a lone "\r"
    ++number;
    const std::size_t first = next.line.find_first_not_of(" \t");
    if (first != std::string_view::npos && next.line[first] != '#')
      lines.emplace_back(number, next.line);
    begin = next.next;
  }
  return lines;
}

std::string number_spelling(std::string_view given, bool decimal_comma) {
  std::string cell(trimmed(given));  // a quoted cell keeps its spaces: " 2 " is 2
  if (decimal_comma) std::replace(cell.begin(), cell.end(), ',', '.');
  if (!cell.empty() && cell.front() == '+') cell.erase(0, 1);
  return cell;
}

std::optional<double> parse_number(std::string_view given, bool decimal_comma) {
  return read_number(number_spelling(given, decimal_comma));
}

std::string not_a_number(const std::string& cell, bool decimal_comma) {
  const std::string range = out_of_range_reason(number_spelling(cell, decimal_comma));
  if (!range.empty()) return quoted_cell(cell) + " is " + range;
  return "not a number: " + quoted_cell(cell);
}

}  // namespace bookspin::fit::recording_text
