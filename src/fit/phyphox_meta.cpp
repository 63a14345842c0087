// phyphox's meta/ tables (docs/phone-lab.md, "The recording"): the pauses of time.csv and the
// gyroscope's range of device.csv.
#include <algorithm>
#include <cmath>

#include "common/errors.hpp"
#include "common/text_lines.hpp"
#include "fit/recording.hpp"
#include "fit/recording_text.hpp"

namespace bookspin::fit {
namespace {

using recording_text::csv_rows;
using recording_text::lines_of;
using recording_text::lower;
using recording_text::parse_number;

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

}  // namespace

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

}  // namespace bookspin::fit
