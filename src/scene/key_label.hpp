#pragma once
// The words and unit of every numeric scene key (limits.hpp's kLimits, scenes/README.md "Keys"),
// for the pictures that name a key: a sweep's axes and header lead with the words, the key
// follows (docs/outputs.md, "Sweeps").
#include <string>
#include <string_view>

namespace bookspin::scene {

/// A key's readable name and its unit ("" for a count or a pure number).
struct KeyWords {
  std::string words;  ///< e.g. "time step dt", "ω0 y, body frame"
  std::string unit;   ///< e.g. "time units", "rad per time unit"
};

/// The words of `key`, a dotted numeric scene key, a vector key's component as "key[i]"
/// ("initial.angular_velocity[1]": "ω0 y, body frame"). Throws std::invalid_argument for a key
/// that is not one of kLimits' (a sweep varies only those: an internal error).
KeyWords key_words(std::string_view key);

/// "words (unit)", or "words" where there is no unit: an axis' or a header's name of `key`.
std::string key_label(std::string_view key);

/// "words (unit) · key": a picture's name of `key`, the words leading and the key as written in
/// the CSV and on the command line second (a sweep's axes and header).
std::string key_caption(std::string_view key);

}  // namespace bookspin::scene
