#include "jobs/sweep.hpp"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>
#include <thread>

#include "charts/heat_map.hpp"
#include "charts/panel.hpp"
#include "common/errors.hpp"
#include "output/atomic_output.hpp"
#include "output/finite_number.hpp"
#include "output/manifest.hpp"
#include "output/output_dir.hpp"
#include "output/png_writer.hpp"
#include "output/sha256.hpp"
#include "scene/canonical.hpp"

namespace bookspin::jobs {

namespace {

constexpr const char* kShardMagic = "# bookspin sweep shard ";
constexpr int kPlotWidth = 1400;
constexpr int kPlotHeightPerMeasure = 330;
constexpr int kMapHeightPerRow = 560;  ///< two heat maps a row

/// A measure's cell: empty where the run does not reach it (no flip), else its value, checked
/// finite on the way out (output/finite_number.hpp).
std::string cell(const std::optional<double>& v, std::string_view column) {
  return v ? full_precision(output::finite(*v, "sweep CSV column " + std::string(column)))
           : std::string();
}

std::vector<std::string> row_cells(const std::vector<double>& point, const MeasureList& measures,
                                   const analysis::RunMeasures& m) {
  std::vector<std::string> cells;
  for (double v : point) cells.push_back(full_precision(output::finite(v, "sweep grid value")));
  for (const analysis::Measure* measure : measures)
    cells.push_back(cell(m.*(measure->value), measure->name));
  for (const analysis::Measure* measure : measures)
    if (measure->exact) cells.push_back(cell(m.*(measure->exact), measure->exact_name));
  return cells;
}

std::string join(const std::vector<std::string>& cells, const std::string& first = {}) {
  std::string line = first;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (i > 0 || !first.empty()) line += ',';
    line += cells[i];
  }
  return line;
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
  return meta;
}

/// The header lines of the plot image: the sweep, then its ranges.
std::vector<std::string> plot_header(const SweepTable& table) {
  std::vector<std::string> lines{"Sweep of " + table.scene_name + ": " +
                                 std::to_string(table.rows.size()) + " runs"};
  for (const auto& r : table.ranges) {
    char text[200];
    std::snprintf(text, sizeof text, "varied: %s from %.6g to %.6g, %d values%s", r.key.c_str(),
                  r.start, r.stop, r.count, r.log ? " (log spaced)" : "");
    lines.emplace_back(text);
  }
  return lines;
}

/// A two-key sweep's picture: one heat map per measure, first key on x (charts/heat_map.hpp).
RgbaImage sweep_heat_map_sheet(const SweepTable& table) {
  std::vector<std::vector<std::string>> rows;
  for (const auto& row : table.rows) rows.push_back(row.second);
  const auto maps =
      charts::sweep_heat_maps(table.header, rows, table.ranges[0].values(), table.ranges[0].log,
                              table.ranges[1].values(), table.ranges[1].log, table.measures);
  const int height = 120 + kMapHeightPerRow * static_cast<int>((maps.size() + 1) / 2);
  return charts::heat_map_sheet(plot_header(table), maps, kPlotWidth, height + height % 2);
}

std::vector<std::filesystem::path> write_full_outputs(const SweepTable& table,
                                                      const SweepPaths& paths) {
  const std::filesystem::path& csv = paths.csv;
  const std::filesystem::path& png = paths.png;
  output::prepare_output_dir(csv.parent_path());
  {
    output::AtomicTextFile file(csv);
    write_sweep_csv(table, file.stream());
    file.commit();
  }
  if (table.ranges.size() == 2) {
    output::write_png(png, sweep_heat_map_sheet(table));
    return {csv, png};
  }
  const auto plots = sweep_plots(table);
  const int height = 120 + kPlotHeightPerMeasure * static_cast<int>(plots.size());
  output::write_png(png,
                    charts::plot_sheet(plot_header(table), plots, kPlotWidth, height + height % 2));
  return {csv, png};
}

std::vector<std::string> split_commas(const std::string& line) {
  std::vector<std::string> cells;
  std::size_t start = 0;
  for (std::size_t comma; (comma = line.find(',', start)) != std::string::npos; start = comma + 1)
    cells.push_back(line.substr(start, comma - start));
  cells.push_back(line.substr(start));
  return cells;
}

double parse_cell(const std::string& text) {
  if (text.empty()) return std::nan("");
  return std::strtod(text.c_str(), nullptr);
}

}  // namespace

MeasureList parse_measures(const std::string& text) {
  MeasureList measures;
  for (const std::string& name : split_commas(text)) {
    const analysis::Measure* found = analysis::find_measure(name);
    if (!found) {
      throw InputError("--measure " + text + ": unknown measure '" + name + "' (" +
                       analysis::measure_names() + ")");
    }
    if (std::find(measures.begin(), measures.end(), found) != measures.end())
      throw InputError("--measure " + text + ": '" + name + "' is given twice");
    measures.push_back(found);
  }
  return measures;
}

std::vector<std::string> sweep_csv_header(const std::vector<VaryRange>& ranges,
                                          const MeasureList& measures) {
  std::vector<std::string> header;
  for (const auto& r : ranges) header.push_back(r.key);
  for (const analysis::Measure* m : measures) header.emplace_back(m->name);
  for (const analysis::Measure* m : measures)
    if (m->exact) header.emplace_back(m->exact_name);
  return header;
}

void write_sweep_csv(const SweepTable& table, std::ostream& out) {
  out << join(table.header) << '\n';
  for (const auto& [index, cells] : table.rows) out << join(cells) << '\n';
}

std::vector<overlay::PlotSpec> sweep_plots(const SweepTable& table) {
  const std::size_t keys = table.ranges.size();
  // Rows grouped by the values of the keys after the first (as written, so values that
  // print alike at 6 digits stay apart), groups in order of appearance.
  std::vector<std::string> group_names;
  std::vector<std::vector<std::size_t>> groups;
  std::map<std::string, std::size_t> group_of;
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    std::string key, name;
    for (std::size_t k = 1; k < keys; ++k) {
      const std::string& cell_text = table.rows[r].second[k];
      key += cell_text + ",";
      char value[40];
      std::snprintf(value, sizeof value, "%.6g", parse_cell(cell_text));
      if (k > 1) name += ", ";
      name += table.header[k] + " = " + value;
    }
    const auto [it, added] = group_of.emplace(key, groups.size());
    if (added) {
      group_names.push_back(name);
      groups.emplace_back();
    }
    groups[it->second].push_back(r);
  }
  std::vector<overlay::PlotSpec> plots;
  for (std::size_t m = 0; m < table.measures.size(); ++m) {
    const std::string column(table.measures[m]->name);
    const std::size_t col = keys + m;
    std::optional<std::size_t> exact_col;
    for (std::size_t c = keys + table.measures.size(); c < table.header.size(); ++c)
      if (table.header[c] == column + "_exact") exact_col = c;
    overlay::PlotSpec spec;
    spec.title = column + (exact_col ? " (measured: solid; exact model: dashed)" : "");
    spec.x_label = table.header[0] + (table.ranges[0].log ? " (log scale)" : "");
    spec.y_label = std::string(table.measures[m]->axis_label);
    spec.log_x = table.ranges[0].log;
    spec.log_y = table.measures[m]->log_scale;
    spec.legend = true;
    for (std::size_t g = 0; g < groups.size(); ++g) {
      overlay::Series measured, exact;
      measured.label = group_names[g].empty() ? "measured" : group_names[g];
      exact.label = group_names[g].empty() ? "exact model" : "exact, " + group_names[g];
      overlay::palette_colour(static_cast<int>(g), measured.r, measured.g, measured.b);
      exact.r = measured.r * 0.3;
      exact.g = measured.g * 0.3;
      exact.b = measured.b * 0.3;
      exact.dashed = true;
      for (std::size_t r : groups[g]) {
        const auto& cells = table.rows[r].second;
        measured.x.push_back(parse_cell(cells[0]));
        measured.y.push_back(parse_cell(cells[col]));
        if (exact_col) {
          exact.x.push_back(parse_cell(cells[0]));
          exact.y.push_back(parse_cell(cells[*exact_col]));
        }
      }
      spec.series.push_back(std::move(measured));
      if (exact_col) spec.series.push_back(std::move(exact));  // dashed, on top
    }
    plots.push_back(std::move(spec));
  }
  return plots;
}

SweepResult run_sweep(const SweepRequest& request) {
  const scene::Scene base =
      request.scene ? *request.scene : scene::parse_scene(request.scene_path, request.overrides);
  if (!base.compare.empty()) {
    throw InputError(request.scene_path.string() +
                     ": a comparison scene ([[compare]]) has one run per tile; sweep a "
                     "single-model scene (set model.kind and model.integrator)");
  }
  if (request.measures.empty()) throw InputError("sweep: give --measure M[,M…]");
  const SweepGrid grid(request.ranges);
  const bool sharded = request.shard_count > 0;
  if (sharded && (request.shard_index < 0 || request.shard_index >= request.shard_count)) {
    throw InputError("--shard " + std::to_string(request.shard_index) + "/" +
                     std::to_string(request.shard_count) + ": K must be from 0 to N − 1");
  }
  std::vector<std::size_t> indices;
  for (std::size_t i = 0; i < grid.size(); ++i) {
    if (!sharded || i % static_cast<std::size_t>(request.shard_count) ==
                        static_cast<std::size_t>(request.shard_index))
      indices.push_back(i);
  }
  // Every point's scene first: a bad value fails the sweep before any run.
  std::vector<scene::Scene> scenes;
  scenes.reserve(indices.size());
  for (std::size_t i : indices) {
    std::vector<std::string> overrides = request.overrides;
    for (auto& o : point_overrides(base, grid, i)) overrides.push_back(std::move(o));
    scenes.push_back(scene::parse_scene(request.scene_path, overrides));
  }

  std::vector<analysis::RunMeasures> results(indices.size());
  std::atomic<std::size_t> next{0};
  std::atomic<int> signal{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  // A running point stops within a few steps of a signal (or of another point's failure): its
  // physics loop asks this predicate, which records the signal for the others.
  const std::function<bool()> abandon = [&] {
    if (signal != 0) return true;
    if (const int s = stop_signal(request.stop_signal, "sweep steps")) signal = s;
    return signal != 0;
  };
  const auto work = [&] {
    for (std::size_t i; (i = next++) < indices.size();) {
      if (const int s = stop_signal(request.stop_signal, "sweep point")) signal = s;
      if (signal != 0) return;
      try {
        results[i] = analysis::measure_run(scenes[i], abandon);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(failure_mutex);
        if (!failure) failure = std::current_exception();
        signal = -1;
        return;
      }
    }
  };
  unsigned jobs = request.jobs > 0 ? static_cast<unsigned>(request.jobs)
                                   : std::max(1u, std::thread::hardware_concurrency());
  jobs =
      static_cast<unsigned>(std::min<std::size_t>(jobs, std::max<std::size_t>(1, indices.size())));
  std::vector<std::thread> threads;
  for (unsigned j = 1; j < jobs; ++j) threads.emplace_back(work);
  work();
  for (auto& t : threads) t.join();
  if (failure) std::rethrow_exception(failure);
  SweepResult result;
  if (signal > 0) {
    result.signal = signal;
    return result;
  }

  SweepTable table;
  table.scene_name = base.name;
  table.ranges = grid.ranges();
  table.measures = request.measures;
  table.header = sweep_csv_header(table.ranges, table.measures);
  for (std::size_t r = 0; r < indices.size(); ++r)
    table.rows.emplace_back(indices[r],
                            row_cells(grid.point(indices[r]), table.measures, results[r]));
  if (!sharded) {
    result.written = write_full_outputs(table, request.layout(table.scene_name));
    return result;
  }
  const auto path =
      request.layout(table.scene_name).shard(request.shard_index, request.shard_count);
  output::prepare_output_dir(path.parent_path());
  output::AtomicTextFile file(path);
  file.stream() << kShardMagic << request.shard_index << " of " << request.shard_count << ": "
                << shard_meta(table, grid.size(),
                              output::sha256_text(scene::canonical_json(base, 0)))
                << '\n'
                << join(table.header, "grid_index") << '\n';
  for (const auto& [index, cells] : table.rows)
    file.stream() << join(cells, std::to_string(index)) << '\n';
  file.commit();
  result.written.push_back(path);
  return result;
}

namespace {

/// A line of a shard without its line ending: LF or CRLF (a file that went through Windows).
bool read_line(std::istream& in, std::string& line) {
  if (!std::getline(in, line)) return false;
  if (!line.empty() && line.back() == '\r') line.pop_back();
  return true;
}

/// The fields of a shard's first line after "K of N: ": scene, scene_sha256, build, points,
/// vary (one per range, in order), measure.
struct ShardLine {
  std::string scene, scene_sha256, build, points, measure;
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

std::vector<std::filesystem::path> merge_sweep(const std::vector<std::filesystem::path>& shards,
                                               const SweepLayout& layout) {
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
    if (!read_line(in, header) || header != join(table.header, "grid_index"))
      throw InputError(name + ":2: header differs from the sweep's: expected grid_index," +
                       join(table.header));
    // Cells 1 … ranges are the varied values (always numbers); the rest are measures and
    // their exact columns, empty where undefined.
    const std::size_t varied = table.ranges.size();
    int line_number = 2;
    for (std::string row; read_line(in, row);) {
      ++line_number;
      const std::string where = name + ":" + std::to_string(line_number);
      auto cells = split_commas(row);
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
      for (std::size_t c = 1; c < cells.size(); ++c) {
        if (is_number(cells[c]) || (c > varied && cells[c].empty())) continue;
        throw InputError(where + ": " + table.header[c - 1] + " '" + cells[c] +
                         "' is not a number");
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
                                 : layout(table.scene_name).shard(k, shard_count).string();
    throw InputError(file + ": grid point " + std::to_string(i) + " of " + std::to_string(points) +
                     " is missing" + (it == shard_files.end() ? " (shard not given)" : ""));
  }
  for (auto& [index, cells] : rows) table.rows.emplace_back(index, std::move(cells));
  return write_full_outputs(table, layout(table.scene_name));
}

}  // namespace bookspin::jobs
