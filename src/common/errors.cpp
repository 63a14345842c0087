#include "common/errors.hpp"

#include <cstdio>
#include <cstring>

namespace bookspin {

namespace {

std::string input_message(const std::string& file, int line, const std::string& key,
                          std::string_view reason) {
  std::string message = file;
  if (line > 0) message.append(":").append(std::to_string(line));
  if (!key.empty()) message.append(": ").append(key);
  message.append(": ").append(reason);
  return message;
}

}  // namespace

InputError::InputError(const std::string& file, int line, const std::string& key,
                       std::string_view reason)
    : std::runtime_error(input_message(file, line, key, reason)),
      file_(file),
      line_(line),
      key_(key) {}

void throw_output_error(std::string_view action, const std::filesystem::path& path,
                        std::string_view reason) {
  std::string message(action);
  message.append(" \"").append(path.string()).append("\": ").append(reason);
  throw OutputError(message);
}

void throw_output_error(std::string_view action, const std::filesystem::path& path,
                        int errno_value) {
  throw_output_error(action, path, std::strerror(errno_value));
}

void fail_assertion(const char* condition, const char* file, int line) {
  throw InternalError(std::string(file) + ":" + std::to_string(line) +
                      ": check failed: " + condition);
}

std::string escape_controls(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto u = static_cast<unsigned char>(text[i]);
    char buffer[8];
    if (u == '\n' || u == '\t' || u == '\r') {
      out += '\\';
      out += u == '\n' ? 'n' : u == '\t' ? 't' : 'r';
    } else if (u < 0x20 || u == 0x7f) {
      std::snprintf(buffer, sizeof buffer, "\\x%02x", u);
      out += buffer;
    } else if (u == 0xc2 && i + 1 < text.size() &&
               static_cast<unsigned char>(text[i + 1]) >= 0x80 &&
               static_cast<unsigned char>(text[i + 1]) <= 0x9f) {
      std::snprintf(buffer, sizeof buffer, "\\u%04x", static_cast<unsigned char>(text[++i]));
      out += buffer;
    } else {
      out += text[i];
    }
  }
  return out;
}

}  // namespace bookspin
