#include "render/render_error.hpp"

#include <algorithm>

namespace bookspin::render {

namespace {
// Driver logs (shader info logs) come with newlines; the message must stay one line.
std::string one_line(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  std::replace(text.begin(), text.end(), '\r', ' ');
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text;
}
}  // namespace

RenderError::RenderError(const std::string& message) : std::runtime_error(one_line(message)) {}

}  // namespace bookspin::render
