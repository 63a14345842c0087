#pragma once
// The one JSON string escaper, for every stage that writes JSON: the canonical scene and the
// manifests (scene/canonical.hpp, cache/), and the JSON writer of the outputs
// (json_writer.hpp).
#include <string>

namespace bookspin {

/// `text` as a JSON string literal, quotes included (", \ , control characters and DEL escaped,
/// the last two as \uXXXX; the bytes of any other character, UTF-8 included, are kept). It is
/// a TOML basic string too (TOML requires DEL escaped), which the Python module writes overrides
/// with.
std::string json_string(const std::string& text);

}  // namespace bookspin
