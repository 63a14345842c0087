#include "common/text_file.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

#include "common/errors.hpp"

namespace bookspin {

std::string not_a_file_reason(const std::filesystem::path& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec && ec.value() == ELOOP) return kLinkLoop;
  if (!fs::exists(status)) return "no such file";
  if (fs::is_regular_file(status)) return "";
  if (fs::is_directory(status)) return "is a directory";
  if (fs::is_fifo(status)) return "is a FIFO, not a regular file";
  if (fs::is_character_file(status) || fs::is_block_file(status))
    return "is a device, not a regular file";
  if (fs::is_socket(status)) return "is a socket, not a regular file";
  return "not a regular file";
}

std::optional<std::string> try_read_text_file(const std::filesystem::path& path,
                                              std::string* reason) {
  const auto none = [reason](std::string why) {
    if (reason) *reason = std::move(why);
    return std::nullopt;
  };
  // Not a FIFO or a device either: those may never end.
  if (std::string why = not_a_file_reason(path); !why.empty()) return none(std::move(why));
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
