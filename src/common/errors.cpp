#include "common/errors.hpp"

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

}  // namespace bookspin
