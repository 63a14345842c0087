#pragma once
// A name in any alphabet as a file's name: the one rule for a recording's name (the command
// line's, the Python module's and the page's, which compiles this file) and the check a scene's
// name passes (docs/phone-lab.md, "Names").
#include <cstddef>
#include <string>
#include <string_view>

namespace bookspin {

/// The most bytes of UTF-8 a name made by file_name_of() holds: a file system holds 255 bytes
/// in one name (ext4, NTFS's 255 UTF-16 units hold more), and the outputs add a suffix
/// ("-toss12-measured.csv") and a pool's "-and-N-more" to it.
inline constexpr std::size_t kMaxFileNameBytes = 160;

/// `text` (UTF-8; a file's name without its extension, a folder's name) as a file's name:
/// every letter, mark, digit, space, punctuation and symbol of any script kept, normalized to
/// NFC (Unicode's composed form: "über" typed as u + U+0308 is "über" as one character);
/// replaced by '-': what a file's name cannot hold on Debian or Windows (/ \ : * ? " < > |),
/// control characters (C0, C1, U+2028/U+2029, the bidirectional overrides and isolates,
/// which would reorder the name as shown), a byte that is not UTF-8, and a leading '.' (a hidden
/// file); cut to at most kMaxFileNameBytes bytes at the end of a whole character (a grapheme
/// cluster: a letter with its marks, an emoji with its joiners), never inside one. "recording"
/// for an empty text. Names that differ after this rule stay apart ("anna b", "anna-b");
/// telling apart those it makes alike is the pool's (fit/pool.hpp).
std::string file_name_of(std::string_view text);

/// Why `name` cannot be a file's name under file_name_of()'s rule (not UTF-8, a character it
/// replaces, a leading '.'), or "" when it can; its form (NFC or not: a file named on macOS)
/// and its length are left to the file system.
std::string file_name_problem(std::string_view name);

/// `text` as valid UTF-8: each maximal subpart of an ill-formed sequence (a byte that is no
/// UTF-8, a sequence cut short) replaced by U+FFFD, as Unicode recommends (§3.9, "U+FFFD
/// Substitution of Maximal Subparts") and as node's Buffer.toString(), the WHATWG decoder and
/// Python's bytes.decode("utf-8", "replace") do; valid UTF-8 unchanged. A file's name in bytes
/// that are no UTF-8 ("caf\xe9.csv") written into a table or a line of text: "caf\uFFFD.csv".
std::string utf8_replaced(std::string_view text);

/// Whether `text` starts with a letter or a digit of any script (Unicode's L* and N*).
bool starts_with_letter_or_digit(std::string_view text);

/// The character (code point) that starts at byte `at` of `text` and its length in bytes;
/// length 0 where no valid UTF-8 sequence starts there (a stray byte, a cut sequence).
struct Utf8Character {
  char32_t code = 0;
  std::size_t length = 0;
};
Utf8Character utf8_character_at(std::string_view text, std::size_t at);

/// Whether `c` shows as itself in one line: a letter, mark, digit, punctuation or symbol of any
/// script, or U+0020; not a control, a format character (the marks of direction, the
/// zero-width joiners), another space (U+2009 THIN SPACE), a line or paragraph separator.
bool shows_as_itself(char32_t c);

/// The characters of `text` (UTF-8) that do not show as themselves but look like nothing or
/// like a plain space, each once in order as "U+2009", joined by ", " ("U+2009, U+200F"): what
/// a copy from a document brings into a number or a name. "" where there are none; the ASCII
/// controls are left to the escapes of the line that quotes `text`.
std::string invisible_characters(std::string_view text);

}  // namespace bookspin
