#pragma once
// What the scene suites share: a scene parsed from TOML text, and the error line it gives.
#include <string>

#include "scene/scene.hpp"

namespace bookspin::scene::testing {

/// `text` parsed as the file "test.toml" (relative paths resolve against the working folder).
inline Scene parse(const std::string& text) { return parse_scene_text(text, "test.toml"); }

/// The InputError message of parsing `text`, or "" if it parses.
inline std::string error_of(const std::string& text) {
  try {
    parse(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace bookspin::scene::testing
