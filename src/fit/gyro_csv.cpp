// The samples of a gyroscope recording's CSV (docs/phone-lab.md, "The recording"): phyphox's
// dialects (comma, tab, semicolon with decimal commas), a labelled header in any unit, a
// whitespace-separated text export, and a plain t,wx,wy,wz CSV.
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <optional>
#include <utility>

#include "common/errors.hpp"
#include "common/file_name.hpp"
#include "common/number_text.hpp"
#include "common/text_lines.hpp"
#include "fit/recording.hpp"
#include "fit/recording_text.hpp"

namespace bookspin::fit {
namespace {

using recording_text::csv_rows;
using recording_text::kMinSamples;
using recording_text::lines_of;
using recording_text::lower;
using recording_text::not_a_number;
using recording_text::parse_number;

bool is_phyphox_gyro_header(const std::vector<std::string>& header) {
  if (header.size() != 4 && header.size() != 5) return false;
  const std::string axes = "xyz";
  if (lower(header[0]).rfind("time (s)", 0) != 0) return false;
  for (int i = 0; i < 3; ++i) {
    const std::string cell = lower(header[i + 1]);
    if (cell != std::string("gyroscope ") + axes[i] + " (rad/s)") return false;
  }
  return header.size() == 4 || lower(header[4]).rfind("absolute", 0) == 0;
}

/// The cells of a whitespace-separated line: split at runs of spaces and tabs, a "(unit)" kept
/// with the name before it ("ωₓ (rad/s)" one cell).
std::vector<std::string> whitespace_cells(std::string_view line) {
  std::vector<std::string> cells;
  std::size_t i = 0;
  while (true) {
    i = line.find_first_not_of(" \t", i);
    if (i == std::string_view::npos) return cells;
    const std::size_t end = std::min(line.find_first_of(" \t", i), line.size());
    const std::string_view word = line.substr(i, end - i);
    if (word.front() == '(' && !cells.empty())
      cells.back().append(" ").append(word);
    else
      cells.emplace_back(word);
    i = end;
  }
}

/// A column name without its unit, lowered, and its "(unit)" ("" without one).
std::pair<std::string, std::string> name_and_unit(const std::string& cell) {
  const std::size_t open = cell.find('(');
  const std::size_t close = cell.rfind(')');
  if (open == std::string::npos || close == std::string::npos || close < open)
    return {lower(std::string(trimmed(cell))), ""};
  return {lower(std::string(trimmed(cell.substr(0, open)))),
          lower(std::string(trimmed(cell.substr(open + 1, close - open - 1))))};
}

/// The axis ("x", "y", "z") a column named `name` (name_and_unit's) holds ω about: "wx", "ωₓ",
/// "ω_y", "omega z", "gyro x", "gyroscope z", …; "" for any other name.
std::string omega_axis(std::string name) {
  // The subscripts people type: ₓ (U+2093), ᵧ (U+1D67, gamma, used for y), ᶻ (U+1DBB).
  for (const auto& [from, to] : {std::pair<const char*, const char*>{"\u2093", "x"},
                                 {"\u1d67", "y"},
                                 {"\u1dbb", "z"},
                                 {"\u03c9", "w"}}) {
    for (std::size_t at = name.find(from); at != std::string::npos; at = name.find(from))
      name.replace(at, std::string(from).size(), to);
  }
  std::string bare;
  for (char c : name)
    if (c != '_' && c != ' ' && c != '-') bare += c;
  for (const char* prefix : {"gyroscope", "gyro", "omega", "w"})
    if (bare.rfind(prefix, 0) == 0 && bare.size() == std::string(prefix).size() + 1) {
      const char axis = bare.back();
      if (axis == 'x' || axis == 'y' || axis == 'z') return std::string(1, axis);
    }
  return "";
}

/// rad/s in one unit an ω column's header states: 1 for rad/s (or none stated), π/180 for
/// degrees per second; nullopt for any other unit.
std::optional<double> omega_unit(const std::string& unit) {
  if (unit.empty() || unit == "rad/s" || unit == "rad s^-1" || unit == "rad s-1") return 1.0;
  if (unit == "\u00b0/s" || unit == "deg/s" || unit == "dps") return 3.14159265358979323846 / 180.0;
  return std::nullopt;
}

/// Whether a column named `name` (name_and_unit's) holds |ω|: "ω_total", "w total", "|ω|",
/// "absolute", "omega norm", "magnitude".
bool is_omega_total(std::string name) {
  for (const auto& [from, to] : {std::pair<const char*, const char*>{"\u03c9", "w"}, {"|", ""}})
    for (std::size_t at = name.find(from); at != std::string::npos; at = name.find(from))
      name.replace(at, std::string(from).size(), to);
  std::string bare;
  for (char c : name)
    if (c != '_' && c != ' ' && c != '-') bare += c;
  for (const char* prefix : {"", "w", "omega", "gyro", "gyroscope"})
    for (const char* word : {"total", "abs", "absolute", "norm", "magnitude"})
      if (bare == std::string(prefix) + word) return true;
  return bare == "w" || bare == "omega";
}

/// Seconds in one unit a time column's header states: 1 for s (or none stated), 1e-3 for ms,
/// 1e-6 for µs (us, µs or μs), 1e-9 for ns; nullopt for any other unit.
std::optional<double> time_unit_seconds(const std::string& unit) {
  if (unit.empty() || unit == "s") return 1.0;
  if (unit == "ms") return 1e-3;
  if (unit == "us" || unit == "\u00b5s" || unit == "\u03bcs") return 1e-6;
  if (unit == "ns") return 1e-9;
  return std::nullopt;
}

/// A labelled header: the time column's scale to seconds, each ω column's to rad/s, and the
/// scale of a fifth column holding |ω| (nullopt without one).
struct LabelledHeader {
  double time_scale = 1.0;
  std::array<double, 3> scale{};
  std::optional<double> total_scale;
};

/// A header naming time and ω about x, y, z in that order ("t (s)", "ωₓ (rad/s)", "ωᵧ
/// (rad/s)", "ωᶻ (rad/s)"), and optionally |ω| after them ("ω_total (rad/s)"); a time without
/// its unit is in seconds, one in ms, µs or ns converted (docs/phone-lab.md, "The recording").
/// Nullopt for any other header.
std::optional<LabelledHeader> labelled_gyro_header(const std::vector<std::string>& header) {
  if (header.size() != 4 && header.size() != 5) return std::nullopt;
  const auto [time, time_unit] = name_and_unit(header[0]);
  const std::optional<double> seconds = time_unit_seconds(time_unit);
  if ((time != "t" && time != "time") || !seconds) return std::nullopt;
  LabelledHeader labelled;
  labelled.time_scale = *seconds;
  for (int i = 0; i < 3; ++i) {
    const auto [name, unit] = name_and_unit(header[i + 1]);
    const std::optional<double> to_rad = omega_unit(unit);
    if (omega_axis(name) != std::string(1, "xyz"[i]) || !to_rad) return std::nullopt;
    labelled.scale[static_cast<std::size_t>(i)] = *to_rad;
  }
  if (header.size() == 5) {
    const auto [name, unit] = name_and_unit(header[4]);
    labelled.total_scale = omega_unit(unit);
    if (!is_omega_total(name) || !labelled.total_scale) return std::nullopt;
  }
  return labelled;
}

/// A recording's cells are numbers and its header's names one line each: a quoted cell over a
/// line end is a quote left open, in any column, read or not (else the next line's time reads as
/// this cell's, or the header's last name swallows the rows). Throws InputError naming the row,
/// the column (`names`; "header" for the header row itself, `names` empty) and the line the cell
/// closes on, each line end ("\r\n", "\n" or a lone "\r", as next_line counts them) once.
void check_quotes_closed(const std::vector<std::string>& cells,
                         const std::vector<std::string>& names, int number,
                         const std::string& file) {
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const std::string& cell = cells[c];
    int ends = 0;
    for (std::size_t k = 0; k < cell.size(); ++k)
      ends += cell[k] == '\n' || (cell[k] == '\r' && (k + 1 == cell.size() || cell[k + 1] != '\n'));
    if (ends > 0)
      throw InputError(file, number,
                       names.empty()      ? "header"
                       : c < names.size() ? names[c]
                                          : "",
                       "a quote opens a cell on this row (" +
                           quoted_cell(cell.substr(0, cell.find_first_of("\r\n"))) +
                           " and the line's end) and closes it on line " +
                           std::to_string(number + ends) + ": a quote left open?");
  }
}

bool is_plain_header(const std::vector<std::string>& header) {
  return header == std::vector<std::string>{"t", "wx", "wy", "wz"};
}

/// A decimal number's text as sign, significant digits (no leading or trailing zeros) and the
/// power of ten of its first digit, for comparing two texts exactly; nullopt for other text.
struct Decimal {
  bool negative = false;
  std::string digits;  // empty for zero
  long exponent = 0;
};
std::optional<Decimal> decimal_of(std::string text, bool decimal_comma) {
  if (decimal_comma) std::replace(text.begin(), text.end(), ',', '.');
  Decimal d;
  std::size_t i = 0;
  if (i < text.size() && (text[i] == '+' || text[i] == '-')) d.negative = text[i++] == '-';
  long point = -1, count = 0;
  std::string all;
  for (; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '.' && point < 0) {
      point = count;
    } else if (std::isdigit(static_cast<unsigned char>(c))) {
      all += c;
      ++count;
    } else {
      break;
    }
  }
  if (all.empty()) return std::nullopt;
  long exponent = 0;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    // The exponent's own sign, written or not ("e15", "e+15", "e-3").
    const std::size_t at = i + 1 + (i + 1 < text.size() && text[i + 1] == '+' ? 1 : 0);
    const std::optional<double> e = read_number(text.substr(at));
    if (!e || std::fabs(*e) > 1e6 || *e != std::floor(*e)) return std::nullopt;
    exponent = static_cast<long>(*e);
  } else if (i != text.size()) {
    return std::nullopt;
  }
  if (point < 0) point = count;
  const std::size_t first = all.find_first_not_of('0');
  if (first == std::string::npos) return Decimal{};  // zero, whatever its sign
  d.digits = all.substr(first, all.find_last_not_of('0') - first + 1);
  d.exponent = exponent + point - static_cast<long>(first) - 1;
  return d;
}

/// Whether decimal text `a` is a larger number than `b` (false where either is not one).
bool decimal_greater(const std::string& a, const std::string& b, bool decimal_comma) {
  const std::optional<Decimal> x = decimal_of(a, decimal_comma), y = decimal_of(b, decimal_comma);
  if (!x || !y) return false;
  const auto sign = [](const Decimal& d) { return d.digits.empty() ? 0 : d.negative ? -1 : 1; };
  if (sign(*x) != sign(*y)) return sign(*x) > sign(*y);
  if (sign(*x) == 0) return false;
  // Same sign: compare magnitudes, then flip for negatives.
  int magnitude = 0;
  if (x->exponent != y->exponent) {
    magnitude = x->exponent > y->exponent ? 1 : -1;
  } else {
    const int c = x->digits.compare(y->digits);  // same exponent: digit by digit
    magnitude = c > 0 ? 1 : c < 0 ? -1 : 0;
  }
  return sign(*x) > 0 ? magnitude > 0 : magnitude < 0;
}

/// Why the time `cell` (read as a double no larger than `previous`, the previous row's, written
/// `previous_cell`) is refused: where the text is larger and the two read as one double, that
/// a double cannot tell them apart at that size (its step there), else that time does not
/// increase.
std::string time_not_increasing(const std::string& cell, const std::string& previous_cell,
                                double previous, bool decimal_comma) {
  if (decimal_greater(cell, previous_cell, decimal_comma)) {
    const double step = std::nextafter(std::fabs(previous), HUGE_VAL) - std::fabs(previous);
    return "time " + cut_cell(cell) + " is after the previous row's " + cut_cell(previous_cell) +
           " in the file, but a double cannot tell them apart: both read as " +
           finite_text(previous, "a time") + " s, where a double's step is " +
           finite_text(step, "a double's step") +
           " s (subtract the first time from every time, or write them as offsets)";
  }
  return "time does not increase (" + cut_cell(cell) + " after the previous row's)";
}

/// Throws InputError where a row's |ω| column (`total`, rad/s) disagrees with the norm of its
/// three axes (`omega`, rad/s) beyond a printed value's rounding (1 % and 0.01 rad/s): the
/// columns then do not hold what the header says. Where one axis taken in the other unit (°/s
/// for rad/s or back) makes the norm agree, that axis is named: mixed units.
void check_total(const Eigen::Vector3d& omega, double total, const std::string& file, int number,
                 const std::vector<std::string>& header) {
  const auto agrees = [&](const Eigen::Vector3d& w) {
    return std::fabs(total - w.norm()) <= 0.01 * std::max(w.norm(), std::fabs(total)) + 0.01;
  };
  if (agrees(omega)) return;
  const double degree = 3.14159265358979323846 / 180.0;
  std::string cause =
      "the columns do not hold what the header says (an axis in another unit, "
      "or in another order?)";
  for (int i = 0; i < 3; ++i)
    for (const double factor : {degree, 1.0 / degree}) {
      Eigen::Vector3d w = omega;
      w[i] *= factor;
      if (agrees(w) && !agrees(omega))
        cause = "mixed units? " + header[static_cast<std::size_t>(i) + 1] + " holds " +
                (factor == degree ? "°/s" : "rad/s") +
                ", not the unit its header says (taken so, the axes' norm is |ω|)";
    }
  throw InputError(file, number, header[4],
                   "|ω| is " + finite_text(total, "|ω|", "%.4g") +
                       " rad/s where the three axes' norm is " +
                       finite_text(omega.norm(), "|ω|", "%.4g") + " rad/s: " + cause);
}

}  // namespace

GyroRecording parse_gyro_csv(std::string_view text, const std::string& file,
                             const std::string& name) {
  text = without_bom(text);  // a spreadsheet's byte-order mark before the header
  if (const auto nul = nul_byte_problem(text)) throw InputError(file, 0, "", *nul);
  const auto lines = lines_of(text);
  if (lines.empty()) throw InputError(file, 0, "", "not a gyroscope recording: the file is empty");
  // Tab, semicolon (a decimal comma) or comma as phyphox writes; else, with none of them,
  // cells separated by spaces (a text export: "t (s)  ωₓ (rad/s) …").
  const auto separator_of = [](std::string_view line) {
    return line.find('\t') != std::string_view::npos  ? '\t'
           : line.find(';') != std::string_view::npos ? ';'
           : line.find(',') != std::string_view::npos ? ','
           : line.find(' ') != std::string_view::npos ? ' '
                                                      : ',';
  };
  // A table whose header is its last comment before the numbers ("#time  ωₓ (rad/s) …", as a
  // text export writes it): that comment, without its '#', is the header, and says the
  // separator.
  const auto [head_line, head] = lines.front();
  std::optional<std::pair<int, std::string_view>> comment;
  {
    int number = 0;
    for (std::size_t at = 0; at < text.size() && number + 1 < head_line;) {
      const TextLine line = next_line(text, at);
      ++number;
      const std::string_view bare = trimmed(line.line);
      if (!bare.empty() && bare.front() == '#') comment.emplace(number, trimmed(bare.substr(1)));
      at = line.next;
    }
  }
  const auto all_numbers = [](const std::vector<std::string>& cells, bool comma) {
    bool numbers = cells.size() >= 4;
    for (const std::string& cell : cells)
      numbers = numbers && parse_number(cell, comma).has_value();
    return numbers;
  };
  const char head_separator = separator_of(head);
  const bool header_in_comment =
      comment && !comment->second.empty() &&
      all_numbers(head_separator == ' ' ? whitespace_cells(head)
                                        : next_csv_record(head, 0, head_separator).cells,
                  head_separator == ';');
  const char separator = header_in_comment ? separator_of(comment->second) : head_separator;
  const int header_line = header_in_comment ? comment->first : head_line;
  const bool decimal_comma = separator == ';';
  // The rows, the header first: quoted cells read as RFC 4180 reads them, or a whitespace
  // table's words.
  std::vector<std::pair<int, std::vector<std::string>>> rows;
  if (separator == ' ')
    for (const auto& [number, line] : lines) rows.emplace_back(number, whitespace_cells(line));
  else
    rows = csv_rows(text, separator, file);
  if (header_in_comment)
    rows.insert(
        rows.begin(),
        {header_line, separator == ' ' ? whitespace_cells(comment->second)
                                       : next_csv_record(comment->second, 0, separator).cells});
  const std::vector<std::string>& header = rows.front().second;
  check_quotes_closed(header, {}, header_line, file);
  const std::optional<LabelledHeader> labelled = labelled_gyro_header(header);
  const bool phyphox = is_phyphox_gyro_header(header);
  if (!phyphox && !is_plain_header(header) && !labelled) {
    // A quote left open in the header's line (an odd count: the cell it opens swallowed the
    // separator after it) is the cause, not the names it garbled: named as in a data row.
    const std::string_view header_text = header_in_comment ? comment->second : head;
    const auto quotes = std::count(header_text.begin(), header_text.end(), '"');
    if (quotes % 2 == 1) {
      std::string garbled;  // the first name that holds a separator or a quote
      for (const std::string& cell : header)
        if (garbled.empty() &&
            cell.find_first_of(std::string("\"") + separator) != std::string::npos)
          garbled = cell;
      throw InputError(file, header_line, "header",
                       "a quote left open: the line holds " + std::to_string(quotes) +
                           " quotes, one without its partner" +
                           (garbled.empty() ? std::string()
                                            : ", and reads as the name " + quoted_cell(garbled)));
    }
  }
  if (!phyphox && !is_plain_header(header) && !labelled)
    throw InputError(file, header_line, "header",
                     separator == ' '
                         ? "not a gyroscope recording: a whitespace-separated table whose " +
                               std::to_string(header.size()) +
                               " column names are not time (s) and ω about x, y, z (rad/s or "
                               "°/s), as \"t (s)  ωₓ (rad/s)  ωᵧ (rad/s)  ω_z (rad/s)\""
                         : "not a gyroscope recording: expected phyphox's \"Time (s)\", "
                           "\"Gyroscope x (rad/s)\", ... or t,wx,wy,wz");
  const std::array<double, 3> scale =
      labelled ? labelled->scale : std::array<double, 3>{1.0, 1.0, 1.0};
  const double time_scale = labelled ? labelled->time_scale : 1.0;
  // |ω| beside the axes (phyphox's "Absolute (rad/s)", a text export's "ω_total"): checked.
  double total_scale = 1.0;  // phyphox's Absolute is in rad/s
  bool has_total = !labelled && phyphox && header.size() == 5;
  if (labelled && labelled->total_scale) {
    has_total = true;
    total_scale = *labelled->total_scale;
  }
  const int columns = has_total ? 5 : 4;
  GyroRecording recording;
  recording.name = file_name_of(name);
  recording.source = file;
  recording.t.reserve(rows.size());
  recording.omega.reserve(rows.size());
  std::string previous_time;  // the previous row's time as written
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const auto& [number, cells] = rows[i];
    check_quotes_closed(cells, header, number, file);
    if (static_cast<int>(cells.size()) < columns)
      throw InputError(file, number, "",
                       "a row of " + std::to_string(cells.size()) + " cells, expected " +
                           std::to_string(header.size()));
    double values[5];
    for (int c = 0; c < columns; ++c) {
      const std::optional<double> value = parse_number(cells[c], decimal_comma);
      if (!value) throw InputError(file, number, header[c], not_a_number(cells[c], decimal_comma));
      if (!std::isfinite(*value))
        throw InputError(file, number, header[c], "not a finite number: " + quoted_cell(cells[c]));
      values[c] = c == 0 ? time_scale * *value : *value;
    }
    if (!recording.t.empty() && values[0] <= recording.t.back())
      throw InputError(
          file, number, header[0],
          time_not_increasing(cells[0], previous_time, recording.t.back(), decimal_comma));
    previous_time = cells[0];
    const Eigen::Vector3d omega(scale[0] * values[1], scale[1] * values[2], scale[2] * values[3]);
    if (has_total) check_total(omega, total_scale * values[4], file, number, header);
    recording.t.push_back(values[0]);
    recording.omega.push_back(omega);
  }
  if (static_cast<int>(recording.t.size()) < kMinSamples)
    throw InputError(file, 0, "",
                     "a gyroscope recording of " + std::to_string(recording.t.size()) +
                         " samples; at least " + std::to_string(kMinSamples) + " are needed");
  if (const std::string unit = time_unit_cause(recording.t, time_scale); !unit.empty())
    throw InputError(file, header_line, header[0], unit);
  return recording;
}

}  // namespace bookspin::fit
