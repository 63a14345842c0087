#pragma once
// The pieces of a text's lines every CSV reader shares, on text already in memory: no I/O, so
// that the explorer page's WebAssembly reads a motion file as the command line does.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace bookspin {

/// `text` without the spaces, tabs and carriage returns around it (a CSV cell, a line).
std::string_view trimmed(std::string_view text);

/// `text` without a UTF-8 byte-order mark (EF BB BF) at its start: spreadsheets write one
/// before a CSV's header, and every CSV reader reads past it (docs/outputs.md).
std::string_view without_bom(std::string_view text);

/// One line of `text` from `start`: the line without its end, and where the next line starts
/// (text.size() after the last). A line ends at "\r\n", "\n" or a lone "\r" (the old Mac
/// ending some exporters still write), so a file of any of the three reads alike.
struct TextLine {
  std::string_view line;
  std::size_t next = 0;
};
TextLine next_line(std::string_view text, std::size_t start);

/// One record of a CSV `text` from `start`, its cells split at `separator` as RFC 4180 reads
/// them (the reader R's write.csv, spreadsheets and phyphox write for): a cell in double
/// quotes may hold the separator, a line end and a quote doubled ("a ""b"", c" is `a "b", c`);
/// spaces and tabs around a cell are not part of it. A record ends at a line end outside quotes
/// (next_line's ends). `lines`: how many lines it spans (more than 1 where a quoted cell holds
/// a line end); `unclosed`: a quoted cell still open at the end of `text` (its cells then hold
/// what was read); `text_after_quote`: the cells (by index, ascending) whose closing quote is
/// followed by more text before the separator (`"a"b`, read as `ab`): where that quote was
/// meant to open a cell, the quote before it was left open.
struct CsvRecord {
  std::vector<std::string> cells;
  std::size_t next = 0;
  int lines = 1;
  bool unclosed = false;
  std::vector<std::size_t> text_after_quote;
};
CsvRecord next_csv_record(std::string_view text, std::size_t start, char separator);

/// "NUL byte at line N" (1-based, lines as next_line() counts them, with what it usually means)
/// when `text` holds a NUL byte, or nullopt: a reader says so before anything else, so that no
/// message quotes a cell cut short at the NUL.
std::optional<std::string> nul_byte_problem(std::string_view text);

/// `cell` quoted for an error message: "…" whole up to 80 characters; a longer one cut to its
/// first 60 with its length given ("12345678901…" (2097152 characters)), so that one line stays
/// one line.
std::string quoted_cell(std::string_view cell);

/// The same unquoted, for a message that shows a number as it is ("t = 0.5 is …"): whole up to
/// 80 characters, else its first 60, "…" and its length ("0.5000…" (2097152 characters)).
std::string cut_cell(std::string_view cell);

/// The most bytes of a name (a scenario's) that a message names whole: 4096, PATH_MAX, the
/// longest path Linux takes, so that any name a person or a file could give is named whole
/// (a scenario name of 300 characters, over its limit of 128, is named so in its refusal);
/// beyond it (a million characters pasted) it is cut as a cell is.
inline constexpr std::size_t kWholeName = 4096;

/// `name` quoted for an error message: "…" whole up to kWholeName bytes, else quoted_cell's cut.
std::string quoted_name(std::string_view name);

/// The same unquoted (a message's prefix naming what it is about).
std::string cut_name(std::string_view name);

}  // namespace bookspin
