#pragma once
// A CSV table as a plain value, and its writer. A report that writes a CSV (the accuracy report's
// tables, say) builds its cells first and hands the table here once: every number is printed in
// its cell's printf format and checked finite (finite_number.hpp), so the writer, not each
// caller, keeps NaN and infinity out of the outputs (docs/outputs.md, "Numbers").
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace bookspin::output {

/// A number cell: `value` in the printf `format` ("%.17g": reads back to the same double;
/// "%.6e"), or an empty cell where there is no value (nullopt).
struct CsvNumber {
  std::optional<double> value;
  const char* format = "%.17g";
};

/// One cell: text as it is (a name, an integer, a flag; "" is an empty cell) or a number.
using CsvCell = std::variant<std::string, CsvNumber>;

struct CsvTable {
  std::vector<std::string> columns;        ///< the header's names, in order
  std::vector<std::vector<CsvCell>> rows;  ///< each as many cells as there are columns
};

/// The header line, then one line per row, each ending in '\n'. A text cell holding a comma, a
/// double quote or a line break is quoted (RFC 4180). Throws InternalError "non-finite WHAT
/// column NAME in an output: nan" for a NaN or infinite number, and for a row whose cells do not
/// match the columns.
std::string csv_text(const CsvTable& table, std::string_view what);

}  // namespace bookspin::output
