#include "output/data_url.hpp"

#include <openssl/evp.h>

#include <stdexcept>

namespace bookspin::output {

std::string data_url(std::string_view mime_type, const std::vector<std::uint8_t>& bytes) {
  if (bytes.size() > (std::size_t{1} << 30)) throw std::length_error("data_url: input over 1 GiB");
  const std::string head = "data:" + std::string(mime_type) + ";base64,";
  // 4 characters per 3 bytes, rounded up, and the NUL EVP_EncodeBlock writes.
  std::string out(head.size() + 4 * ((bytes.size() + 2) / 3) + 1, '\0');
  out.replace(0, head.size(), head);
  const int written = EVP_EncodeBlock(reinterpret_cast<unsigned char*>(out.data() + head.size()),
                                      bytes.data(), static_cast<int>(bytes.size()));
  out.resize(head.size() + static_cast<std::size_t>(written));
  return out;
}

}  // namespace bookspin::output
