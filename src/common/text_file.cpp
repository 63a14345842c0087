#include "common/text_file.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

#include "common/errors.hpp"

namespace bookspin {

std::optional<std::string> try_read_text_file(const std::filesystem::path& path,
                                              std::string* reason) {
  const auto none = [reason](std::string why) {
    if (reason) *reason = std::move(why);
    return std::nullopt;
  };
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (!std::filesystem::exists(status)) return none("no such file");
  if (std::filesystem::is_directory(status)) return none("is a directory");
  // Not a FIFO or a device either: those may never end.
  if (!std::filesystem::is_regular_file(status)) return none("not a regular file");
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"),
                                                             &std::fclose);
  if (!file) return none(std::strerror(errno));
  std::string text;
  char buffer[1 << 16];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, file.get())) > 0;) {
    text.append(buffer, n);
  }
  if (std::ferror(file.get())) return none(std::strerror(errno));
  return text;
}

std::string read_text_file(const std::filesystem::path& path, std::string_view what) {
  std::string reason;
  std::optional<std::string> text = try_read_text_file(path, &reason);
  if (!text) {
    throw InputError(path.string() + ": cannot read " + std::string(what) + ": " + reason);
  }
  return std::move(*text);
}

}  // namespace bookspin
