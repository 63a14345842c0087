#pragma once
// JSON as a plain value, and its one writer. A product that writes JSON (the explorer page's
// scenes, say) builds its data as a JsonValue and hands it here once: strings are escaped by the
// one escaper (common/json_string.hpp) and every number is written in shortest round-trip form
// and checked finite (finite_number.hpp), so the writer, not each caller, keeps NaN and infinity
// out of the outputs (docs/outputs.md, "Numbers").
#include <cstdint>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace bookspin::output {

struct JsonValue;
struct JsonMember;
using JsonArray = std::vector<JsonValue>;
using JsonObject = std::vector<JsonMember>;  ///< members in the order they are written

/// One JSON value: a boolean, an integer, a number, a string, a list of numbers (a 3×N matrix
/// flattened column by column, say: written as an array), an array or an object.
struct JsonValue {
  std::variant<bool, std::int64_t, double, std::string, std::vector<double>, JsonArray, JsonObject>
      value;
};

struct JsonMember {
  std::string key;
  JsonValue value;
};

/// How json_text() lays out a top-level array: all on one line, or each element on a line of
/// its own ("[\n" element ",\n" element "]"), for a reader of a long list.
enum class JsonLayout { compact, element_per_line };

/// `value` as compact JSON text (no spaces; numbers as output::finite_text writes them, so the
/// same bits always give the same bytes). Throws InternalError "non-finite WHAT PATH in an
/// output: nan" for a NaN or infinite number, PATH naming where it sits (e.g. "state.dt",
/// "[2].body.vertices").
std::string json_text(const JsonValue& value, std::string_view what,
                      JsonLayout layout = JsonLayout::compact);

}  // namespace bookspin::output
