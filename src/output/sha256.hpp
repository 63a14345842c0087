#pragma once
// SHA-256 of files (inputs and outputs in the manifests), over common/sha256.hpp's digest.
#include <filesystem>
#include <optional>
#include <string>

namespace bookspin::output {

/// Lower-case hex SHA-256 (64 characters) of the file's bytes; std::nullopt if it cannot be
/// opened or read.
std::optional<std::string> sha256_file(const std::filesystem::path& path);

}  // namespace bookspin::output
