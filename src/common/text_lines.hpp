#pragma once
// The pieces of a text's lines every CSV reader shares, on text already in memory: no I/O, so
// that the explorer page's WebAssembly reads a motion file as the command line does.
#include <string_view>

namespace bookspin {

/// `text` without the spaces, tabs and carriage returns around it (a CSV cell, a line).
std::string_view trimmed(std::string_view text);

/// `text` without a UTF-8 byte-order mark (EF BB BF) at its start: spreadsheets write one
/// before a CSV's header, and every CSV reader reads past it (docs/outputs.md).
std::string_view without_bom(std::string_view text);

}  // namespace bookspin
