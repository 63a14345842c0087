#pragma once
// The pieces of a recording's text that its readers share (docs/phone-lab.md, "The recording"):
// rows as RFC 4180 reads them, lines without comments, number cells with either decimal mark.
// For the readers in src/fit (gyro_csv.cpp, phyphox_meta.cpp) alone.
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace bookspin::fit::recording_text {

/// Fewer samples than this are no recording (a fit needs ten).
inline constexpr int kMinSamples = 10;

/// The rows of `text` split at `separator` as RFC 4180 reads them (next_csv_record: a quoted
/// cell may hold the separator, doubled quotes and line ends, as R's write.csv and spreadsheets
/// write them), each with its 1-based line number; blank lines and comment lines (starting with
/// '#') left out. Throws InputError naming `file` for a quoted cell not closed by the end of the
/// file.
std::vector<std::pair<int, std::vector<std::string>>> csv_rows(std::string_view text,
                                                               char separator,
                                                               const std::string& file);

/// `text` with ASCII letters lowered.
std::string lower(std::string text);

/// The lines of `text` (without their ends), with their 1-based numbers; blank lines and
/// comment lines (starting with '#', as a whitespace-separated export's notes do) left out.
std::vector<std::pair<int, std::string_view>> lines_of(std::string_view text);

/// A number cell as read_number takes it: trimmed, ',' as '.' where `decimal_comma`, a leading
/// '+' dropped.
std::string number_spelling(std::string_view given, bool decimal_comma);

/// A number cell: '.' or (decimal_comma) ',' as the decimal mark, scientific notation allowed;
/// nullopt for text. NaN and infinity are returned as such (the caller names them).
std::optional<double> parse_number(std::string_view given, bool decimal_comma);

/// Why a cell parse_number refuses is no number: past the largest double (1e400), or not one.
std::string not_a_number(const std::string& cell, bool decimal_comma);

}  // namespace bookspin::fit::recording_text
