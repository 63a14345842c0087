#pragma once
// SHA-256 (FIPS 180-4) through OpenSSL's libcrypto: of files (inputs and outputs in the
// manifests) and of text.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace bookspin::output {

/// Lower-case hex SHA-256 (64 characters) of the file's bytes; std::nullopt if it cannot be
/// opened or read.
std::optional<std::string> sha256_file(const std::filesystem::path& path);

/// Lower-case hex SHA-256 of `bytes`.
std::string sha256_text(std::string_view bytes);

}  // namespace bookspin::output
