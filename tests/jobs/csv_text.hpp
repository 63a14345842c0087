#pragma once
// A CSV file of the jobs read back as text cells, for the tests that compare its columns.
#include <filesystem>
#include <fstream>
#include <istream>
#include <string>
#include <vector>

namespace bookspin::jobs {

/// The cells of a CSV line (a trailing comma ends in an empty cell), read here without the
/// code under test: RFC 4180's quoted cells ("a, b" and doubled quotes "") on one line.
inline std::vector<std::string> cells_of(const std::string& line) {
  std::vector<std::string> cells(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
      cells.back() += '"';
      ++i;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      cells.emplace_back();
    } else {
      cells.back() += c;
    }
  }
  return cells;
}

/// A CSV read back: its header's column names and its rows' cells.
struct Csv {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
};

inline Csv read_csv(std::istream& in) {
  Csv csv;
  std::string line;
  if (std::getline(in, line)) csv.header = cells_of(line);
  while (std::getline(in, line)) csv.rows.push_back(cells_of(line));
  return csv;
}

inline Csv read_csv(const std::filesystem::path& path) {
  std::ifstream in(path);
  return read_csv(in);
}

}  // namespace bookspin::jobs
