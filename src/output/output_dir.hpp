#pragma once
// The one check that an output directory is usable, made before any work.
#include <filesystem>

namespace bookspin::output {

/// Makes `dir` (and its parents) if missing and checks it is writable, so a bad -o fails
/// before any rendering. Throws OutputError naming the directory and the OS error.
void prepare_output_dir(const std::filesystem::path& dir);

}  // namespace bookspin::output
