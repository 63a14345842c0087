#pragma once
// The one check that an output directory is usable, made before any work, and the record of
// the directories this process made, so that a run that stops early (an interrupt, an error)
// can take back the empty ones.
#include <filesystem>
#include <system_error>

namespace bookspin::output {

/// Makes `dir` (and its parents) if missing and checks it is writable, so a bad -o fails
/// before any rendering. Throws OutputError naming the directory and the OS error.
void prepare_output_dir(const std::filesystem::path& dir);

/// std::filesystem::create_directories(dir, ec), remembering every directory it made (not
/// those that were there already) for remove_empty_made_directories(). Thread-safe.
void make_directories(const std::filesystem::path& dir, std::error_code& ec);

/// Removes, deepest first, each directory make_directories() made in this process that is
/// empty now (a directory holding anything stays), and forgets them all. For the exit path of
/// a run that stops without its outputs. Never throws.
void remove_empty_made_directories() noexcept;

}  // namespace bookspin::output
