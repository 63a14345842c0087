// The one JSON string escaper (common/json_string.hpp) against the JSON grammar itself
// (RFC 8259 §7): read back by a reader of string literals written here from the RFC, every
// character comes back, and every character the RFC says must be escaped is.
#include "common/json_string.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <optional>
#include <string>

namespace bookspin {
namespace {

/// The value of one JSON string literal (RFC 8259 §7), or empty where the text is not one:
/// quotes around it; a raw '"', '\' or control character U+0000–U+001F inside is refused
/// ("characters that MUST be escaped"); the escapes are \" \\ \/ \b \f \n \r \t and \uXXXX
/// (four hex digits, either case; only code points below U+0080 are needed here).
std::optional<std::string> read_json_string(const std::string& literal) {
  if (literal.size() < 2 || literal.front() != '"' || literal.back() != '"') return std::nullopt;
  std::string out;
  for (std::size_t i = 1; i + 1 < literal.size(); ++i) {
    const auto c = static_cast<unsigned char>(literal[i]);
    if (c == '"' || c < 0x20) return std::nullopt;
    if (c != '\\') {
      out += static_cast<char>(c);
      continue;
    }
    if (++i + 1 >= literal.size()) return std::nullopt;
    switch (literal[i]) {
      case '"':
        out += '"';
        break;
      case '\\':
        out += '\\';
        break;
      case '/':
        out += '/';
        break;
      case 'b':
        out += '\x08';
        break;
      case 'f':
        out += '\x0c';
        break;
      case 'n':
        out += '\x0a';
        break;
      case 'r':
        out += '\x0d';
        break;
      case 't':
        out += '\x09';
        break;
      case 'u': {
        if (i + 4 > literal.size() - 2) return std::nullopt;  // four digits before the quote
        unsigned value = 0;
        for (int k = 1; k <= 4; ++k) {
          const char h = literal[i + k];
          const int digit = h >= '0' && h <= '9'   ? h - '0'
                            : h >= 'a' && h <= 'f' ? h - 'a' + 10
                            : h >= 'A' && h <= 'F' ? h - 'A' + 10
                                                   : -1;
          if (digit < 0) return std::nullopt;
          value = value * 16 + static_cast<unsigned>(digit);
        }
        if (value >= 0x80) return std::nullopt;  // not needed by these tests
        out += static_cast<char>(value);
        i += 4;
        break;
      }
      default:
        return std::nullopt;
    }
  }
  return out;
}

// RFC 8259 §7: "the characters that MUST be escaped: quotation mark, reverse solidus, and
// the control characters (U+0000 through U+001F)". Each of the 32 control characters alone
// and between letters: the literal holds no raw byte below 0x20 and reads back as the text.
TEST(JsonString, EveryControlCharacterIsEscapedAndReadsBack) {
  for (int code = 0x00; code <= 0x1f; ++code) {
    char name[8];
    std::snprintf(name, sizeof name, "U+%04X", static_cast<unsigned>(code));
    SCOPED_TRACE(name);
    const char c = static_cast<char>(code);
    for (const std::string& text : {std::string{c}, std::string{'a', c, 'b'}}) {
      const std::string literal = json_string(text);
      for (std::size_t i = 0; i < literal.size(); ++i)
        EXPECT_GE(static_cast<unsigned char>(literal[i]), 0x20) << "raw byte at " << i;
      const std::optional<std::string> back = read_json_string(literal);
      EXPECT_TRUE(back.has_value()) << literal;
      if (back) {
        EXPECT_EQ(*back, text);
      }
    }
  }
}

// The other two that must be escaped, and what need not be: the space and UTF-8's bytes are
// kept as they are. DEL (U+007F), which RFC 8259 lets through but TOML's basic strings do not,
// is escaped, so that the literal is a TOML string too, and reads back.
TEST(JsonString, QuoteAndBackslashAreEscapedTheRestKept) {
  EXPECT_EQ(json_string("a\"b\\c"), "\"a\\\"b\\\\c\"");
  EXPECT_EQ(read_json_string(json_string("a\"b\\c")), std::optional<std::string>("a\"b\\c"));
  EXPECT_EQ(json_string(" \x7f/\xc3\xa9"), "\" \\u007f/\xc3\xa9\"");
  EXPECT_EQ(read_json_string(json_string("a\x7f")), std::optional<std::string>("a\x7f"));
  EXPECT_EQ(json_string(""), "\"\"");
}

}  // namespace
}  // namespace bookspin
