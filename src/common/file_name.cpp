#include "common/file_name.hpp"

#include <utf8proc.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <vector>

namespace bookspin {
namespace {

struct Freer {
  void operator()(utf8proc_uint8_t* p) const { std::free(p); }
};

const utf8proc_uint8_t* bytes(std::string_view text) {
  return reinterpret_cast<const utf8proc_uint8_t*>(text.data());
}

/// The code point at `at` of `text` and its length in bytes; length 0 where no valid UTF-8
/// sequence starts there.
struct CodePoint {
  utf8proc_int32_t value = -1;
  std::size_t length = 0;
};
CodePoint code_point_at(std::string_view text, std::size_t at) {
  CodePoint cp;
  const utf8proc_ssize_t n = utf8proc_iterate(
      bytes(text.substr(at)), static_cast<utf8proc_ssize_t>(text.size() - at), &cp.value);
  cp.length = n > 0 ? static_cast<std::size_t>(n) : 0;
  return cp;
}

/// The length of the maximal subpart at `at` of `text`, where no valid UTF-8 sequence starts:
/// the longest start of a well-formed sequence there (Unicode Table 3-7: the second byte's
/// range after E0, ED, F0 and F4 is narrower), at least one byte.
std::size_t maximal_subpart(std::string_view text, std::size_t at) {
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
  const unsigned char lead = byte(at);
  std::size_t continuations = 0;
  unsigned char low = 0x80, high = 0xbf;  // the second byte's range
  if (lead >= 0xc2 && lead <= 0xdf) {
    continuations = 1;
  } else if (lead >= 0xe0 && lead <= 0xef) {
    continuations = 2;
    if (lead == 0xe0) low = 0xa0;
    if (lead == 0xed) high = 0x9f;
  } else if (lead >= 0xf0 && lead <= 0xf4) {
    continuations = 3;
    if (lead == 0xf0) low = 0x90;
    if (lead == 0xf4) high = 0x8f;
  }
  std::size_t length = 1;
  for (std::size_t k = 0; k < continuations && at + length < text.size(); ++k, ++length) {
    const unsigned char b = byte(at + length);
    if (k == 0 ? (b < low || b > high) : (b < 0x80 || b > 0xbf)) break;
  }
  return length;
}

/// Characters a file's name cannot hold, or that would hide or reorder it as shown.
bool is_replaced(utf8proc_int32_t c) {
  if (c < 0x80)
    return c < 0x20 || c == 0x7f ||
           std::string_view("/\\:*?\"<>|").find(static_cast<char>(c)) != std::string_view::npos;
  const utf8proc_category_t category = utf8proc_category(c);
  return category == UTF8PROC_CATEGORY_CC || category == UTF8PROC_CATEGORY_ZL ||
         category == UTF8PROC_CATEGORY_ZP || category == UTF8PROC_CATEGORY_CS ||
         (c >= 0x202a && c <= 0x202e) || (c >= 0x2066 && c <= 0x2069);
}

/// `text` with what starts no valid UTF-8 sequence as `replacement`: each byte of it, or with
/// `maximal`, each maximal subpart (maximal_subpart).
std::string with_invalid_replaced(std::string_view text, std::string_view replacement,
                                  bool maximal) {
  std::string valid;
  valid.reserve(text.size());
  for (std::size_t at = 0; at < text.size();) {
    const CodePoint cp = code_point_at(text, at);
    if (cp.length == 0) {
      valid.append(replacement);
      at += maximal ? maximal_subpart(text, at) : 1;
    } else {
      valid.append(text.substr(at, cp.length));
      at += cp.length;
    }
  }
  return valid;
}

/// `text` with each byte that starts no valid UTF-8 sequence as '-'.
std::string valid_utf8(std::string_view text) { return with_invalid_replaced(text, "-", false); }

/// `text` (valid UTF-8) in NFC.
std::string nfc(std::string_view text) {
  if (text.empty()) return {};
  utf8proc_uint8_t* mapped = nullptr;
  const utf8proc_ssize_t n =
      utf8proc_map(bytes(text), static_cast<utf8proc_ssize_t>(text.size()), &mapped,
                   static_cast<utf8proc_option_t>(UTF8PROC_STABLE | UTF8PROC_COMPOSE));
  const std::unique_ptr<utf8proc_uint8_t, Freer> owned(mapped);
  if (n < 0) return std::string(text);  // cannot happen on valid UTF-8 but out of memory
  return std::string(reinterpret_cast<const char*>(mapped), static_cast<std::size_t>(n));
}

/// The longest start of `text` (valid UTF-8) of at most `limit` bytes that ends where a
/// grapheme cluster ends.
std::string_view cut_at_grapheme(std::string_view text, std::size_t limit) {
  if (text.size() <= limit) return text;
  std::size_t end = 0;  // the last cluster boundary within the limit
  utf8proc_int32_t state = 0;
  utf8proc_int32_t previous = -1;
  for (std::size_t at = 0; at < text.size();) {
    const CodePoint cp = code_point_at(text, at);
    if (previous >= 0 && utf8proc_grapheme_break_stateful(previous, cp.value, &state)) end = at;
    if (at + cp.length > limit) break;
    previous = cp.value;
    at += cp.length;
  }
  return text.substr(0, end);
}

}  // namespace

std::string file_name_of(std::string_view text) {
  const std::string composed = nfc(valid_utf8(text));
  std::string safe;
  safe.reserve(composed.size());
  for (std::size_t at = 0; at < composed.size();) {
    const CodePoint cp = code_point_at(composed, at);
    if (is_replaced(cp.value))
      safe += '-';
    else
      safe.append(composed, at, cp.length);
    at += cp.length;
  }
  if (!safe.empty() && safe.front() == '.') safe.front() = '-';
  safe = std::string(cut_at_grapheme(safe, kMaxFileNameBytes));
  return safe.empty() ? std::string("recording") : safe;
}

std::string file_name_problem(std::string_view name) {
  if (name.empty()) return "it is empty";
  for (std::size_t at = 0; at < name.size();) {
    const CodePoint cp = code_point_at(name, at);
    if (cp.length == 0) return "not UTF-8 at byte " + std::to_string(at + 1);
    if (is_replaced(cp.value)) return "it must not hold / \\ : * ? \" < > | or a control character";
    at += cp.length;
  }
  if (name.front() == '.') return "it must not start with '.'";
  return "";
}

bool starts_with_letter_or_digit(std::string_view text) {
  if (text.empty()) return false;
  const CodePoint cp = code_point_at(text, 0);
  if (cp.length == 0) return false;
  switch (utf8proc_category(cp.value)) {
    case UTF8PROC_CATEGORY_LU:
    case UTF8PROC_CATEGORY_LL:
    case UTF8PROC_CATEGORY_LT:
    case UTF8PROC_CATEGORY_LM:
    case UTF8PROC_CATEGORY_LO:
    case UTF8PROC_CATEGORY_ND:
    case UTF8PROC_CATEGORY_NL:
    case UTF8PROC_CATEGORY_NO:
      return true;
    default:
      return false;
  }
}

std::string utf8_replaced(std::string_view text) {
  return with_invalid_replaced(text, "\xef\xbf\xbd", true);  // U+FFFD
}

Utf8Character utf8_character_at(std::string_view text, std::size_t at) {
  const CodePoint cp = code_point_at(text, at);
  return {cp.length == 0 ? U'\0' : static_cast<char32_t>(cp.value), cp.length};
}

bool shows_as_itself(char32_t c) {
  if (c == U' ') return true;
  if (c > 0x10ffff) return false;
  switch (utf8proc_category(static_cast<utf8proc_int32_t>(c))) {
    case UTF8PROC_CATEGORY_CN:
    case UTF8PROC_CATEGORY_CC:
    case UTF8PROC_CATEGORY_CF:
    case UTF8PROC_CATEGORY_CS:
    case UTF8PROC_CATEGORY_CO:
    case UTF8PROC_CATEGORY_ZS:
    case UTF8PROC_CATEGORY_ZL:
    case UTF8PROC_CATEGORY_ZP:
      return false;
    default:
      return true;
  }
}

std::string invisible_characters(std::string_view text) {
  std::string named;
  std::vector<utf8proc_int32_t> seen;
  for (std::size_t at = 0; at < text.size();) {
    const CodePoint cp = code_point_at(text, at);
    if (cp.length == 0) {
      ++at;
      continue;
    }
    at += cp.length;
    if (cp.value < 0x80 || shows_as_itself(static_cast<char32_t>(cp.value))) continue;
    if (std::find(seen.begin(), seen.end(), cp.value) != seen.end()) continue;
    seen.push_back(cp.value);
    char code[16];
    std::snprintf(code, sizeof code, "U+%04X", static_cast<unsigned>(cp.value));
    named += (named.empty() ? "" : ", ") + std::string(code);
  }
  return named;
}

}  // namespace bookspin
