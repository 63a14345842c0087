#include "common/text_lines.hpp"

#include <string>

namespace bookspin {

std::string_view trimmed(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t' || text.front() == '\r'))
    text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t' || text.back() == '\r'))
    text.remove_suffix(1);
  return text;
}

std::string_view without_bom(std::string_view text) {
  constexpr std::string_view kBom = "\xEF\xBB\xBF";
  if (text.substr(0, kBom.size()) == kBom) text.remove_prefix(kBom.size());
  return text;
}

TextLine next_line(std::string_view text, std::size_t start) {
  const std::size_t end = text.find_first_of("\r\n", start);
  if (end == std::string_view::npos) return {text.substr(start), text.size()};
  const std::size_t next =
      text[end] == '\r' && end + 1 < text.size() && text[end + 1] == '\n' ? end + 2 : end + 1;
  return {text.substr(start, end - start), next};
}

CsvRecord next_csv_record(std::string_view text, std::size_t start, char separator) {
  CsvRecord record;
  std::string cell;
  bool inside = false;   // within its quotes now
  bool started = false;  // anything but spaces seen in the cell
  bool closed = false;   // its closing quote seen
  std::size_t kept = 0;  // the cell's length up to its last character that is not a space
  const auto finish_cell = [&] {
    cell.resize(kept);  // the spaces after it dropped; a quoted cell's own kept
    record.cells.push_back(cell);
    cell.clear();
    inside = started = closed = false;
    kept = 0;
  };
  std::size_t i = start;
  while (i < text.size()) {
    const char c = text[i];
    if (inside) {
      if (c == '"') {
        if (i + 1 < text.size() && text[i + 1] == '"') {
          cell += '"';
          i += 2;
          kept = cell.size();
          continue;
        }
        inside = false;
        closed = true;
      } else {
        if (c == '\n' || (c == '\r' && !(i + 1 < text.size() && text[i + 1] == '\n')))
          ++record.lines;
        cell += c;
        kept = cell.size();
      }
      ++i;
      continue;
    }
    if (c == '\r' || c == '\n') {
      record.next = c == '\r' && i + 1 < text.size() && text[i + 1] == '\n' ? i + 2 : i + 1;
      finish_cell();
      return record;
    }
    if (c == separator) {
      finish_cell();
      ++i;
      continue;
    }
    if (c == ' ' || c == '\t') {
      if (started) cell += c;
    } else if (c == '"' && !started) {
      inside = started = true;
    } else {
      if (closed && (record.text_after_quote.empty() ||
                     record.text_after_quote.back() != record.cells.size()))
        record.text_after_quote.push_back(record.cells.size());
      cell += c;
      started = true;
      kept = cell.size();
    }
    ++i;
  }
  record.unclosed = inside;
  record.next = text.size();
  finish_cell();
  return record;
}

std::optional<std::string> nul_byte_problem(std::string_view text) {
  const std::size_t nul = text.find('\0');
  if (nul == std::string_view::npos) return std::nullopt;
  int line = 1;
  for (std::size_t start = 0;;) {
    const TextLine next = next_line(text, start);
    if (next.next > nul || next.next >= text.size()) break;
    start = next.next;
    ++line;
  }
  return "NUL byte at line " + std::to_string(line) +
         " (not a text file: a binary file, or text saved as UTF-16)";
}

namespace {
constexpr std::size_t kWholeCell = 80, kCutCell = 60;

/// The first kCutCell bytes of `cell`, not ending inside a UTF-8 sequence.
std::string_view cell_start(std::string_view cell) {
  std::size_t cut = kCutCell;
  while (cut > 0 && (static_cast<unsigned char>(cell[cut]) & 0xC0) == 0x80) --cut;
  return cell.substr(0, cut);
}
}  // namespace

// Appended piece by piece: "\"" + std::string(…) made GCC 12 warn of an overlapping memcpy
// inside std::string (-Wrestrict, a false positive of its inlining).
std::string quoted_cell(std::string_view cell) {
  std::string quoted(1, '"');
  if (cell.size() <= kWholeCell) return quoted.append(cell).append(1, '"');
  return quoted.append(cell_start(cell))
      .append("…\" (")
      .append(std::to_string(cell.size()))
      .append(" characters)");
}

std::string cut_cell(std::string_view cell) {
  if (cell.size() <= kWholeCell) return std::string(cell);
  return std::string(cell_start(cell)) + "… (" + std::to_string(cell.size()) + " characters)";
}

std::string quoted_name(std::string_view name) {
  if (name.size() <= kWholeName) return std::string(1, '"').append(name).append(1, '"');
  return quoted_cell(name);
}

std::string cut_name(std::string_view name) {
  return name.size() <= kWholeName ? std::string(name) : cut_cell(name);
}

}  // namespace bookspin
