#include "fit/fit_options.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "common/errors.hpp"
#include "common/file_name.hpp"
#include "common/number_text.hpp"
#include "fit/fit_tables.hpp"
#include "fit/recording.hpp"

namespace bookspin::fit {
namespace {

/// "\"TEXT\" WHY", appended piece by piece (GCC 12 warns, -Wrestrict, about a literal + string
/// + literal chain here).
std::string quoted_and(const std::string& text, const char* why) {
  std::string line = "\"";
  line.append(text).append("\" ").append(why);
  return line;
}

/// "is not a number", naming the invisible characters `text` holds (a thin space, a mark of
/// direction a copy from a document brings: "0.75\u2009" looks like "0.75 "), which the quoted
/// text alone does not show.
std::string not_a_number(const std::string& text) {
  const std::string invisible = invisible_characters(text);
  if (invisible.empty()) return "is not a number";
  const bool one = invisible.find(',') == std::string::npos;
  return "is not a number: it holds " + invisible +
         (one ? ", a character that shows" : ", characters that show") +
         " as nothing or as a space (type the number again)";
}

std::string trimmed_part(const std::string& part) {
  const std::size_t begin = part.find_first_not_of(" \t");
  if (begin == std::string::npos) return std::string();
  return part.substr(begin, part.find_last_not_of(" \t") - begin + 1);
}

/// The shortest text that reads back as `value` ("0.1", "1e+308", "inf", "nan").
std::string shortest(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  return finite_text(value, "an option's value");
}

/// The ranges of `text`, each end as read_number reads it (NaN and infinity as such), or the
/// cause of the first part that is not START:END or not a number, in `error`.
std::vector<std::pair<double, double>> read_ranges(const std::string& text, std::string& error) {
  std::vector<std::pair<double, double>> ranges;
  std::size_t begin = 0;
  while (begin <= text.size()) {
    const std::size_t comma = std::min(text.find(',', begin), text.size());
    const std::string range = text.substr(begin, comma - begin);
    const std::size_t colon = range.find(':');
    if (colon == std::string::npos || range.find(':', colon + 1) != std::string::npos) {
      error = quoted_and(trimmed_part(range), "is not START:END");
      return {};
    }
    double ends[2];
    const std::string parts[2] = {range.substr(0, colon), range.substr(colon + 1)};
    for (int i = 0; i < 2; ++i) {  // the start named first where both are bad
      const std::string given = trimmed_part(parts[i]);
      const std::optional<double> value = read_number(given);
      if (!value) {
        const std::string range = out_of_range_reason(given);
        error = !range.empty() ? quoted_and(given, "is ") + range
                               : quoted_and(given, not_a_number(given).c_str());
        return {};
      }
      if (!std::isfinite(*value)) {  // "inf", "nan" typed: quoted as given
        error = quoted_and(given, "is not a finite time (s)");
        return {};
      }
      ends[i] = *value;
    }
    ranges.emplace_back(ends[0], ends[1]);
    begin = comma + 1;
  }
  return ranges;
}

/// `text` with each comma between two digits made a decimal point: what a decimal comma meant.
std::string with_decimal_points(std::string text) {
  const auto digit = [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; };
  for (std::size_t i = 1; i + 1 < text.size(); ++i)
    if (text[i] == ',' && digit(text[i - 1]) && digit(text[i + 1])) text[i] = '.';
  return text;
}

}  // namespace

FitOptionNames fit_option_names(Reader reader) {
  switch (reader) {
    case Reader::page:
      return {"flights by hand", "air drag", "moments"};
    case Reader::python:
      return {"tosses", "drag", "moments"};
    case Reader::command_line:
      break;
  }
  return {"--tosses", "--drag", "--moments"};
}

std::string toss_time_text(double t) {
  if (!(std::fabs(t) < 1e6)) return shortest(t);
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", t);
  return text;
}

std::vector<std::pair<double, double>> parse_toss_ranges(const std::string& text,
                                                         const std::string& option) {
  if (trimmed_part(text).empty()) return {};
  std::string error;
  const std::vector<std::pair<double, double>> ranges = read_ranges(text, error);
  if (!error.empty()) {
    // "2,93:3,58" read as "2", "93:3", "58": where the text with decimal points reads whole,
    // say so.
    const std::string fixed = with_decimal_points(text);
    std::string fixed_error;
    if (fixed != text && (read_ranges(fixed, fixed_error), fixed_error.empty()))
      error += " (a decimal comma? write " + trimmed_part(fixed) + ")";
    throw InputError(option + ": " + error);
  }
  check_toss_ranges(ranges, option);
  return ranges;
}

void check_toss_ranges(const std::vector<std::pair<double, double>>& ranges,
                       const std::string& option) {
  for (const auto& [start, end] : ranges)
    for (const double t : {start, end})
      if (!std::isfinite(t))
        throw InputError(option + ": \"" + shortest(t) + "\" is not a finite time (s)");
}

physics::DragLaw parse_drag_option(const std::string& text, const std::string& option) {
  physics::DragLaw law = physics::DragLaw::linear;
  if (!physics::parse_drag_law(text, law))
    throw InputError(option + ": \"" + text + "\" is not none, linear or quadratic");
  return law;
}

Eigen::Vector3d parse_moments(const std::string& text, const std::string& option) {
  std::vector<std::string> parts;
  for (std::size_t begin = 0;;) {
    const std::size_t comma = text.find(',', begin);
    parts.push_back(
        trimmed_part(text.substr(begin, comma == std::string::npos ? comma : comma - begin)));
    if (comma == std::string::npos) break;
    begin = comma + 1;
  }
  if (parts.size() != 3) throw InputError(option + ": expected I1,I2,I3");
  Eigen::Vector3d moments;
  for (int i = 0; i < 3; ++i) {
    const std::string& given = parts[static_cast<std::size_t>(i)];
    const std::optional<double> value = read_number(given);
    if (!value) {
      const std::string range = out_of_range_reason(given);
      throw InputError(option + ": \"" + given + "\" is " +
                       (!range.empty() ? range + ": not a positive finite number"
                                       : not_a_number(given).substr(3)));
    }
    if (!std::isfinite(*value))  // "inf", "nan" typed: quoted as given
      throw InputError(option + ": \"" + given + "\" is not a positive finite number");
    moments[i] = *value;
  }
  check_moments(moments, option);
  return moments;
}

void check_moments(const Eigen::Vector3d& moments, const std::string& option) {
  for (int i = 0; i < 3; ++i)
    if (!(moments[i] > 0) || !std::isfinite(moments[i]))
      throw InputError(option + ": \"" + shortest(moments[i]) +
                       "\" is not a positive finite number");
  // A rigid body's principal moments obey the triangle inequality, the two smaller summing to
  // at least the largest (docs/physics.md §11: I1 + I2 - I3 = 2 ∫ z² dm ≥ 0); a flat body has
  // the equality, kept within the rounding of a typed decimal.
  Eigen::Vector3d sorted = moments;
  std::sort(sorted.begin(), sorted.end());
  if (sorted[0] + sorted[1] < sorted[2] * (1 - 1e-12))
    throw InputError(option + ": " + shortest(sorted[0]) + " + " + shortest(sorted[1]) + " < " +
                     shortest(sorted[2]) +
                     ": no rigid body has these principal moments (the two smaller sum to at "
                     "least the largest)");
}

}  // namespace bookspin::fit
