#include "common/number_text.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <string>

#include "common/errors.hpp"

#if defined(__EMSCRIPTEN__)
#include <emscripten.h>
#endif

namespace bookspin {

namespace {

#if !(defined(__cpp_lib_to_chars) && __cpp_lib_to_chars >= 201611L) && defined(__EMSCRIPTEN__)
/// The shortest digits that read back as `value`, the nearest of them to it, as JavaScript's
/// Number.prototype.toExponential() spells them ("1.5e+2", "-3e-7"), into `out` (`size` bytes):
/// its length. Where the C library would print and read back a double once for each count of
/// digits, in WebAssembly's software long double (musl's printf and strtod), at about 3 µs
/// each (docs/performance-build.md, "The npm package against the command line").
EM_JS(int, javascript_exponential, (double value, char* out, int size),
      { return stringToUTF8(value.toExponential(), out, size); });
#endif

#if defined(__EMSCRIPTEN__)
/// The double nearest to the decimal number `text` (`length` ASCII bytes, checked by
/// read_number()), as JavaScript's Number() reads it: correctly rounded, as strtod, which in
/// WebAssembly reads through a software long double at about 2 µs a number.
EM_JS(double, javascript_number, (const char* text, int length), {
  var spelled = "";
  for (var k = 0; k < length; ++k) spelled += String.fromCharCode(HEAPU8[text + k]);
  return Number(spelled);
});
#endif

/// `value` (finite) in the shortest text that reads back, as std::to_chars(first, last, value)
/// spells it: the fewest significant digits that round-trip, in fixed or scientific notation
/// ("1e-05", "1e+22"), whichever is shorter, fixed on a tie. std::to_chars where the library has
/// it for doubles (__cpp_lib_to_chars); else (emscripten's libc++, which compiles the explorer
/// page's and the npm package's writers) the digits of JavaScript's toExponential(), the fewest
/// that read back, the nearest of them to `value` (as to_chars chooses them), laid out here.
std::string shortest_text(double value) {
  char buffer[40];
#if defined(__cpp_lib_to_chars) && __cpp_lib_to_chars >= 201611L
  return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
#else
  if (value == 0.0) return std::signbit(value) ? "-0" : "0";
#if defined(__EMSCRIPTEN__)
  javascript_exponential(value, buffer, sizeof buffer);
#else
  for (int precision = 0; precision < 17; ++precision) {
    std::snprintf(buffer, sizeof buffer, "%.*e", precision, value);
    if (std::strtod(buffer, nullptr) == value) break;
  }
#endif
  // buffer: [-]d[.ddd]e±X. Laid out in arrays, no std::string but the one returned: in
  // WebAssembly every call that may throw goes through JavaScript (docs/performance-build.md, "The
  // npm package against the command line").
  const bool negative = buffer[0] == '-';
  char digits[24];
  int n = 0;
  const char* at = buffer + (negative ? 1 : 0);
  for (; *at != 'e'; ++at)
    if (*at != '.') digits[n++] = *at;
  while (n > 1 && digits[n - 1] == '0') --n;
  const int exponent = std::atoi(at + 1);
  const int magnitude = std::abs(exponent);
  const int scientific_size = n + (n > 1 ? 1 : 0) + 2 + (magnitude >= 100 ? 3 : 2);
  char integer[400] = "";
  if (exponent + 1 >= n)  // an integer: to_chars writes its exact digits (4162706789455549952)
    std::snprintf(integer, sizeof integer, "%.0f", std::abs(value));
  const int fixed_size = exponent + 1 >= n ? static_cast<int>(std::strlen(integer))
                         : exponent >= 0   ? n + 1
                                           : n + 1 - exponent;
  if (exponent + 1 >= n && fixed_size <= scientific_size)
    return (negative ? "-" : "") + std::string(integer);
  char out[48];
  int k = 0;
  if (negative) out[k++] = '-';
  if (fixed_size <= scientific_size && exponent < 0) {
    out[k++] = '0';
    out[k++] = '.';
    for (int zero = 0; zero < -exponent - 1; ++zero) out[k++] = '0';
    for (int d = 0; d < n; ++d) out[k++] = digits[d];
  } else if (fixed_size <= scientific_size) {
    for (int d = 0; d < n; ++d) {
      if (d == exponent + 1) out[k++] = '.';
      out[k++] = digits[d];
    }
  } else {
    out[k++] = digits[0];
    if (n > 1) out[k++] = '.';
    for (int d = 1; d < n; ++d) out[k++] = digits[d];
    out[k++] = 'e';
    out[k++] = exponent < 0 ? '-' : '+';
    if (magnitude >= 100) out[k++] = static_cast<char>('0' + magnitude / 100);
    out[k++] = static_cast<char>('0' + magnitude / 10 % 10);
    out[k++] = static_cast<char>('0' + magnitude % 10);
  }
  return std::string(out, static_cast<std::size_t>(k));
#endif
}

}  // namespace

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
      return shortest_text(value);
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

std::string plus_minus(double value, double sigma) {
  char text[128];
  if (!std::isfinite(value)) {
    std::snprintf(text, sizeof text, "%g", value);
    return text;
  }
  if (!(std::isfinite(sigma) && sigma > 0.0)) {
    std::snprintf(text, sizeof text, sigma == 0.0 ? "%.4g ± 0" : "%.4g", value);
    return text;
  }
  // σ's leading exponent after its rounding to two digits (0.0995 → 0.10: place −2), read from
  // the decimal text, as log10 is one off near powers of ten.
  char rounded[32];
  std::snprintf(rounded, sizeof rounded, "%.1e", sigma);
  const int place = std::atoi(std::strchr(rounded, 'e') + 1) - 1;  // the last digit kept
  if (place < 0) {
    std::snprintf(text, sizeof text, "%.*f ± %.*f", -place, value, -place, sigma);
  } else {
    const double step = std::pow(10.0, place);
    std::snprintf(text, sizeof text, "%.0f ± %.0f", std::round(value / step) * step,
                  std::round(sigma / step) * step);
  }
  std::string out = text;
  // "-0.000 ± …": a value that rounds to zero has no sign.
  if (out[0] == '-' && out.find_first_not_of("-0.", 0) == out.find(' ')) out.erase(0, 1);
  return out;
}

std::optional<double> read_number(std::string_view text) {
  const auto lower_is = [&](std::string_view word, std::size_t at) {
    if (text.size() - at != word.size()) return false;
    for (std::size_t i = 0; i < word.size(); ++i)
      if ((text[at + i] | 0x20) != word[i]) return false;
    return true;
  };
  std::size_t i = 0;
  const bool negative = !text.empty() && text[0] == '-';
  if (negative) ++i;
  if (lower_is("nan", i)) return negative ? -std::nan("") : std::nan("");
  if (lower_is("inf", i) || lower_is("infinity", i)) return negative ? -HUGE_VAL : HUGE_VAL;
  bool digits = false, nonzero = false;
  const auto digit_run = [&] {
    while (i < text.size() && text[i] >= '0' && text[i] <= '9') {
      digits = true;
      nonzero = nonzero || text[i] != '0';
      ++i;
    }
  };
  digit_run();
  if (i < text.size() && text[i] == '.') {
    ++i;
    digit_run();
  }
  if (!digits) return std::nullopt;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    std::size_t j = i + 1;
    if (j < text.size() && (text[j] == '+' || text[j] == '-')) ++j;
    const std::size_t exponent = j;
    while (j < text.size() && text[j] >= '0' && text[j] <= '9') ++j;
    // An 'e' with no exponent after it ends the number before it, as from_chars reads it.
    if (j > exponent) i = j;
  }
  if (i != text.size()) return std::nullopt;
#if defined(__EMSCRIPTEN__)
  const double value = javascript_number(text.data(), static_cast<int>(text.size()));
#else
  const std::string copy(text);
  const double value = std::strtod(copy.c_str(), nullptr);
#endif
  if (!std::isfinite(value) || (value == 0.0 && nonzero)) return std::nullopt;
  return value;
}

namespace {

/// The value strtod reads from all of `text`, a decimal number as written (an optional sign,
/// digits, '.', an exponent), out of the doubles' range or not; nullopt for other text.
std::optional<double> decimal_value(std::string_view text) {
  std::string_view digits = text;
  if (!digits.empty() && (digits[0] == '+' || digits[0] == '-')) digits.remove_prefix(1);
  if (digits.empty() ||
      !(std::isdigit(static_cast<unsigned char>(digits[0])) || digits[0] == '.') ||
      digits.find_first_not_of("0123456789.eE+-") != std::string_view::npos)
    return std::nullopt;
  const std::string copy(text);
  char* end = nullptr;
  const double value = std::strtod(copy.c_str(), &end);
  if (end != copy.c_str() + copy.size()) return std::nullopt;
  return value;
}

}  // namespace

bool below_doubles(std::string_view text) {
  const std::optional<double> value = decimal_value(text);
  if (!value || *value != 0.0) return false;
  const std::string_view mantissa = text.substr(0, text.find_first_of("eE"));
  return mantissa.find_first_of("123456789") != std::string_view::npos;  // not a zero
}

std::string out_of_range_reason(std::string_view text) {
  if (beyond_doubles(text)) return kBeyondDoubles;
  if (below_doubles(text)) return kBelowDoubles;
  return "";
}

bool beyond_doubles(std::string_view text) {
  const std::optional<double> value = decimal_value(text);
  return value && std::isinf(*value);
}

}  // namespace bookspin
