#include "fit/recording.hpp"

#include <unzip.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <optional>
#include <regex>
#include <utility>

#include "common/errors.hpp"
#include "common/file_name.hpp"
#include "common/number_text.hpp"
#include "common/text_file.hpp"
#include "common/text_lines.hpp"
#include "fit/median.hpp"

namespace bookspin::fit {
namespace {

constexpr int kMinSamples = 10;

/// The rows of `text` split at `separator` as RFC 4180 reads them (next_csv_record: a quoted
/// cell may hold the separator, doubled quotes and line ends, as R's write.csv and spreadsheets
/// write them), each with its 1-based line number; blank lines and comment lines (starting with
/// '#') left out. Throws InputError for a quoted cell not closed by the end of the file.
std::vector<std::pair<int, std::vector<std::string>>> csv_rows(std::string_view text,
                                                               char separator,
                                                               const std::string& file) {
  std::vector<std::pair<int, std::vector<std::string>>> rows;
  int number = 1;
  std::size_t at = 0;
  while (at < text.size()) {
    const TextLine line = next_line(text, at);
    const std::size_t first = line.line.find_first_not_of(" \t");
    if (first == std::string_view::npos || line.line[first] == '#') {
      ++number;
      at = line.next;
      continue;
    }
    CsvRecord record = next_csv_record(text, at, separator);
    if (record.unclosed)
      throw InputError(file, number, "",
                       "a quoted cell opens on this row and is not closed by the end of the file");
    rows.emplace_back(number, std::move(record.cells));
    number += record.lines;
    at = record.next;
  }
  return rows;
}

std::string lower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

/// The lines of `text` (without their ends), with their 1-based numbers; blank lines and
/// comment lines (starting with '#', as a whitespace-separated export's notes do) left out.
std::vector<std::pair<int, std::string_view>> lines_of(std::string_view text) {
  std::vector<std::pair<int, std::string_view>> lines;
  int number = 0;
  std::size_t begin = 0;
  while (begin < text.size()) {
    const TextLine next = next_line(text, begin);  // "\r\n", "\n" or a lone "\r"
    ++number;
    const std::size_t first = next.line.find_first_not_of(" \t");
    if (first != std::string_view::npos && next.line[first] != '#')
      lines.emplace_back(number, next.line);
    begin = next.next;
  }
  return lines;
}

/// A number cell: '.' or (decimal_comma) ',' as the decimal mark, scientific notation allowed;
/// nullopt for text. NaN and infinity are returned as such (the caller names them).
std::string number_spelling(std::string_view given, bool decimal_comma) {
  std::string cell(trimmed(given));  // a quoted cell keeps its spaces: " 2 " is 2
  if (decimal_comma) std::replace(cell.begin(), cell.end(), ',', '.');
  if (!cell.empty() && cell.front() == '+') cell.erase(0, 1);
  return cell;
}

std::optional<double> parse_number(std::string_view given, bool decimal_comma) {
  return read_number(number_spelling(given, decimal_comma));
}

/// Why a cell parse_number refuses is no number: past the largest double (1e400), or not one.
std::string not_a_number(const std::string& cell, bool decimal_comma) {
  if (beyond_doubles(number_spelling(cell, decimal_comma)))
    return quoted_cell(cell) + " is " + kBeyondDoubles;
  return "not a number: " + quoted_cell(cell);
}

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

struct ZipCloser {
  void operator()(void* zip) const { unzClose(zip); }
};

/// The most bytes a zip entry may inflate to (a recording of hours at 500 Hz is under 100 MB):
/// an entry that says it is larger, or inflates beyond it, is refused before it fills memory.
constexpr std::uint64_t kMaxZipEntryBytes = std::uint64_t{256} << 20;

/// The bytes of the one entry of the zip `path` whose name ends in `suffix` (after a folder
/// boundary); nullopt when none. Throws InputError when the file is empty, not a readable zip,
/// an empty zip, holds two such entries (naming them: which one is meant?), or the entry
/// inflates beyond kMaxZipEntryBytes.
std::optional<std::string> zip_entry(const std::filesystem::path& path, std::string_view suffix) {
  std::error_code error;
  if (std::filesystem::file_size(path, error) == 0 && !error)
    throw InputError(path.string() + ": an empty file, not a zip file");
  const std::unique_ptr<void, ZipCloser> zip(unzOpen64(path.string().c_str()));
  if (!zip) {
    // A zip of no file is its end record alone ("PK\5\6"), which minizip may not open.
    const std::optional<std::string> head =
        std::filesystem::file_size(path, error) == 22 ? try_read_text_file(path) : std::nullopt;
    if (head && head->compare(0, 4, "PK\x05\x06") == 0)
      throw InputError(path.string() + ": an empty zip (no file in it)");
    throw InputError(path.string() + ": not a zip file");
  }
  unz_global_info64 global{};
  if (unzGetGlobalInfo64(zip.get(), &global) != UNZ_OK)
    throw InputError(path.string() + ": a damaged zip file");
  if (global.number_entry == 0) throw InputError(path.string() + ": an empty zip (no file in it)");
  std::vector<std::string> found;
  unz64_file_pos found_at{};
  std::uint64_t found_size = 0;
  for (int status = unzGoToFirstFile(zip.get()); status == UNZ_OK;
       status = unzGoToNextFile(zip.get())) {
    unz_file_info64 info{};
    char name[1024];
    if (unzGetCurrentFileInfo64(zip.get(), &info, name, sizeof name, nullptr, 0, nullptr, 0) !=
        UNZ_OK)
      throw InputError(path.string() + ": a damaged zip file");
    const std::string entry = name;
    if (entry.size() < suffix.size() ||
        entry.compare(entry.size() - suffix.size(), suffix.size(), suffix) != 0)
      continue;
    // "meta/time.csv" must not match "othermeta/time.csv": a folder boundary before it.
    if (entry.size() > suffix.size() && entry[entry.size() - suffix.size() - 1] != '/') continue;
    if (found.empty()) {
      unzGetFilePos64(zip.get(), &found_at);
      found_size = info.uncompressed_size;
    }
    found.push_back(entry);
  }
  if (found.empty()) return std::nullopt;
  if (found.size() > 1) {
    std::string names;
    for (const std::string& entry : found) names += (names.empty() ? "\"" : ", \"") + entry + "\"";
    throw InputError(path.string() + ": holds " + std::to_string(found.size()) + " exports (" +
                     names + "): which one? Unzip it and give that export's folder");
  }
  const std::string& entry = found.front();
  const std::string too_large = path.string() + ": " + entry + ": inflates to more than " +
                                std::to_string(kMaxZipEntryBytes >> 20) +
                                " MiB, more than a recording (a damaged zip, or not phyphox's)";
  if (found_size > kMaxZipEntryBytes) throw InputError(too_large);
  if (unzGoToFilePos64(zip.get(), &found_at) != UNZ_OK || unzOpenCurrentFile(zip.get()) != UNZ_OK)
    throw InputError(path.string() + ": " + entry + ": cannot open the zip entry");
  std::string bytes;
  char buffer[65536];
  int got = 0;
  // The declared size bounds the bytes read: minizip inflates an entry no further than its
  // header's uncompressed size, so an entry whose header understates it reads short and fails
  // its CRC at the close below (ZipLimits.AnUnderstatedSizeReadsShortAndIsADamagedEntry).
  while ((got = unzReadCurrentFile(zip.get(), buffer, sizeof buffer)) > 0)
    bytes.append(buffer, static_cast<std::size_t>(got));
  const int closed = unzCloseCurrentFile(zip.get());
  if (got < 0 || closed != UNZ_OK)
    throw InputError(path.string() + ": " + entry + ": a damaged zip entry");
  return bytes;
}

/// The rows after the header of a phyphox `meta/` table `text` (time.csv, device.csv): each
/// one's 1-based line number and cells; `separator` set to the one its header uses. Throws
/// InputError for a NUL byte.
std::vector<std::pair<int, std::vector<std::string>>> meta_rows(std::string_view text,
                                                                const std::string& file,
                                                                char& separator) {
  text = without_bom(text);
  if (const auto nul = nul_byte_problem(text)) throw InputError(file, 0, "", *nul);
  const auto lines = lines_of(text);
  if (lines.empty()) return {};
  const std::string_view head = lines.front().second;
  separator = head.find('\t') != std::string_view::npos  ? '\t'
              : head.find(';') != std::string_view::npos ? ';'
                                                         : ',';
  std::vector<std::pair<int, std::vector<std::string>>> rows = csv_rows(text, separator, file);
  rows.erase(rows.begin());  // the header
  return rows;
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

std::string time_unit_cause(const std::vector<double>& t, double stated) {
  if (t.size() < 2) return {};
  std::vector<double> steps;
  steps.reserve(t.size() - 1);
  for (std::size_t i = 1; i < t.size(); ++i) steps.push_back(t[i] - t[i - 1]);
  const double step = median_of(std::move(steps));
  if (!(step > kMaxSampleStep)) return {};
  // The unit that puts the median step as written within a gyroscope's 0.1–100 ms.
  const std::array<std::pair<const char*, double>, 3> units{
      {{"ms", 1e-3}, {"µs", 1e-6}, {"ns", 1e-9}}};
  const double written = step / stated;
  const char* likely = nullptr;
  for (const auto& [unit, seconds] : units)
    if (written * seconds >= 1e-4 && written * seconds <= 0.1) {
      likely = unit;
      break;
    }
  std::string read_as;  // what the header stated, where it named a unit
  for (const auto& [unit, seconds] : units)
    if (stated == seconds) read_as = std::string(", read in ") + unit + " as the header names them";
  char text[400];
  std::snprintf(text, sizeof text,
                "the samples lie %.4g s apart (the median step%s), where a phone's gyroscope "
                "samples every 1–40 ms: are the times %s%s? Give them in seconds, or name %s "
                "unit in the header (\"t (%s)\")",
                step, read_as.c_str(), likely ? "in " : "in another unit", likely ? likely : "",
                read_as.empty() ? "the" : "their", likely ? likely : "ms");
  return text;
}

GyroRecording samples_recording(const std::string& name, std::vector<double> t,
                                std::vector<Eigen::Vector3d> omega) {
  const std::string where = name + ": ";
  if (t.size() != omega.size())
    throw InputError(where + std::to_string(t.size()) + " times and " +
                     std::to_string(omega.size()) + " samples of omega");
  for (std::size_t i = 0; i < t.size(); ++i) {
    const std::string index = std::string(1, '[').append(std::to_string(i)).append(1, ']');
    // Infinity from the caller's own reading of a number past the largest double (Python's
    // float("1e400")): said as the file door says it.
    const auto not_finite = [&](const char* what, bool infinite) {
      return InputError(where + what + index + ": " +
                        (infinite ? std::string(kBeyondDoubles) + ": " : std::string()) +
                        "not a finite number");
    };
    if (!std::isfinite(t[i])) throw not_finite("t", std::isinf(t[i]));
    if (!omega[i].allFinite()) throw not_finite("omega", omega[i].array().isInf().any());
    if (i > 0 && !(t[i] > t[i - 1]))
      throw InputError(where + "t" + index + ": time does not increase");
  }
  if (static_cast<int>(t.size()) < kMinSamples)
    throw InputError(where + "a gyroscope recording of " + std::to_string(t.size()) +
                     " samples; at least " + std::to_string(kMinSamples) + " are needed");
  if (const std::string unit = time_unit_cause(t); !unit.empty())
    throw InputError(where + "t: " + unit);
  GyroRecording recording;
  recording.name = file_name_of(name);
  recording.source = name;
  recording.t = std::move(t);
  recording.omega = std::move(omega);
  return recording;
}

std::vector<double> parse_time_csv(std::string_view text, const std::string& file) {
  std::vector<double> pauses;
  char separator = ',';
  for (const auto& [number, cells] : meta_rows(text, file, separator)) {
    if (cells.size() < 2) throw InputError(file, number, "", "expected an event and its time");
    if (cells[0] != "PAUSE") continue;
    const std::optional<double> time = parse_number(cells[1], separator == ';');
    if (!time || !std::isfinite(*time))
      throw InputError(file, number, "experiment time", "not a number: " + quoted_cell(cells[1]));
    pauses.push_back(*time);
  }
  std::sort(pauses.begin(), pauses.end());
  return pauses;
}

std::optional<double> parse_device_csv(std::string_view text, const std::string& file) {
  char separator = ',';
  for (const auto& [number, cells] : meta_rows(text, file, separator)) {
    if (cells.size() < 2 || lower(cells[0]) != "gyroscope range") continue;
    const std::string& cell = cells[1];
    if (cell.empty() || cell == "null") return std::nullopt;
    // Java's Float.toString: a decimal point whatever the export's separator.
    std::optional<double> range = parse_number(cell, false);
    if (!range) range = parse_number(cell, true);
    if (!range || !std::isfinite(*range) || !(*range > 0.0))
      throw InputError(file, number, cells[0],
                       "not a positive number of rad/s: " + quoted_cell(cell));
    return range;
  }
  return std::nullopt;
}

namespace {

/// Whether `file_name` is phyphox's name for one sensor's CSV export: the sensor, then the
/// date and time it was recorded ("Gyroscope rotation rate 2022-05-03 12-10-56.csv").
bool single_sensor_export(const std::string& file_name) {
  static const std::regex pattern(R"(.+ \d{4}-\d{2}-\d{2} \d{2}-\d{2}-\d{2}\.[cC][sS][vV])");
  return std::regex_match(file_name, pattern);
}

/// Whether `path`'s folder holds no other CSV.
bool only_csv_of_its_folder(const std::filesystem::path& path) {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::path folder = fs::absolute(path).parent_path();
  for (const fs::directory_entry& entry : fs::directory_iterator(folder, error))
    if (entry.is_regular_file(error) && lower(entry.path().extension().string()) == ".csv" &&
        entry.path().filename() != path.filename())
      return false;
  return !error;
}

}  // namespace

GyroRecording read_recording(const std::filesystem::path& path) {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (!fs::exists(status))
    throw InputError(path.string() + ": " +
                     (error.value() == ELOOP ? kLinkLoop : "no such file or folder"));
  if (fs::is_directory(status)) {
    const fs::path raw = path / "Raw Data.csv";
    if (fs::exists(raw)) return read_recording(raw);
    // phyphox's single-CSV exports are kept one to a folder ("Gyroscope rotation rate
    // 2022-05-03 12-07-27.csv"): a folder holding exactly one CSV is that CSV, named after the
    // folder as an export is.
    std::vector<fs::path> csvs;
    for (const fs::directory_entry& entry : fs::directory_iterator(path, error))
      if (entry.is_regular_file(error) && lower(entry.path().extension().string()) == ".csv")
        csvs.push_back(entry.path());
    std::sort(csvs.begin(), csvs.end());
    if (csvs.empty())
      throw InputError(path.string() +
                       ": not a gyroscope recording: the folder holds no \"Raw Data.csv\" and no "
                       "other CSV");
    if (csvs.size() > 1) {
      std::string names;
      for (const fs::path& csv : csvs)
        names += (names.empty() ? "\"" : ", \"") + csv.filename().string() + "\"";
      throw InputError(path.string() + ": holds " + std::to_string(csvs.size()) +
                       " CSVs and no \"Raw Data.csv\" (" + names + "): which one? Give that file");
    }
    GyroRecording recording = read_recording(csvs.front());
    fs::path folder = fs::absolute(path).lexically_normal();
    if (folder.filename().empty()) folder = folder.parent_path();  // "anna/" as "anna"
    recording.name = file_name_of(folder.filename().string());
    return recording;
  }
  const std::string name = path.stem().string();
  if (lower(path.extension().string()) == ".zip") {
    const std::optional<std::string> raw = zip_entry(path, "Raw Data.csv");
    if (!raw)
      throw InputError(path.string() +
                       ": not a gyroscope recording: the zip holds no \"Raw Data.csv\"");
    GyroRecording recording = parse_gyro_csv(*raw, path.string() + ":Raw Data.csv", name);
    if (const std::optional<std::string> time = zip_entry(path, "meta/time.csv"))
      recording.pauses = parse_time_csv(*time, path.string() + ":meta/time.csv");
    if (const std::optional<std::string> device = zip_entry(path, "meta/device.csv"))
      recording.gyroscope_range = parse_device_csv(*device, path.string() + ":meta/device.csv");
    recording.file = fs::weakly_canonical(path, error);
    return recording;
  }
  const std::string text = read_text_file(path, "the recording");
  // A phyphox export is named after its folder; so is a single sensor's export given with its
  // folder ("12-10-56/Gyroscope rotation rate … .csv", a dropped folder's file) that holds no
  // other CSV, as that folder given is named, so that the file, its folder or a dropped folder
  // name one recording alike and a pooled set sorts alike; another CSV, or one given by its
  // bare name, after itself.
  const bool in_export = path.filename() == "Raw Data.csv";
  const fs::path folder = fs::absolute(path).parent_path();
  const bool named_by_folder =
      in_export || (single_sensor_export(path.filename().string()) && path.has_parent_path() &&
                    only_csv_of_its_folder(path) && !folder.filename().empty());
  GyroRecording recording =
      parse_gyro_csv(text, path.string(), named_by_folder ? folder.filename().string() : name);
  // Named in messages as the recording was given ("anna/meta/time.csv").
  const fs::path time_csv = folder / "meta" / "time.csv";
  const fs::path meta_named = path.parent_path() / "meta";
  if (in_export && fs::exists(time_csv))
    recording.pauses =
        parse_time_csv(read_text_file(time_csv, "the pauses"), (meta_named / "time.csv").string());
  const fs::path device_csv = folder / "meta" / "device.csv";
  if (in_export && fs::exists(device_csv))
    recording.gyroscope_range = parse_device_csv(read_text_file(device_csv, "the device"),
                                                 (meta_named / "device.csv").string());
  recording.file = fs::weakly_canonical(path, error);
  return recording;
}

}  // namespace bookspin::fit
