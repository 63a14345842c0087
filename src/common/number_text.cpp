#include "common/number_text.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "common/errors.hpp"

namespace bookspin {

double finite(double value, std::string_view what) {
  if (std::isfinite(value)) return value;
  const char* shown = std::isnan(value) ? "nan" : value > 0 ? "inf" : "-inf";
  std::string message = "non-finite ";
  message.append(what).append(" in an output: ").append(shown);
  throw InternalError(message);
}

std::string finite_text(double value, std::string_view what, NumberStyle style) {
  finite(value, what);
  char buffer[40];
  switch (style) {
    case NumberStyle::shortest:
      return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
    case NumberStyle::digits17:
      std::snprintf(buffer, sizeof buffer, "%.17g", value);
      return buffer;
    case NumberStyle::fewest_g:
      for (int digits = 15; digits <= 17; ++digits) {
        std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
        if (std::strtod(buffer, nullptr) == value) break;
      }
      return buffer;
  }
  BOOKSPIN_ASSERT(false);
  return {};
}

std::string finite_text(const std::optional<double>& value, std::string_view what,
                        NumberStyle style) {
  return value ? finite_text(*value, what, style) : std::string();
}

std::string finite_text(double value, std::string_view what, const char* format) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, finite(value, what));
  return buffer;
}

}  // namespace bookspin
