#pragma once
// The closing check on every computed number bookspin writes to a CSV or JSON file: it is
// finite, or the run ends with an internal error (exit 70). Every stage before keeps its
// numbers finite or reports bad input, so a NaN or infinity here is a bug, never something to
// write down (docs/outputs.md, "Numbers").
#include <optional>
#include <string>
#include <string_view>

namespace bookspin::output {

/// `value` itself when finite; else throws InternalError "non-finite WHAT in an output: nan"
/// (`what` names the column or field, e.g. "diagnostics CSV column energy_total").
double finite(double value, std::string_view what);

/// `value` in shortest round-trip form (std::to_chars: the same bits always give the same
/// bytes), checked by finite().
std::string finite_text(double value, std::string_view what);

/// The same, or "" (an empty cell) for nullopt: for the columns that allow empty cells.
std::string finite_text(const std::optional<double>& value, std::string_view what);

}  // namespace bookspin::output
