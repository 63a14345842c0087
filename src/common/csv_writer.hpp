#pragma once
// The one CSV writer, for every CSV bookspin writes: a sweep's table and its shards, the
// accuracy report's tables, a clip's diagnostics CSV (row by row, as the frames come) and the
// bench's report. A caller builds its cells and hands them here: a text cell is quoted where it
// must be (RFC 4180), and every number is spelled and checked finite by the one formatter
// (number_text.hpp), so the writer, not each caller, keeps NaN and infinity out of the outputs
// (docs/outputs.md, "Numbers").
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "common/number_text.hpp"

namespace bookspin {

/// A number cell: `value` in the printf `format` ("%.6e"), or in `style` where `format` is null,
/// or an empty cell where there is no value (nullopt).
struct CsvNumber {
  std::optional<double> value;
  const char* format = nullptr;
  NumberStyle style = NumberStyle::digits17;
};

/// A number cell in shortest round-trip form (NumberStyle::shortest); an empty cell for none.
inline CsvNumber shortest_cell(std::optional<double> value) {
  return {value, nullptr, NumberStyle::shortest};
}

/// One cell: text as it is (a name, an integer, a flag, a number the caller spelled with
/// number_text.hpp; "" is an empty cell) or a number.
using CsvCell = std::variant<std::string, CsvNumber>;

struct CsvTable {
  std::vector<std::string> columns;        ///< the header's names, in order
  std::vector<std::vector<CsvCell>> rows;  ///< each as many cells as there are columns
};

/// `text` as one CSV field: as it is, or in double quotes with its quotes doubled where it holds
/// a comma, a double quote or a line break (RFC 4180).
std::string csv_field(const std::string& text);

/// One line of text cells, each through csv_field(), joined by commas; no line end. For a CSV
/// written line by line (the diagnostics CSV, a sweep's shard).
std::string csv_row(const std::vector<std::string>& cells);

/// A CSV line's cells: the inverse of csv_row (RFC 4180 on one line: a cell in double quotes
/// may hold commas and doubled quotes, as a sweep's `refused` reason does). Throws
/// std::invalid_argument for a quote that is not closed, or text after a closing quote.
std::vector<std::string> csv_cells(const std::string& line);

/// The lines of a CSV text that csv_text() wrote (one line a row: no cell holds a line break),
/// each as its cells (csv_cells), the header first: how the doors that present a table the
/// command line writes (the explorer's lab, the Python module) read it back. Throws
/// std::invalid_argument as csv_cells.
std::vector<std::vector<std::string>> csv_lines(const std::string& text);

/// The header line, then one line per row, each ending in '\n'. Throws InternalError
/// "non-finite WHAT column NAME in an output: nan" for a NaN or infinite number, and for a row
/// whose cells do not match the columns.
std::string csv_text(const CsvTable& table, std::string_view what);

}  // namespace bookspin
