// The one JSON string escaper and its reader (common/json_string.hpp) against the JSON grammar
// itself (RFC 8259 §7) and against each other: every character the RFC says must be escaped
// is, each escape of the RFC reads as the character it stands for, and what the escaper writes
// of any text reads back as that text.
#include "common/json_string.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace bookspin {
namespace {

/// The value of one whole JSON string literal (read_json_string), or empty where the text is
/// not one or holds more after it.
std::optional<std::string> read_literal(const std::string& literal) {
  if (literal.empty() || literal.front() != '"') return std::nullopt;
  const JsonStringRead read = read_json_string(literal, 0);
  if (!read.error.empty() || read.end != literal.size()) return std::nullopt;
  return read.text;
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
      const std::optional<std::string> back = read_literal(literal);
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
  EXPECT_EQ(read_literal(json_string("a\"b\\c")), std::optional<std::string>("a\"b\\c"));
  EXPECT_EQ(json_string(" \x7f/\xc3\xa9"), "\" \\u007f/\xc3\xa9\"");
  EXPECT_EQ(read_literal(json_string("a\x7f")), std::optional<std::string>("a\x7f"));
  EXPECT_EQ(json_string(""), "\"\"");
}

// Each escape of RFC 8259 §7 read as the character it stands for, written out here by hand:
// \uXXXX in UTF-8 (é two bytes, € three, a surrogate pair its one four-byte character, a lone
// half its own three bytes), other bytes as they are, and the reader stopping past the
// closing quote of a literal inside a longer text.
TEST(JsonString, EveryEscapeReadsAsItsCharacter) {
  EXPECT_EQ(read_literal(R"("\"\\\/\b\f\n\r\t")"), std::optional<std::string>("\"\\/\b\f\n\r\t"));
  EXPECT_EQ(read_literal(R"("\u0041\u00e9\u00C9\u20ac")"),
            std::optional<std::string>("A\xc3\xa9\xc3\x89\xe2\x82\xac"));
  EXPECT_EQ(read_literal(R"("\ud83d\ude00")"), std::optional<std::string>("\xf0\x9f\x98\x80"));
  EXPECT_EQ(read_literal(R"("\ud83dx")"), std::optional<std::string>("\xed\xa0\xbdx"));
  EXPECT_EQ(read_literal("\"caf\xc3\xa9 \x7f\""), std::optional<std::string>("caf\xc3\xa9 \x7f"));
  const std::string text = R"({"a\"b": 1})";
  const JsonStringRead key = read_json_string(text, 1);
  EXPECT_EQ(key.text, "a\"b");
  EXPECT_EQ(key.end, 7u);
  EXPECT_TRUE(key.error.empty());
}

// What is no string literal, refused with the offset of what is wrong: a raw control
// character, an unknown escape (at its letter), a \u without four hex digits (at the first
// that is none), no closing quote (the text's end).
TEST(JsonString, WhatIsNoLiteralIsRefusedWhereItIsWrong) {
  const auto refused = [](const std::string& text, std::size_t end, const std::string& error) {
    const JsonStringRead read = read_json_string(text, 0);
    EXPECT_EQ(read.error, error) << text;
    EXPECT_EQ(read.end, end) << text;
  };
  refused("\"ab\ncd\"", 3, "a control character in a string");
  refused(R"("ab\qcd")", 4, "an unknown escape \\q in a string");
  refused(R"("\u12x4")", 5, "expected four hex digits after \\u");
  refused(R"("\u12)", 5, "expected four hex digits after \\u");
  refused(R"("abc)", 4, "a string without its closing quote");
  refused(R"("abc\)", 5, "a string without its closing quote");
}

// The relation: json_string() then read_json_string() is the identity, for seeded random texts
// of control characters, quotes, backslashes, slashes, DEL, ASCII, UTF-8 of two to four bytes
// and bytes that are no UTF-8 at all.
TEST(JsonString, WhatTheEscaperWritesTheReaderReadsBack) {
  const std::vector<std::string> pieces = {"\"",
                                           "\\",
                                           "/",
                                           "\x7f",
                                           "a",
                                           "Z",
                                           " ",
                                           "\\u0041",
                                           "\xc3\xa9",
                                           "\xe2\x82\xac",
                                           "\xf0\x9f\x98\x80",
                                           "\xed\xa0\xbd",
                                           "\xff",
                                           "\x80"};
  std::mt19937 random(88);
  std::uniform_int_distribution<int> kind(0, 2), control(0x00, 0x1f), length(0, 24);
  std::uniform_int_distribution<std::size_t> piece(0, pieces.size() - 1);
  for (int draw = 0; draw < 5000; ++draw) {
    std::string text;
    for (int n = length(random); n > 0; --n)
      text += kind(random) == 0 ? std::string(1, static_cast<char>(control(random)))
                                : pieces[piece(random)];
    const std::string literal = json_string(text);
    const JsonStringRead read = read_json_string(literal + ", more", 0);
    ASSERT_TRUE(read.error.empty()) << literal << ": " << read.error;
    ASSERT_EQ(read.text, text) << literal;
    ASSERT_EQ(read.end, literal.size()) << literal;
  }
}

}  // namespace
}  // namespace bookspin
