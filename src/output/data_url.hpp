#pragma once
// Bytes as a data: URL (RFC 2397, base64 of RFC 4648 §4), for files that must carry their
// images inline (the explorer page opens from disk with the network off).
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace bookspin::output {

/// "data:<mime_type>;base64,<base64 of bytes>" (standard alphabet, '=' padding, no line
/// breaks; encoded by libcrypto's EVP_EncodeBlock). Throws std::length_error for input over
/// 1 GiB.
std::string data_url(std::string_view mime_type, const std::vector<std::uint8_t>& bytes);

}  // namespace bookspin::output
