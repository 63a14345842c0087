// The one file-name rule (common/file_name.hpp): a name in any alphabet kept, in NFC, with only
// what a file's name cannot hold replaced, cut at a whole character. The expected names are
// written out by hand; the relations (idempotent, NFC and NFD alike, a cut a prefix ending at a
// character's end) hold for every name given.
#include "common/file_name.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace bookspin {
namespace {

// Names a class writes: Japanese, Greek, Cyrillic, German, Arabic, an emoji, a family emoji
// (three code points joined by U+200D), Hangul, Devanagari with its vowel signs (marks).
const std::vector<std::string> kNames = {"太郎",
                                         "花子",
                                         "Αθηνά",
                                         "Юлия бросок",
                                         "Wurf über dem Bett",
                                         "تجربة ٣",
                                         "🎲 würfel",
                                         "👩‍👩‍👧 family",
                                         "한국어",
                                         "परीक्षण",
                                         "anna b",
                                         "anna-b",
                                         "12-13-01",
                                         "Straße #2 & 'co' (50%)"};

bool valid_utf8(const std::string& s) {
  // A strict decoder of its own (not utf8proc's): lead byte, continuation bytes, no overlong.
  for (std::size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    int n = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 0;
    if (n == 0 || (n == 2 && c < 0xc2) || i + n > s.size()) return false;
    for (int k = 1; k < n; ++k)
      if ((static_cast<unsigned char>(s[i + k]) >> 6) != 2) return false;
    i += n;
  }
  return true;
}

TEST(FileName, EveryScriptsLettersMarksDigitsAndSymbolsAreKept) {
  for (const std::string& name : kNames) EXPECT_EQ(file_name_of(name), name) << name;
}

TEST(FileName, OnlyWhatAFileNameCannotHoldIsReplaced) {
  EXPECT_EQ(file_name_of("a/b\\c:d*e?f\"g<h>i|j"), "a-b-c-d-e-f-g-h-i-j");
  EXPECT_EQ(file_name_of("tab\there\nnew\x1b[31m\x7f"), "tab-here-new-[31m-");
  EXPECT_EQ(file_name_of("C1\u0085 line\u2028para\u2029"), "C1- line-para-");
  // The bidirectional override and isolate would show "gnp.exe" as "exe.png".
  EXPECT_EQ(file_name_of("x\u202egnp.exe"), "x-gnp.exe");
  EXPECT_EQ(file_name_of("a\u2066b\u2069"), "a-b-");
  EXPECT_EQ(file_name_of(".hidden"), "-hidden");
  EXPECT_EQ(file_name_of(".."), "-.");
  EXPECT_EQ(file_name_of("a.b.c"), "a.b.c");  // a dot inside stays
  EXPECT_EQ(file_name_of("\xff\xfe"
                         "太郎\xe5"),
            "--太郎-");  // bytes that are not UTF-8
  EXPECT_EQ(file_name_of(""), "recording");
  // The joiners an emoji or a Persian word needs are not controls.
  EXPECT_EQ(file_name_of("می\u200cخواهم"), "می\u200cخواهم");
}

TEST(FileName, ComposedAndDecomposedNameTheSame) {
  EXPECT_EQ(file_name_of("Wurf u\u0308ber dem Bett"), "Wurf \u00fcber dem Bett");
  EXPECT_EQ(file_name_of("\u1112\u1161\u11ab"), "\ud55c");        // Hangul jamo: 한
  EXPECT_EQ(file_name_of("\u0391\u0301\u03b8"), "\u0386\u03b8");  // Ά
  // "<" with U+0338 is "≮" in NFC, a character of its own, not a '<' to replace.
  EXPECT_EQ(file_name_of("<\u0338"), "\u226e");
}

TEST(FileName, TheRuleIsIdempotentAndGivesNamesItAccepts) {
  std::vector<std::string> names = kNames;
  for (const char* odd : {"a/b", "\x01\x02", ".x", "u\u0308", "\xc3", "x\u202e", "   "})
    names.emplace_back(odd);
  for (const std::string& name : names) {
    const std::string safe = file_name_of(name);
    EXPECT_EQ(file_name_of(safe), safe) << name;
    EXPECT_EQ(file_name_problem(safe), "") << name;
    EXPECT_TRUE(valid_utf8(safe)) << name;
    EXPECT_LE(safe.size(), kMaxFileNameBytes) << name;
  }
  EXPECT_NE(file_name_problem("a/b"), "");
  EXPECT_NE(file_name_problem("a\nb"), "");
  EXPECT_NE(file_name_problem(".x"), "");
  EXPECT_NE(file_name_problem("\xc3"), "");
}

TEST(FileName, NamesThatDifferStayApartAndOnlyReplacedOnesMeet) {
  EXPECT_NE(file_name_of("anna b"), file_name_of("anna-b"));
  EXPECT_NE(file_name_of("太郎"), file_name_of("花子"));
  EXPECT_NE(file_name_of("Юлия"), file_name_of("Юлиа"));
  // Alike after the rule: the pool tells these apart (PoolOrder.*).
  EXPECT_EQ(file_name_of("anna:b"), file_name_of("anna*b"));
  EXPECT_EQ(file_name_of("über"), file_name_of("u\u0308ber"));
}

TEST(FileName, ALongNameIsCutAtTheEndOfAWholeCharacter) {
  // Units of 1, 2, 3 and 4 bytes, a letter with a combining mark (no composed form: 3 bytes),
  // and a family emoji (18 bytes), each repeated past the limit.
  for (const std::string unit : {"a", "ß", "太", "🎲", "x\u0301", "👩‍👩‍👧", "ก\u0e34"}) {
    std::string name;
    while (name.size() < 3 * kMaxFileNameBytes) name += unit;
    const std::string cut = file_name_of(name);
    EXPECT_LE(cut.size(), kMaxFileNameBytes) << unit;
    EXPECT_GT(cut.size() + unit.size(), kMaxFileNameBytes) << unit;  // as long as it may be
    EXPECT_EQ(cut.size() % unit.size(), 0u) << unit;                 // whole characters only
    EXPECT_EQ(name.compare(0, cut.size(), cut), 0) << unit;          // a start of the name
  }
  // A 240-character name: its first 160 characters.
  EXPECT_EQ(file_name_of(std::string(240, 'n')), std::string(kMaxFileNameBytes, 'n'));
}

TEST(FileName, ALetterOrADigitOfAnyScriptStartsAName) {
  for (const char* name : {"太郎", "Αθηνά", "Юлия", "über", "تجربة", "٣", "7", "한"})
    EXPECT_TRUE(starts_with_letter_or_digit(name)) << name;
  for (const char* name : {"", ".x", "-x", " x", "🎲", "\u0301x", "\xc3"})
    EXPECT_FALSE(starts_with_letter_or_digit(name)) << name;
}

// A name in bytes that are no UTF-8 written into a table (utf8_replaced): each maximal subpart
// of an ill-formed sequence is one U+FFFD (Unicode §3.9's examples, as node's Buffer.toString()
// and Python's bytes.decode("utf-8", "replace") give them, written out by hand); valid UTF-8,
// every name of kNames, is kept byte for byte.
TEST(FileName, BytesThatAreNoUtf8AreEachMaximalSubpartAReplacementCharacter) {
  const std::string r = "\xef\xbf\xbd";                         // U+FFFD
  EXPECT_EQ(utf8_replaced("caf\xe9.csv"), "caf" + r + ".csv");  // Latin-1's é
  EXPECT_EQ(utf8_replaced("\xe2\x82x"), r + "x");               // a sequence cut short: one
  EXPECT_EQ(utf8_replaced("\xf0\x9f\x98"), r);                  // cut at the end: one
  EXPECT_EQ(utf8_replaced("\xed\xa0\x80"), r + r + r);          // a surrogate: E D's range
  EXPECT_EQ(utf8_replaced("\xe0\x80\xaf"), r + r + r);          // overlong: E0's range
  EXPECT_EQ(utf8_replaced("\xc0\xaf"), r + r);                  // C0 starts nothing
  EXPECT_EQ(utf8_replaced("\xf4\x90\x80\x80"), r + r + r + r);  // past U+10FFFF
  EXPECT_EQ(utf8_replaced("a\x80\xbf"), "a" + r + r);           // lone continuations
  EXPECT_EQ(utf8_replaced(""), "");
  for (const std::string& name : kNames) EXPECT_EQ(utf8_replaced(name), name);
  EXPECT_TRUE(valid_utf8(utf8_replaced("\xff\xfe\xe9\xf0\x90")));
}

}  // namespace
}  // namespace bookspin
