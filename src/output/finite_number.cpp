#include "output/finite_number.hpp"

#include <charconv>
#include <cmath>

#include "common/errors.hpp"

namespace bookspin::output {

double finite(double value, std::string_view what) {
  if (std::isfinite(value)) return value;
  const char* shown = std::isnan(value) ? "nan" : value > 0 ? "inf" : "-inf";
  std::string message = "non-finite ";
  message.append(what).append(" in an output: ").append(shown);
  throw InternalError(message);
}

std::string finite_text(double value, std::string_view what) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, finite(value, what));
  return std::string(buffer, result.ptr);
}

std::string finite_text(const std::optional<double>& value, std::string_view what) {
  return value ? finite_text(*value, what) : std::string();
}

}  // namespace bookspin::output
