#include "output/sha256.hpp"

#include <cstdio>
#include <memory>
#include <vector>

#include "common/sha256.hpp"

namespace bookspin::output {

namespace {

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};

}  // namespace

std::optional<std::string> sha256_file(const std::filesystem::path& path) {
  std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "rb"));
  if (!file) return std::nullopt;
  Sha256 digest;
  std::vector<unsigned char> buffer(1 << 20);
  std::size_t got = 0;
  while ((got = std::fread(buffer.data(), 1, buffer.size(), file.get())) > 0)
    digest.update(buffer.data(), got);
  if (std::ferror(file.get())) return std::nullopt;
  return digest.hex();
}

}  // namespace bookspin::output
