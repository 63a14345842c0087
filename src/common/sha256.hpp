#pragma once
// SHA-256 (FIPS 180-4) through OpenSSL's libcrypto, of bytes in memory: a scenario's identity,
// a manifest's head. Files are hashed by output/sha256.hpp, over this digest.
#include <cstddef>
#include <string>
#include <string_view>

#include "common/non_copyable.hpp"

struct evp_md_ctx_st;

namespace bookspin {

/// A SHA-256 digest fed in pieces: update() any number of times, then hex() once. Throws
/// std::runtime_error where libcrypto fails (an internal error: exit 70).
class Sha256 : NonCopyable {
 public:
  Sha256();
  ~Sha256();
  void update(const void* data, std::size_t size);
  /// Lower-case hex (64 characters) of everything given; the digest is finished.
  std::string hex();

 private:
  evp_md_ctx_st* ctx_;
};

/// Lower-case hex SHA-256 of `bytes`.
std::string sha256_text(std::string_view bytes);

}  // namespace bookspin
