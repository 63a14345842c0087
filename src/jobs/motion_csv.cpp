#include "jobs/motion_csv.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "common/number_text.hpp"
#include "common/text_lines.hpp"

namespace bookspin::jobs {

namespace {

/// rad per time unit: a larger ω component is refused (its E and |L| would overflow).
constexpr double kMaxOmega = 1e100;

/// `cell` as a finite double, or false: a decimal number (an optional sign, digits with an
/// optional point, an optional exponent) as read_number() reads one (common/number_text.hpp:
/// correctly rounded, compiled into the explorer page too). Refused: anything else (hex, "inf",
/// "nan", spaces within), a value beyond the doubles and one so small that it reads as 0.
bool finite_number(std::string_view cell, double& out) {
  // One sign at most: a '+' is dropped, and no second sign may follow it.
  if (!cell.empty() && cell[0] == '+') {
    cell.remove_prefix(1);
    if (!cell.empty() && (cell[0] == '+' || cell[0] == '-')) return false;
  }
  const std::optional<double> value = read_number(cell);
  if (!value || !std::isfinite(*value)) return false;
  out = *value;
  return true;
}

/// The line ends in `cell` ("\r\n", "\n" or a lone "\r", each one, as next_line counts them).
int line_ends(std::string_view cell) {
  int ends = 0;
  for (std::size_t k = 0; k < cell.size(); ++k)
    ends += cell[k] == '\n' || (cell[k] == '\r' && (k + 1 == cell.size() || cell[k + 1] != '\n'));
  return ends;
}

/// A quoted cell over a line end is a quote left open (else the lines it holds are not read as
/// rows, and the next row read is blamed on its t) where it cannot be a cell of text: in the
/// header (a name), in a column the motion is read from (`read`: a number), past the header's
/// columns, or holding a whole row after its line end (as many commas as a row of the header
/// has), or followed by more text after its closing quote (a column quoted on every row: the
/// next row's opening quote closed it, `"note 5⏎…,"note 6",…`). A note over two lines, in a
/// column of its own, is read. Throws InputError naming the row, the column and the line where
/// the quote closes.
void refuse_quote_left_open(const CsvRecord& record, const std::vector<std::string_view>& header,
                            const std::array<std::size_t, 8>& read, const std::string& file,
                            int line_number) {
  const std::vector<std::string>& cells = record.cells;
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const std::string& cell = cells[c];
    const int ends = line_ends(cell);
    if (ends == 0) continue;
    const std::size_t first_end = cell.find_first_of("\r\n");
    const bool text =
        !header.empty() && c < header.size() &&
        std::find(record.text_after_quote.begin(), record.text_after_quote.end(), c) ==
            record.text_after_quote.end() &&
        std::find(read.begin(), read.end(), c) == read.end() &&
        static_cast<std::size_t>(std::count(cell.begin() + first_end, cell.end(), ',')) + 1 <
            header.size();
    if (!text)
      throw InputError(file, line_number, c < header.size() ? std::string(header[c]) : "",
                       "a quote opens a cell on this row (" +
                           quoted_cell(cell.substr(0, first_end)) +
                           " and the line's end) and closes it on line " +
                           std::to_string(line_number + ends) + ": a quote left open?");
  }
}

/// Why a cell finite_number() refused is no finite number: a decimal number beyond the doubles
/// is named so (it overflows, or underflows to 0: common/number_text.hpp's words, as every door
/// says them), anything else "is not a finite number".
std::string not_a_number_reason(std::string_view cell, const std::string& quoted) {
  std::string_view digits = cell;
  if (!digits.empty() && digits[0] == '+') digits.remove_prefix(1);  // finite_number's '+'
  const std::string range = out_of_range_reason(digits);
  if (range == kBelowDoubles) return quoted + " is " + range + " (write 0 if that is meant)";
  if (!range.empty()) return quoted + " is " + range;
  return quoted + " is not a finite number";
}

/// A column the motion is read from (t, q, ω in either frame, either spelling) that the header
/// names twice, or "".
std::string repeated_column(const std::vector<std::string_view>& header) {
  static constexpr std::string_view kRead[] = {
      "t",  "qw", "qx", "qy",      "qz",      "q_w",     "q_x",      "q_y",      "q_z",
      "wx", "wy", "wz", "omega_x", "omega_y", "omega_z", "wx_world", "wy_world", "wz_world"};
  for (const std::string_view name : kRead)
    if (std::count(header.begin(), header.end(), name) > 1) return std::string(name);
  return "";
}

/// A quantity the header gives under both of its spellings (bookspin's diagnostics' q_w beside
/// qw, omega_x beside wx), as "qw and q_w", or "": one quantity, one column.
std::string two_spellings(const std::vector<std::string_view>& header) {
  static constexpr std::string_view kSpellings[][2] = {
      {"qw", "q_w"},     {"qx", "q_x"},     {"qy", "q_y"},    {"qz", "q_z"},
      {"wx", "omega_x"}, {"wy", "omega_y"}, {"wz", "omega_z"}};
  for (const auto& [a, b] : kSpellings)
    if (std::count(header.begin(), header.end(), a) && std::count(header.begin(), header.end(), b))
      return std::string(a) + " and " + std::string(b);
  return "";
}

/// The index of the first of `names` in `header`, or nullopt.
std::optional<std::size_t> column(const std::vector<std::string_view>& header,
                                  std::initializer_list<std::string_view> names) {
  for (std::string_view name : names)
    for (std::size_t i = 0; i < header.size(); ++i)
      if (header[i] == name) return i;
  return std::nullopt;
}

/// Checks one row's numbers `v` (t, qw, qx, qy, qz, ω x, y, z in motion.omega_frame) against
/// the rows before it and adds it to `motion`: q normalized, ω turned into the body frame.
/// `error(k, reason)` makes the InputError naming the row and its value k, `text(k)` spells
/// value k as it was given.
template <typename Error, typename Text>
void add_row(MotionFile& motion, const std::array<double, 8>& v, double dt, long long steps,
             const Error& error, const Text& text) {
  const double t = v[0];
  const double n = std::round(t / dt);
  if (!(n >= 0.0 && n <= static_cast<double>(steps))) {
    throw error(0, "t = " + text(0) + " is outside the scenario's 0 … " +
                       finite_text(static_cast<double>(steps) * dt, "t_end"));
  }
  if (std::abs(t - n * dt) > 1e-6 * dt) {
    throw error(
        0, "t = " + text(0) + " is not a whole number of steps of dt = " + finite_text(dt, "dt"));
  }
  const auto step = static_cast<long long>(n);
  const long long index = static_cast<long long>(motion.rows.size());
  if (index == 0 && step != 0) throw error(0, "the first row must be t = 0");
  if (index == 1) {
    if (step <= 0) throw error(0, "t does not increase");
    motion.stride = step;
  }
  // Rows every k steps reach the scenario's end where k divides `steps`; where it does not, the
  // last row may be the last multiple of k, or the scenario's last step after it (a shorter last
  // interval): both are the whole run (docs/flipcheck.md, "judge: the motion file").
  const bool last_step_after_the_strides = index > 1 && step == steps &&
                                           step > (index - 1) * motion.stride &&
                                           step < index * motion.stride;
  if (index > 1 && step != index * motion.stride && !last_step_after_the_strides) {
    throw error(0, "t = " + text(0) + " is not step " + std::to_string(index * motion.stride) +
                       " (rows every " + std::to_string(motion.stride) + " steps from t = 0)");
  }
  // Any norm: a squared norm that would over- or underflow (1e300, 1e-300) is divided by the
  // largest component first; a usual one is normalised as it is (the same bits as ever).
  const double q_largest =
      std::max({std::abs(v[1]), std::abs(v[2]), std::abs(v[3]), std::abs(v[4])});
  if (q_largest == 0.0) throw error(1, "q is zero (qw = qx = qy = qz = 0): no orientation");
  Eigen::Quaterniond q(v[1], v[2], v[3], v[4]);
  if (!(q_largest >= 1e-100 && q_largest <= 1e100)) q.coeffs() /= q_largest;
  q.normalize();
  for (std::size_t k = 5; k < 8; ++k)
    if (std::abs(v[k]) > kMaxOmega)
      throw error(
          k, "\"" + text(k) + "\" is beyond ±1e100 rad per time unit (its energy would overflow)");
  Eigen::Vector3d omega(v[5], v[6], v[7]);
  if (motion.omega_frame == OmegaFrame::world) omega = q.toRotationMatrix().transpose() * omega;
  motion.rows.push_back({step, q, omega});
}

}  // namespace

MotionFile parse_motion_csv(std::string_view text, const std::string& file, double dt,
                            long long steps) {
  text = without_bom(text);  // a spreadsheet's byte-order mark before the header
  if (const auto nul = nul_byte_problem(text)) throw InputError(file, 0, "", *nul);
  MotionFile motion;
  std::vector<std::string> header_cells;  // the header's names, trimmed
  std::vector<std::string_view> header;
  std::array<std::size_t, 8> at{};  // t, qw, qx, qy, qz, ω x, y, z
  std::array<std::string_view, 8> names{};
  int line_number = 0;  // the line the row being read starts on (1-based)
  int lines_read = 0;
  std::size_t start = 0;
  while (start < text.size()) {
    const TextLine next = next_line(text, start);  // "\r\n", "\n" or a lone "\r"
    const std::string_view line = trimmed(next.line);
    line_number = ++lines_read;
    if (line.empty() || line.front() == '#') {
      start = next.next;
      continue;
    }
    // A row as RFC 4180 reads it (R's write.csv, spreadsheets): a quoted cell may hold commas,
    // doubled quotes and, in a column of text, line ends.
    CsvRecord record = next_csv_record(text, start, ',');
    if (record.unclosed) {
      // The cell left open is the record's last: named by its column where the header has one.
      const std::size_t c = record.cells.size() - 1;
      throw InputError(file, line_number, c < header.size() ? std::string(header[c]) : "",
                       "a quoted cell opens on this row and is not closed by the end of the file");
    }
    refuse_quote_left_open(record, header, at, file, line_number);
    start = record.next;
    lines_read += record.lines - 1;
    if (header.empty()) {
      for (const std::string& name : record.cells) header_cells.emplace_back(trimmed(name));
      header.assign(header_cells.begin(), header_cells.end());
      if (const std::string twice = repeated_column(header); !twice.empty())
        throw InputError(file, line_number, twice,
                         "the column " + twice + " appears twice in the header: which is meant?");
      if (const std::string both = two_spellings(header); !both.empty())
        throw InputError(file, line_number, both.substr(both.rfind(' ') + 1),
                         "the header has both " + both +
                             ": two spellings of one quantity, which is meant? (keep one)");
      const auto need = [&](std::initializer_list<std::string_view> options,
                            std::string_view what) {
        const auto i = column(header, options);
        if (!i) {
          throw InputError(file, line_number, std::string(*options.begin()),
                           "no column " + std::string(what) + " in the header");
        }
        return *i;
      };
      at[0] = need({"t"}, "t (time units)");
      const char* q_names[4][2] = {{"qw", "q_w"}, {"qx", "q_x"}, {"qy", "q_y"}, {"qz", "q_z"}};
      for (int k = 0; k < 4; ++k)
        at[1 + k] = need({q_names[k][0], q_names[k][1]},
                         std::string(q_names[k][0]) + " (or " + q_names[k][1] + ")");
      const auto wx = column(header, {"wx", "omega_x"}), wy = column(header, {"wy", "omega_y"}),
                 wz = column(header, {"wz", "omega_z"});
      if (wx && wy && wz) {
        at[5] = *wx, at[6] = *wy, at[7] = *wz;
      } else {
        motion.omega_frame = OmegaFrame::world;
        at[5] = need({"wx_world"}, "wx,wy,wz (body frame) or wx_world,wy_world,wz_world");
        at[6] = need({"wy_world"}, "wy_world");
        at[7] = need({"wz_world"}, "wz_world");
      }
      for (std::size_t k = 0; k < at.size(); ++k) names[k] = header[at[k]];
      continue;
    }
    const std::vector<std::string>& cells = record.cells;
    if (cells.size() != header.size()) {
      throw InputError(file, line_number, "",
                       std::to_string(cells.size()) + " cells where the header has " +
                           std::to_string(header.size()));
    }
    std::array<double, 8> v{};
    for (std::size_t k = 0; k < at.size(); ++k) {
      const std::string_view cell = trimmed(cells[at[k]]);  // a quoted " 2.5 " is 2.5
      const std::string column_name(names[k]);
      if (cell.empty()) throw InputError(file, line_number, column_name, "empty cell");
      if (!finite_number(cell, v[k])) {
        throw InputError(file, line_number, column_name,
                         not_a_number_reason(cell, quoted_cell(cell)));
      }
    }
    add_row(
        motion, v, dt, steps,
        [&](std::size_t k, const std::string& reason) {
          return InputError(file, line_number, std::string(names[k]), reason);
        },
        [&](std::size_t k) { return cut_cell(cells[at[k]]); });
  }
  if (header.empty()) throw InputError(file, 0, "", "no header row (t,qw,qx,qy,qz,wx,wy,wz)");
  if (motion.rows.empty()) throw InputError(file, line_number, "", "no rows after the header");
  return motion;
}

MotionFile motion_from_rows(const std::vector<std::array<double, 8>>& rows, OmegaFrame frame,
                            const std::string& what, double dt, long long steps) {
  MotionFile motion;
  motion.omega_frame = frame;
  const std::string omega_name = frame == OmegaFrame::world ? "omega_world" : "omega_body";
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const std::array<double, 8>& v = rows[i];
    const auto key = [&](std::size_t k) {
      const std::string array = k == 0 ? "t" : k < 5 ? "q" : omega_name;
      return array + "[" + std::to_string(i) + "]";
    };
    const auto error = [&](std::size_t k, const std::string& reason) {
      return InputError(what + ": " + key(k) + ": " + reason);
    };
    const auto text = [&](std::size_t k) {
      return std::isfinite(v[k]) ? finite_text(v[k], "a motion's value") : std::string("nan");
    };
    for (std::size_t k = 0; k < v.size(); ++k) {
      if (!std::isfinite(v[k])) {
        // A value, not text: named as an infinity typed is (docs/phone-lab.md, "Numbers").
        throw error(k, std::string(std::isnan(v[k]) ? "nan"
                                   : v[k] > 0       ? "inf"
                                                    : "-inf") +
                           " is not a finite number");
      }
    }
    add_row(motion, v, dt, steps, error, text);
  }
  if (motion.rows.empty()) throw InputError(what + ": no rows (t is empty)");
  return motion;
}

}  // namespace bookspin::jobs
