#pragma once
// JSON as a plain value, and its one writer, for every file bookspin writes JSON into: the
// manifests (their heads and notes, cache/manifest_head.hpp, and the outputs list,
// output/manifest.hpp), the canonical scene (scene/canonical.hpp), the explorer page's data, a
// mesh's inertia. A caller builds its data as a JsonValue and hands it here: strings are escaped
// by the one escaper (json_string.hpp) and every number is spelled and checked finite by the one
// formatter (number_text.hpp), so the writer, not each caller, keeps NaN and infinity out of the
// outputs (docs/outputs.md, "Numbers").
#include <cstdint>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "common/number_text.hpp"

namespace bookspin {

struct JsonValue;
struct JsonMember;
using JsonArray = std::vector<JsonValue>;
using JsonObject = std::vector<JsonMember>;  ///< members in the order they are written

/// A number spelled in a style of its own (a plain double is written NumberStyle::shortest).
struct JsonNumber {
  double value = 0.0;
  NumberStyle style = NumberStyle::shortest;
};

/// One JSON value: a boolean, an integer, a number (shortest round-trip form, or a JsonNumber's
/// style), a string, a list of numbers (a 3×N matrix flattened column by column, say: written as
/// an array), an array or an object.
struct JsonValue {
  std::variant<bool, std::int64_t, double, JsonNumber, std::string, std::vector<double>, JsonArray,
               JsonObject>
      value;
  /// In the indented layout, an array or object with `lines` set is written over lines, one
  /// element or member a line, indented two spaces deeper than the line it opens on; else it
  /// stays on one line (`{"a": 1, "b": [2, 3]}`). The other layouts ignore it.
  bool lines = false;
};

struct JsonMember {
  std::string key;
  JsonValue value;
};

/// How json_text() lays out a value:
/// - compact: all on one line, no spaces (`{"a":1,"b":[2,3]}`);
/// - element_per_line: compact, but a top-level array has each element on a line of its own
///   ("[\n" element ",\n" element "]"), for a reader of a long list;
/// - indented: ", " and ": " between items, and the arrays and objects marked `lines` broken
///   over lines (`{\n  "a": 1,\n  "b": {"c": 2}\n}`; an empty one is "{\n}" at its indent).
enum class JsonLayout { compact, element_per_line, indented };

/// `value` as JSON text in `layout`. Throws InternalError "non-finite WHAT PATH in an output:
/// nan" for a NaN or infinite number, PATH naming where it sits (e.g. "state.dt",
/// "[2].body.vertices").
std::string json_text(const JsonValue& value, std::string_view what,
                      JsonLayout layout = JsonLayout::compact);

/// The members of an object as the lines they make inside an indented object whose members sit
/// `indent` spaces in: one `"key": value` a line, each ending in ",\n", but the last ending in
/// "\n" where `last` (the closing brace follows). For a file written in parts (a manifest: its
/// head, its note, its outputs). Throws as json_text().
std::string json_member_lines(const JsonObject& members, std::string_view what, int indent,
                              bool last);

}  // namespace bookspin
