#include "jobs/sweep_shard.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "common/csv_writer.hpp"
#include "common/errors.hpp"
#include "common/sha256.hpp"
#include "output/manifest.hpp"
#include "scene/canonical.hpp"

namespace bookspin::jobs {

namespace {

constexpr const char* kShardMagic = "# bookspin sweep shard ";

/// `text` as one word of the shard line: '%', spaces and control bytes as %XX (RFC 3986's
/// percent-encoding, upper-case hex); every other byte, UTF-8 too, as it is.
std::string percent_encoded(const std::string& text) {
  static constexpr char kHex[] = "0123456789ABCDEF";
  std::string out;
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte <= 0x20 || byte == 0x7f || c == '%') {
      out += '%';
      out += kHex[byte >> 4];
      out += kHex[byte & 15];
    } else {
      out += c;
    }
  }
  return out;
}

/// percent_encoded() undone; a '%' not followed by two hex digits is kept as it is.
std::string percent_decoded(const std::string& word) {
  const auto hex = [](char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    return -1;
  };
  std::string out;
  for (std::size_t i = 0; i < word.size(); ++i) {
    if (word[i] == '%' && i + 2 < word.size() && hex(word[i + 1]) >= 0 && hex(word[i + 2]) >= 0) {
      out += static_cast<char>(16 * hex(word[i + 1]) + hex(word[i + 2]));
      i += 2;
    } else {
      out += word[i];
    }
  }
  return out;
}

/// Everything after "shard K of N: " in a shard's first line: the same in every shard of one
/// sweep. scene_sha256 is the SHA-256 of the resolved scene in canonical form (after --set
/// and defaults, before the grid's values: scene::canonical_json, as in the manifests), build
/// the SHA-256 of the bookspin that ran it (program_build_id).
std::string shard_meta(const SweepTable& table, std::size_t points,
                       const std::string& scene_sha256) {
  std::string meta = "scene=" + table.scene_name + " scene_sha256=" + scene_sha256 +
                     " build=" + output::program_build_id() + " points=" + std::to_string(points);
  for (const auto& r : table.ranges) meta += " vary=" + r.key + "=" + r.spec();
  meta += " measure=";
  for (std::size_t i = 0; i < table.measures.size(); ++i) {
    if (i > 0) meta += ',';
    meta += table.measures[i]->name;
  }
  if (!table.scene_title.empty()) meta += " title=" + percent_encoded(table.scene_title);
  return meta;
}

/// A line of a shard without its line ending: LF or CRLF (a file that went through Windows).
bool read_line(std::istream& in, std::string& line) {
  if (!std::getline(in, line)) return false;
  if (!line.empty() && line.back() == '\r') line.pop_back();
  return true;
}

/// The fields of a shard's first line after "K of N: ": scene, scene_sha256, build, points,
/// vary (one per range, in order), measure.
struct ShardLine {
  std::string scene, scene_sha256, build, points, measure, title;
  std::vector<std::string> vary;
};

ShardLine parse_shard_line(const std::string& meta) {
  ShardLine line;
  std::istringstream words(meta);
  for (std::string word; words >> word;) {
    const auto value = [&](const char* key) { return word.substr(std::strlen(key)); };
    if (word.rfind("scene=", 0) == 0)
      line.scene = value("scene=");
    else if (word.rfind("scene_sha256=", 0) == 0)
      line.scene_sha256 = value("scene_sha256=");
    else if (word.rfind("build=", 0) == 0)
      line.build = value("build=");
    else if (word.rfind("points=", 0) == 0)
      line.points = value("points=");
    else if (word.rfind("vary=", 0) == 0)
      line.vary.push_back(value("vary="));
    else if (word.rfind("measure=", 0) == 0)
      line.measure = value("measure=");
    else if (word.rfind("title=", 0) == 0)
      line.title = percent_decoded(value("title="));
  }
  return line;
}

/// Why shard line `line` is not of the sweep of `first` (empty when it is): the first field
/// that differs.
std::string shard_line_difference(const ShardLine& line, const ShardLine& first) {
  if (line.scene != first.scene) return "scene '" + line.scene + "', not '" + first.scene + "'";
  if (line.scene_sha256 != first.scene_sha256)
    return "the resolved scene differs (scene file or --set; scene_sha256 " +
           line.scene_sha256.substr(0, 12) + "…, not " + first.scene_sha256.substr(0, 12) + "…)";
  if (line.build != first.build)
    return "made by another bookspin build (" + line.build.substr(0, 12) + "…, not " +
           first.build.substr(0, 12) + "…)";
  if (line.points != first.points || line.vary != first.vary) return "another grid (--vary)";
  if (line.measure != first.measure)
    return "other measures (" + line.measure + ", not " + first.measure + ")";
  return "";
}

/// A cell that reads wholly as a finite number.
bool is_number(const std::string& cell) {
  if (cell.empty() || std::isspace(static_cast<unsigned char>(cell.front()))) return false;
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(cell.c_str(), &end);
  return end == cell.c_str() + cell.size() && std::isfinite(value) && errno != ERANGE;
}

}  // namespace

std::string sweep_shard_text(const SweepTable& table, const scene::Scene& scene,
                             std::size_t grid_points, int k, int n) {
  std::ostringstream text;
  text << kShardMagic << k << " of " << n << ": "
       << shard_meta(table, grid_points, sha256_text(scene::canonical_json(scene, 0))) << '\n'
       << csv_row(after("grid_index", table.header)) << '\n';
  for (const auto& [index, cells] : table.rows)
    text << csv_row(after(std::to_string(index), cells)) << '\n';
  return text.str();
}

SweepTable read_sweep_shards(const std::vector<std::filesystem::path>& shards,
                             const ShardPath& missing) {
  if (shards.empty()) throw InputError("sweep --merge: give the shard CSV files");
  SweepTable table;
  ShardLine first_line;  // the first file's, which every other must repeat
  bool have_first = false;
  int shard_count = 0;
  std::size_t points = 0;
  std::map<int, std::filesystem::path> shard_files;
  std::map<std::size_t, std::vector<std::string>> rows;
  std::map<std::size_t, std::string> row_place;  // "FILE:LINE" of each grid point's row
  for (const auto& path : shards) {
    const std::string name = path.string();
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(name + ": cannot read the shard file");
    std::string first, header;
    if (!read_line(in, first) || first.rfind(kShardMagic, 0) != 0)
      throw InputError(name + ":1: not a sweep shard (no \"" + std::string(kShardMagic) +
                       "\" line)");
    int k = -1, n = 0, used = 0;
    const std::string rest = first.substr(std::string(kShardMagic).size());
    if (std::sscanf(rest.c_str(), "%d of %d: %n", &k, &n, &used) != 2 || used == 0 || n < 1 ||
        k < 0 || k >= n)
      throw InputError(name + ":1: expected \"" + kShardMagic + "K of N: …\"");
    const ShardLine line = parse_shard_line(rest.substr(static_cast<std::size_t>(used)));
    if (!have_first) {
      have_first = true;
      first_line = line;
      shard_count = n;
      if (line.scene_sha256.empty() || line.build.empty())
        throw InputError(name +
                         ":1: the shard line records no scene_sha256 or build (made by "
                         "an older bookspin: run the shards again)");
      std::vector<VaryRange> ranges;
      for (const auto& v : line.vary) ranges.push_back(parse_vary(v));
      points = std::strtoull(line.points.c_str(), nullptr, 10);
      table.scene_name = line.scene;
      table.scene_title = line.title;
      if (!line.measure.empty()) table.measures = parse_measures(line.measure);
      const SweepGrid grid(ranges);
      if (table.scene_name.empty() || grid.size() != points || table.measures.empty())
        throw InputError(name + ":1: the shard line does not describe a sweep");
      table.ranges = ranges;
      table.header = sweep_csv_header(table.ranges, table.measures);
    } else if (const std::string why = shard_line_difference(line, first_line); !why.empty()) {
      throw InputError(name + ":1: a shard of another sweep than " + shards.front().string() +
                       ": " + why);
    } else if (n != shard_count) {
      throw InputError(name + ":1: a shard of another sweep than " + shards.front().string() +
                       ": of " + std::to_string(n) + " shards, not " + std::to_string(shard_count));
    }
    if (!shard_files.emplace(k, path).second) {
      throw InputError(name + ": shard " + std::to_string(k) + " of " + std::to_string(n) +
                       " is also given as " + shard_files[k].string());
    }
    if (!read_line(in, header) || header != csv_row(after("grid_index", table.header)))
      throw InputError(name + ":2: header differs from the sweep's: expected " +
                       csv_row(after("grid_index", table.header)));
    // Cells 1 … ranges are the varied values (always numbers); the rest are measures and
    // their exact columns, empty where undefined.
    const std::size_t varied = table.ranges.size();
    int line_number = 2;
    for (std::string row; read_line(in, row);) {
      ++line_number;
      const std::string where = name + ":" + std::to_string(line_number);
      std::vector<std::string> cells;
      try {
        cells = csv_cells(row);
      } catch (const std::invalid_argument& e) {
        throw InputError(where + ": " + e.what());
      }
      if (cells.size() != table.header.size() + 1)
        throw InputError(where + ": expected " + std::to_string(table.header.size() + 1) +
                         " cells");
      char* end = nullptr;
      const unsigned long long index = std::strtoull(cells[0].c_str(), &end, 10);
      if (cells[0].empty() || !std::isdigit(static_cast<unsigned char>(cells[0].front())) ||
          *end != '\0' || index >= points ||
          index % static_cast<unsigned long long>(n) != static_cast<unsigned long long>(k))
        throw InputError(where + ": grid_index '" + cells[0] + "' is not a point of shard " +
                         std::to_string(k) + " of " + std::to_string(n));
      // The last cell, `refused`, is text: empty, or the reason of a point that did not run
      // and so has no measure.
      const std::size_t refused = cells.size() - 1;
      for (std::size_t c = 1; c < refused; ++c) {
        if (is_number(cells[c]) || (c > varied && cells[c].empty())) continue;
        throw InputError(where + ": " + table.header[c - 1] + " '" + cells[c] +
                         "' is not a number");
      }
      if (!cells[refused].empty()) {
        for (std::size_t c = varied + 1; c < refused; ++c)
          if (!cells[c].empty())
            throw InputError(where + ": " + table.header[c - 1] +
                             " has a value in a refused point's row");
      }
      cells.erase(cells.begin());
      if (!rows.emplace(index, std::move(cells)).second) {
        throw InputError(where + ": grid point " + std::to_string(index) +
                         " is duplicated (also at " + row_place[index] + ")");
      }
      row_place[index] = where;
    }
  }
  for (std::size_t i = 0; i < points; ++i) {
    if (rows.count(i)) continue;
    const int k = static_cast<int>(i % static_cast<std::size_t>(shard_count));
    const auto it = shard_files.find(k);
    const std::string file = it != shard_files.end()
                                 ? it->second.string()
                                 : missing(table.scene_name, k, shard_count).string();
    throw InputError(file + ": grid point " + std::to_string(i) + " of " + std::to_string(points) +
                     " is missing" + (it == shard_files.end() ? " (shard not given)" : ""));
  }
  for (auto& [index, cells] : rows) table.rows.emplace_back(index, std::move(cells));
  return table;
}

}  // namespace bookspin::jobs
