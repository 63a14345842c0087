#include "scene/measured_file.hpp"

#include <charconv>
#include <cmath>

#include "common/text_file.hpp"
#include "scene/limits.hpp"

namespace bookspin::scene {

std::string parse_measured_omega(std::string_view text, MeasuredOmega& out) {
  text = without_bom(text);  // a spreadsheet's byte-order mark before the header
  if (const auto nul = nul_byte_problem(text)) return *nul;
  const char* columns[] = {"t", "wx", "wy", "wz"};
  const double w_limit = limit("initial.angular_velocity").max;
  std::vector<double> t;
  std::vector<Eigen::Vector3d> omega;
  int line = 0;
  while (!text.empty()) {
    const TextLine next = next_line(text, 0);  // "\r\n", "\n" or a lone "\r"
    const std::string_view row = next.line;
    text = text.substr(next.next);
    ++line;
    const std::string where = "row " + std::to_string(line);
    if (line == 1) {
      if (trimmed(row) != "t,wx,wy,wz") return where + ": the header must be t,wx,wy,wz";
      continue;
    }
    if (trimmed(row).empty() && text.empty()) break;  // the last line's newline
    double cells[4];
    std::string_view rest = row;
    for (int c = 0; c < 4; ++c) {
      const std::size_t comma = rest.find(',');
      if ((comma == std::string_view::npos) != (c == 3))
        return where + ": expected 4 cells (t,wx,wy,wz)";
      const std::string_view cell = trimmed(rest.substr(0, comma));
      rest = comma == std::string_view::npos ? std::string_view() : rest.substr(comma + 1);
      const auto [ptr, ec] = std::from_chars(cell.data(), cell.data() + cell.size(), cells[c]);
      if (ec != std::errc() || ptr != cell.data() + cell.size() || !std::isfinite(cells[c]))
        return where + ": " + columns[c] + ": not a finite number: " + quoted_cell(cell);
      if (c > 0 && std::abs(cells[c]) > w_limit)
        return where + ": " + columns[c] + ": beyond ±1e6 rad per time unit";
    }
    if (cells[0] < 0.0) return where + ": t: negative (time since the scene's start)";
    if (!t.empty() && !(cells[0] > t.back())) return where + ": t: not after the row before";
    if (static_cast<int>(t.size()) == kMaxMeasuredSamples)
      return where + ": more than " + std::to_string(kMaxMeasuredSamples) + " samples";
    t.push_back(cells[0]);
    omega.emplace_back(cells[1], cells[2], cells[3]);
  }
  if (line == 0) return "row 1: the header must be t,wx,wy,wz";
  if (t.empty()) return "no samples (a header alone)";
  out.t = std::move(t);
  out.omega.resize(3, static_cast<Eigen::Index>(omega.size()));
  for (std::size_t i = 0; i < omega.size(); ++i)
    out.omega.col(static_cast<Eigen::Index>(i)) = omega[i];
  return "";
}

}  // namespace bookspin::scene
