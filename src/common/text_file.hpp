#pragma once
// The one whole-file reader: a scene, a manifest, the explorer page's shell, read as bytes
// (no newline translation, no encoding check), for every stage.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "common/text_lines.hpp"  // trimmed(), without_bom(): read with the files

namespace bookspin {

/// Why `path` cannot be read as a file, or "" when it is a regular file: "no such file", "is a
/// directory", "is a FIFO, not a regular file", "is a device, not a regular file", "is a
/// socket, not a regular file", "not a regular file", kLinkLoop. Never throws.
std::string not_a_file_reason(const std::filesystem::path& path);

/// The words for a path whose symbolic links lead round in a loop (ELOOP), said alike at every
/// door (the command line, Python, npx and the engines' runner: npm/package/files.mjs).
inline constexpr const char* kLinkLoop = "its symbolic links make a loop";

/// The bytes of the regular file `path`, or std::nullopt when there are none to read: not a
/// regular file ("no such file", "is a directory", "not a regular file"), or the file cannot
/// be opened or read to its end (the OS error, e.g. "Permission denied"); `reason`, when
/// given, is set to which. Never throws for a bad file.
std::optional<std::string> try_read_text_file(const std::filesystem::path& path,
                                              std::string* reason = nullptr);

/// The bytes of the regular file `path`. Throws InputError "PATH: cannot read WHAT: REASON"
/// (`what`: e.g. "the scene file"; REASON as for try_read_text_file()) when there are none.
std::string read_text_file(const std::filesystem::path& path, std::string_view what);

}  // namespace bookspin
