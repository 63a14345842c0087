#pragma once
// The one number formatter: every number bookspin writes into a CSV or JSON file (the writers of
// csv_writer.hpp and json_writer.hpp, the canonical scene, a mesh's inertia, a sweep's grid
// values) is spelled here, and checked finite here. Every stage before keeps its numbers finite
// or reports bad input, so a NaN or infinity at this point is a bug, never something to write
// down: the run ends with an internal error (exit 70; docs/outputs.md, "Numbers").
#include <optional>
#include <string>
#include <string_view>

namespace bookspin {

/// How a number is spelled. Every style reads back to the same double except a printf format
/// that says otherwise ("%.6e").
enum class NumberStyle {
  shortest,  ///< std::to_chars: the shortest text that reads back (1e-05, 0.1, 1234.5)
  digits17,  ///< "%.17g": 17 significant digits (0.10000000000000001)
  fewest_g,  ///< the first of "%.15g", "%.16g", "%.17g" that reads back (0.1, 1.0000000000000002)
};

/// `value` itself when finite; else throws InternalError "non-finite WHAT in an output: nan"
/// (`what` names the column or field, e.g. "diagnostics CSV column energy_total").
double finite(double value, std::string_view what);

/// `value` spelled in `style`, checked by finite().
std::string finite_text(double value, std::string_view what,
                        NumberStyle style = NumberStyle::shortest);

/// The same, or "" (an empty cell) for nullopt: for the columns that allow empty cells.
std::string finite_text(const std::optional<double>& value, std::string_view what,
                        NumberStyle style = NumberStyle::shortest);

/// `value` in the printf `format` (one conversion of a double: "%.6e", "%.2f"), checked by
/// finite().
std::string finite_text(double value, std::string_view what, const char* format);

/// For a person (a summary's lines, not a file): `value` ± `sigma` printed to σ's precision,
/// σ rounded to two significant digits and the value to the same decimal place ("0.348257 ±
/// 0.000027" for 0.3482571 ± 0.0000269; "170 ± 12" for 171.4 ± 12.3), so a σ never rounds to
/// zero; a σ that is not a positive finite number leaves the value at four significant digits
/// and σ as "0" (0) or absent. The same rule as the explorer's web/src/precision.js.
std::string plus_minus(double value, double sigma);

/// The reader beside the writer: `text` as std::from_chars reads a double in its general format
/// (an optional '-', digits with an optional point, an optional exponent; "nan", "inf" and
/// "infinity" in any case, as NaN and infinity), the whole text or nothing; nullopt for
/// anything else and for a value beyond the doubles (one whose digits are not all zero that
/// reads as 0 or as infinity: from_chars's result_out_of_range). Correctly rounded (strtod in
/// the "C" locale): emscripten's libc++ has no from_chars for doubles, and the explorer page
/// reads recordings and motions with this too.
std::optional<double> read_number(std::string_view text);

/// Whether `text` spells a decimal number (an optional sign, digits, a point, an exponent) whose
/// magnitude is past the largest double (about 1.8e308: "1e400", "-2e308"), which read_number
/// refuses: every door words it kBeyondDoubles, not "not a number" (a recording's cell, the
/// fit's options).
bool beyond_doubles(std::string_view text);

/// The words for a number past the largest double, said alike at every door (and as flipcheck's
/// motion reader says it): `"2e308" is ` kBeyondDoubles.
inline constexpr const char* kBeyondDoubles = "beyond the largest finite number (about 1.8e308)";

/// Whether `text` spells a decimal number whose digits are not all zero but whose magnitude is
/// below the smallest double (about 4.9e-324: "1e-400"), which read_number refuses too.
bool below_doubles(std::string_view text);

/// The words for such a number: `"1e-400" is ` kBelowDoubles.
inline constexpr const char* kBelowDoubles =
    "below the smallest positive number (about 4.9e-324): it would read as 0";

/// Why `text`, which read_number() refuses, is no number, after its quoted text: kBeyondDoubles,
/// kBelowDoubles, or "" (not a number at all: the door says so in its own words).
std::string out_of_range_reason(std::string_view text);

}  // namespace bookspin
