// data: URLs (RFC 2397) with base64 (RFC 4648 §4): the RFC's own test vectors (§10), and
// every byte value through a decoder written here from the RFC's alphabet.
#include "output/data_url.hpp"

#include <gtest/gtest.h>

#include <string>

namespace bookspin::output {
namespace {

std::vector<std::uint8_t> bytes_of(const std::string& text) { return {text.begin(), text.end()}; }

TEST(DataUrl, Rfc4648TestVectors) {
  const std::pair<const char*, const char*> vectors[] = {{"", ""},
                                                         {"f", "Zg=="},
                                                         {"fo", "Zm8="},
                                                         {"foo", "Zm9v"},
                                                         {"foob", "Zm9vYg=="},
                                                         {"fooba", "Zm9vYmE="},
                                                         {"foobar", "Zm9vYmFy"}};
  for (const auto& [in, out] : vectors)
    EXPECT_EQ(data_url("text/plain", bytes_of(in)), std::string("data:text/plain;base64,") + out);
}

TEST(DataUrl, EveryByteValueDecodesBack) {
  const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  for (std::size_t n : {254u, 255u, 256u}) {  // the three paddings
    std::vector<std::uint8_t> in(n);
    for (std::size_t i = 0; i < n; ++i) in[i] = static_cast<std::uint8_t>((i * 7 + 3) % 256);
    const std::string url = data_url("image/png", in);
    const std::string head = "data:image/png;base64,";
    ASSERT_EQ(url.rfind(head, 0), 0u);
    const std::string text = url.substr(head.size());
    ASSERT_EQ(text.size() % 4, 0u);
    std::vector<std::uint8_t> out;
    std::uint32_t bits = 0;
    int count = 0;
    for (const char c : text) {
      if (c == '=') break;
      const auto at = alphabet.find(c);
      ASSERT_NE(at, std::string::npos) << "not base64: " << c;
      bits = (bits << 6) | static_cast<std::uint32_t>(at);
      if ((count += 6) >= 8) {
        count -= 8;
        out.push_back(static_cast<std::uint8_t>(bits >> count));
      }
    }
    EXPECT_EQ(out, in) << n << " bytes";
  }
}

}  // namespace
}  // namespace bookspin::output
