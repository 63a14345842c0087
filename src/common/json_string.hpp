#pragma once
// The one JSON string escaper, for every stage that writes JSON: the canonical scene and the
// manifests (scene/canonical.hpp, cache/), and the JSON writer of the outputs
// (json_writer.hpp); and beside it its reader, for the scenario file's JSON reader
// (analysis/scenario_file.hpp): what json_string() writes, read_json_string() reads back.
#include <cstddef>
#include <string>
#include <string_view>

namespace bookspin {

/// `text` as a JSON string literal, quotes included (", \ , control characters and DEL escaped,
/// the last two as \uXXXX; the bytes of any other character, UTF-8 included, are kept). It is
/// a TOML basic string too (TOML requires DEL escaped), which the Python module writes overrides
/// with.
std::string json_string(const std::string& text);

/// One JSON string literal read (RFC 8259 §7).
struct JsonStringRead {
  std::string text;  ///< its characters, UTF-8
  /// Past its closing quote; where the literal stops being one, the offset of what is wrong
  /// (the text's size where it ends first).
  std::size_t end = 0;
  /// Empty, or what is wrong: "a control character in a string", "an unknown escape \q in a
  /// string", "expected four hex digits after \u", "a string without its closing quote".
  std::string error;
};

/// The JSON string literal whose opening quote is text[begin], read: the escapes \" \\ \/ \b
/// \f \n \r \t and \uXXXX (four hex digits, either case) as the characters they stand for,
/// in UTF-8 (a surrogate pair as its one character, a lone surrogate half as its own three
/// bytes); every other byte as it is, UTF-8 included. A raw control character (below U+0020)
/// is refused, as RFC 8259 refuses it. json_string()'s literal of any text reads back as that
/// text.
JsonStringRead read_json_string(std::string_view text, std::size_t begin);

}  // namespace bookspin
