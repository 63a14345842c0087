#include "common/json_string.hpp"

#include <cstdio>
#include <utility>

namespace bookspin {

std::string json_string(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (u < 0x20 || u == 0x7f) {  // DEL too, so that the string is TOML's as well
      char buffer[8];
      std::snprintf(buffer, sizeof buffer, "\\u%04x", u);
      out += buffer;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

namespace {

/// `code` (below U+10000, or a whole code point from a surrogate pair) appended as UTF-8.
void append_utf8(std::string& out, unsigned code) {
  if (code < 0x80) {
    out += static_cast<char>(code);
  } else if (code < 0x800) {
    out += static_cast<char>(0xC0 | (code >> 6));
    out += static_cast<char>(0x80 | (code & 0x3F));
  } else if (code < 0x10000) {
    out += static_cast<char>(0xE0 | (code >> 12));
    out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (code >> 18));
    out += static_cast<char>(0x80 | ((code >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code & 0x3F));
  }
}

/// The four hex digits at text[at], or -1 with `at` on the first that is none.
long hex4(std::string_view text, std::size_t& at) {
  long code = 0;
  for (int i = 0; i < 4; ++i, ++at) {
    const char h = at < text.size() ? text[at] : ' ';
    const int d = h >= '0' && h <= '9'   ? h - '0'
                  : h >= 'a' && h <= 'f' ? h - 'a' + 10
                  : h >= 'A' && h <= 'F' ? h - 'A' + 10
                                         : -1;
    if (d < 0) return -1;
    code = code * 16 + d;
  }
  return code;
}

}  // namespace

JsonStringRead read_json_string(std::string_view text, std::size_t begin) {
  JsonStringRead read;
  std::size_t at = begin + 1;  // past the opening quote
  const auto fail = [&](std::size_t where, std::string why) {
    read.end = where;
    read.error = std::move(why);
    return read;
  };
  while (at < text.size() && text[at] != '"') {
    const char c = text[at];
    if (static_cast<unsigned char>(c) < 0x20) return fail(at, "a control character in a string");
    if (c != '\\') {
      read.text += c;
      ++at;
      continue;
    }
    if (++at >= text.size()) break;
    const char e = text[at++];
    const char* const kEscapes = "\"\"\\\\//b\bf\fn\nr\rt\t";  // pairs: escape, character
    if (e != 'u') {
      const char* pair = kEscapes;
      while (*pair && *pair != e) pair += 2;
      if (!*pair) return fail(at - 1, "an unknown escape \\" + std::string(1, e) + " in a string");
      read.text += pair[1];
      continue;
    }
    long code = hex4(text, at);
    if (code < 0) return fail(at, "expected four hex digits after \\u");
    // A high surrogate followed by a low one's escape: the one character they make.
    if (code >= 0xD800 && code < 0xDC00 && text.substr(at, 2) == "\\u") {
      std::size_t next = at + 2;
      const long low = hex4(text, next);
      if (low >= 0xDC00 && low < 0xE000) {
        code = 0x10000 + ((code - 0xD800) << 10) + (low - 0xDC00);
        at = next;
      }
    }
    append_utf8(read.text, static_cast<unsigned>(code));
  }
  if (at >= text.size()) return fail(text.size(), "a string without its closing quote");
  read.end = at + 1;
  return read;
}

}  // namespace bookspin
