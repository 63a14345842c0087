#include "pipeline/sweep.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>
#include <thread>

#include "common/errors.hpp"
#include "output/atomic_output.hpp"
#include "output/output_dir.hpp"
#include "output/png_writer.hpp"
#include "physics/exact_model.hpp"
#include "pipeline/panel.hpp"

namespace bookspin::pipeline {

namespace {

constexpr const char* kShardMagic = "# bookspin sweep shard ";
constexpr int kPlotWidth = 1400;
constexpr int kPlotHeightPerMeasure = 330;

/// Index (0–2) of the middle one of three principal moments (body x, y, z).
int intermediate_axis(const Eigen::Vector3d& moments) {
  int lo = 0, hi = 0;
  for (int i = 1; i < 3; ++i) {
    if (moments[i] < moments[lo]) lo = i;
    if (moments[i] >= moments[hi]) hi = i;
  }
  if (lo == hi) return 1;  // all equal: any axis is "intermediate"
  return 3 - lo - hi;
}

int sign_of(double x) { return (x > 0.0) - (x < 0.0); }

/// The exact model's first zero of ω about `axis` after t = 0 (docs/physics.md §14): zeros
/// of sn are T/2 apart, so the first lies in (0, T/2]; bracketed on 64 samples per T/2 and
/// bisected to round-off. Empty for steady and separatrix motion (no finite T).
std::optional<double> exact_first_flip(const physics::ExactRotation& exact, int axis) {
  const double half = exact.flip_period();
  if (!std::isfinite(half) || half <= 0.0) return std::nullopt;
  const auto f = [&](double t) { return exact.omega_body(t)[axis]; };
  constexpr int kSamples = 64;
  const double h = half / kSamples;
  double t0 = 0.0;
  int reference = sign_of(f(0.0));  // 0 when it starts on a zero: the sign just after counts
  for (int j = 1; j <= 2 * kSamples + 1; ++j) {
    const double t1 = j * h;
    const int s = sign_of(f(t1));
    if (reference == 0) {
      reference = s;
    } else if (s == 0) {
      return t1;
    } else if (s != reference) {
      double a = t0, b = t1;
      for (int it = 0; it < 200 && b - a > 0.0; ++it) {
        const double m = 0.5 * (a + b);
        if (m <= a || m >= b) break;
        (sign_of(f(m)) == reference ? a : b) = m;
      }
      return 0.5 * (a + b);
    }
    t0 = t1;
  }
  return std::nullopt;
}

/// Rotation angle of a rotation matrix, accurate near 0 (2·atan2(|v|, |w|) of its quaternion).
double rotation_angle(const Eigen::Matrix3d& r) {
  const Eigen::Quaterniond q(r);
  return 2.0 * std::atan2(q.vec().norm(), std::abs(q.w()));
}

std::string cell(const std::optional<double>& v) { return v ? full_precision(*v) : std::string(); }

std::vector<std::string> row_cells(const std::vector<double>& point,
                                   const std::vector<Measure>& measures, const PointMeasures& m) {
  std::vector<std::string> cells;
  for (double v : point) cells.push_back(full_precision(v));
  for (Measure measure : measures) {
    switch (measure) {
      case Measure::first_flip:
        cells.push_back(cell(m.first_flip));
        break;
      case Measure::flip_period:
        cells.push_back(cell(m.flip_period));
        break;
      case Measure::energy_drift:
        cells.push_back(cell(m.energy_drift));
        break;
      case Measure::orientation_error:
        cells.push_back(cell(m.orientation_error));
        break;
      case Measure::diverged_at:
        cells.push_back(cell(m.diverged_at));
        break;
    }
  }
  for (Measure measure : measures) {
    if (measure == Measure::first_flip) cells.push_back(cell(m.first_flip_exact));
    if (measure == Measure::flip_period) cells.push_back(cell(m.flip_period_exact));
  }
  return cells;
}

std::vector<std::string> table_header(const std::vector<VaryRange>& ranges,
                                      const std::vector<Measure>& measures) {
  std::vector<std::string> header;
  for (const auto& r : ranges) header.push_back(r.key);
  for (Measure m : measures) header.emplace_back(to_string(m));
  for (Measure m : measures) {
    if (m == Measure::first_flip) header.emplace_back("first_flip_exact");
    if (m == Measure::flip_period) header.emplace_back("flip_period_exact");
  }
  return header;
}

std::string join(const std::vector<std::string>& cells, const std::string& first = {}) {
  std::string line = first;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (i > 0 || !first.empty()) line += ',';
    line += cells[i];
  }
  return line;
}

/// Everything after "shard K of N: " in a shard's first line: the same in every shard.
std::string shard_meta(const SweepTable& table, std::size_t points) {
  std::string meta = "scene=" + table.scene_name + " points=" + std::to_string(points);
  for (const auto& r : table.ranges) meta += " vary=" + r.key + "=" + r.spec();
  meta += " measure=";
  for (std::size_t i = 0; i < table.measures.size(); ++i) {
    if (i > 0) meta += ',';
    meta += to_string(table.measures[i]);
  }
  return meta;
}

std::filesystem::path shard_path(const std::filesystem::path& dir, const std::string& scene, int k,
                                 int n) {
  return dir / (scene + "-sweep.shard-" + std::to_string(k) + "-of-" + std::to_string(n) + ".csv");
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

std::vector<std::filesystem::path> write_full_outputs(const SweepTable& table,
                                                      const std::filesystem::path& out_dir) {
  output::prepare_output_dir(out_dir);
  const auto csv = out_dir / (table.scene_name + "-sweep.csv");
  const auto png = out_dir / (table.scene_name + "-sweep.png");
  {
    output::AtomicTextFile file(csv);
    write_sweep_csv(table, file.stream());
    file.commit();
  }
  const auto plots = sweep_plots(table);
  const int height = 120 + kPlotHeightPerMeasure * static_cast<int>(plots.size());
  output::write_png(png, plot_sheet(plot_header(table), plots, kPlotWidth, height + height % 2));
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

std::string measure_axis_label(const std::string& column) {
  if (column == "first_flip") return "first flip (time units)";
  if (column == "flip_period") return "flip period (time units)";
  if (column == "energy_drift") return "max |E/E0 - 1|";
  if (column == "orientation_error") return "orientation error at the end (rad)";
  return "diverged at t (time units)";
}

}  // namespace

std::string_view to_string(Measure measure) {
  switch (measure) {
    case Measure::first_flip:
      return "first_flip";
    case Measure::flip_period:
      return "flip_period";
    case Measure::energy_drift:
      return "energy_drift";
    case Measure::orientation_error:
      return "orientation_error";
    case Measure::diverged_at:
      return "diverged_at";
  }
  return "?";
}

std::vector<Measure> parse_measures(const std::string& text) {
  static constexpr Measure kAll[] = {Measure::first_flip, Measure::flip_period,
                                     Measure::energy_drift, Measure::orientation_error,
                                     Measure::diverged_at};
  std::vector<Measure> measures;
  for (const std::string& name : split_commas(text)) {
    const auto* found = std::find_if(std::begin(kAll), std::end(kAll),
                                     [&](Measure m) { return to_string(m) == name; });
    if (found == std::end(kAll)) {
      throw InputError("--measure " + text + ": unknown measure '" + name +
                       "' (first_flip, flip_period, energy_drift, orientation_error, diverged_at)");
    }
    if (std::find(measures.begin(), measures.end(), *found) != measures.end())
      throw InputError("--measure " + text + ": '" + name + "' is given twice");
    measures.push_back(*found);
  }
  return measures;
}

double cos_intermediate_L(const physics::Diagnostics& diagnostics,
                          const Eigen::Vector3d& principal_moments) {
  return diagnostics.cos_axis_L[intermediate_axis(principal_moments)];
}

PointMeasures measure_run(const scene::Scene& scene) {
  PointMeasures result;
  const Eigen::Vector3d moments = scene.body.moments;
  auto sim = physics::make_simulator(scene.body, scene.model);
  sim->reset(scene.initial);
  physics::Diagnostics d = sim->diagnostics();
  const double e0 = d.energy_total;
  double drift = 0.0;
  double prev_c = cos_intermediate_L(d, moments), prev_t = 0.0;
  int last_sign = sign_of(prev_c);
  int flips = 0;
  double first = 0.0, last = 0.0;
  const long long total = static_cast<long long>(scene.frames - 1) * scene.steps_per_frame;
  for (long long n = 1; n <= total; ++n) {
    sim->step(scene.dt);
    const double t = static_cast<double>(n) * scene.dt;  // a product, as FrameSource does
    if (!sim->finite()) {
      result.diverged_at = t;
      break;
    }
    d = sim->diagnostics();
    drift =
        std::max(drift, e0 != 0.0 ? std::abs(d.energy_total / e0 - 1.0) : std::abs(d.energy_total));
    const double c = cos_intermediate_L(d, moments);
    const int s = sign_of(c);
    if (s != 0) {
      if (last_sign != 0 && s != last_sign) {
        // Linear interpolation between the two steps around the zero (prev_c may be 0).
        const double t_flip = prev_t + (t - prev_t) * (prev_c / (prev_c - c));
        if (flips++ == 0) first = t_flip;
        last = t_flip;
      }
      last_sign = s;
    }
    prev_c = c;
    prev_t = t;
  }
  result.energy_drift = drift;
  if (flips >= 1) result.first_flip = first;
  if (flips >= 2) result.flip_period = (last - first) / (flips - 1);

  physics::ExactModel reference(scene.body);
  reference.reset(scene.initial);
  const physics::ExactRotation& exact = reference.rotation();
  const double half = exact.flip_period();
  if (std::isfinite(half)) result.flip_period_exact = half;
  result.first_flip_exact = exact_first_flip(exact, intermediate_axis(moments));
  if (!result.diverged_at) {
    const Eigen::Matrix3d r_exact = exact.orientation(static_cast<double>(total) * scene.dt);
    result.orientation_error =
        rotation_angle(r_exact.transpose() * sim->orientation());
  }
  return result;
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
    const std::string column(to_string(table.measures[m]));
    const std::size_t col = keys + m;
    std::optional<std::size_t> exact_col;
    for (std::size_t c = keys + table.measures.size(); c < table.header.size(); ++c)
      if (table.header[c] == column + "_exact") exact_col = c;
    overlay::PlotSpec spec;
    spec.title = column + (exact_col ? " (measured: solid; exact model: dashed)" : "");
    spec.x_label = table.header[0] + (table.ranges[0].log ? " (log scale)" : "");
    spec.y_label = measure_axis_label(column);
    spec.log_x = table.ranges[0].log;
    spec.log_y = table.measures[m] == Measure::energy_drift ||
                 table.measures[m] == Measure::orientation_error;
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
  const scene::Scene base = scene::parse_scene(request.scene_path, request.overrides);
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

  std::vector<PointMeasures> results(indices.size());
  std::atomic<std::size_t> next{0};
  std::atomic<int> signal{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  const auto work = [&] {
    for (std::size_t i; (i = next++) < indices.size();) {
      if (request.stop_signal) {
        if (const int s = request.stop_signal()) signal = s;
      }
      if (signal != 0) return;
      try {
        results[i] = measure_run(scenes[i]);
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
  table.header = table_header(table.ranges, table.measures);
  for (std::size_t r = 0; r < indices.size(); ++r)
    table.rows.emplace_back(indices[r],
                            row_cells(grid.point(indices[r]), table.measures, results[r]));
  if (!sharded) {
    result.written = write_full_outputs(table, request.out_dir);
    return result;
  }
  output::prepare_output_dir(request.out_dir);
  const auto path =
      shard_path(request.out_dir, table.scene_name, request.shard_index, request.shard_count);
  output::AtomicTextFile file(path);
  file.stream() << kShardMagic << request.shard_index << " of " << request.shard_count << ": "
                << shard_meta(table, grid.size()) << '\n'
                << join(table.header, "grid_index") << '\n';
  for (const auto& [index, cells] : table.rows)
    file.stream() << join(cells, std::to_string(index)) << '\n';
  file.commit();
  result.written.push_back(path);
  return result;
}

std::vector<std::filesystem::path> merge_sweep(const std::vector<std::filesystem::path>& shards,
                                               const std::filesystem::path& out_dir) {
  if (shards.empty()) throw InputError("sweep --merge: give the shard CSV files");
  SweepTable table;
  std::string meta;  // the first file's, which every other must repeat
  int shard_count = 0;
  std::size_t points = 0;
  std::map<int, std::filesystem::path> shard_files;
  std::map<std::size_t, std::vector<std::string>> rows;
  std::map<std::size_t, std::filesystem::path> row_file;
  for (const auto& path : shards) {
    const std::string name = path.string();
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(name + ": cannot read the shard file");
    std::string first, header;
    if (!std::getline(in, first) || first.rfind(kShardMagic, 0) != 0)
      throw InputError(name + ":1: not a sweep shard (no \"" + std::string(kShardMagic) +
                       "\" line)");
    int k = -1, n = 0, used = 0;
    const std::string rest = first.substr(std::string(kShardMagic).size());
    if (std::sscanf(rest.c_str(), "%d of %d: %n", &k, &n, &used) != 2 || used == 0 || n < 1 ||
        k < 0 || k >= n)
      throw InputError(name + ":1: expected \"" + kShardMagic + "K of N: …\"");
    const std::string this_meta = rest.substr(static_cast<std::size_t>(used));
    if (meta.empty()) {
      meta = this_meta;
      shard_count = n;
      std::istringstream words(meta);
      std::vector<VaryRange> ranges;
      for (std::string word; words >> word;) {
        if (word.rfind("scene=", 0) == 0)
          table.scene_name = word.substr(6);
        else if (word.rfind("points=", 0) == 0)
          points = std::strtoull(word.c_str() + 7, nullptr, 10);
        else if (word.rfind("vary=", 0) == 0)
          ranges.push_back(parse_vary(word.substr(5)));
        else if (word.rfind("measure=", 0) == 0)
          table.measures = parse_measures(word.substr(8));
      }
      const SweepGrid grid(ranges);
      if (table.scene_name.empty() || grid.size() != points || table.measures.empty())
        throw InputError(name + ":1: the shard line does not describe a sweep");
      table.ranges = ranges;
      table.header = table_header(table.ranges, table.measures);
    } else if (this_meta != meta || n != shard_count) {
      throw InputError(name + ":1: a shard of another sweep (first line differs from " +
                       shards.front().string() + ")");
    }
    if (!shard_files.emplace(k, path).second) {
      throw InputError(name + ": shard " + std::to_string(k) + " of " + std::to_string(n) +
                       " is also given as " + shard_files[k].string());
    }
    if (!std::getline(in, header) || header != join(table.header, "grid_index"))
      throw InputError(name + ":2: header differs from the sweep's: expected grid_index," +
                       join(table.header));
    int line_number = 2;
    for (std::string line; std::getline(in, line);) {
      ++line_number;
      const std::string where = name + ":" + std::to_string(line_number);
      auto cells = split_commas(line);
      if (cells.size() != table.header.size() + 1)
        throw InputError(where + ": expected " + std::to_string(table.header.size() + 1) +
                         " cells");
      char* end = nullptr;
      const unsigned long long index = std::strtoull(cells[0].c_str(), &end, 10);
      if (cells[0].empty() || *end != '\0' || index >= points ||
          index % static_cast<unsigned long long>(n) != static_cast<unsigned long long>(k))
        throw InputError(where + ": grid_index '" + cells[0] + "' is not a point of shard " +
                         std::to_string(k) + " of " + std::to_string(n));
      cells.erase(cells.begin());
      if (!rows.emplace(index, std::move(cells)).second) {
        throw InputError(where + ": grid point " + std::to_string(index) +
                         " is duplicated (also in " + row_file[index].string() + ")");
      }
      row_file[index] = path;
    }
  }
  for (std::size_t i = 0; i < points; ++i) {
    if (rows.count(i)) continue;
    const int k = static_cast<int>(i % static_cast<std::size_t>(shard_count));
    const auto it = shard_files.find(k);
    const std::string file =
        it != shard_files.end()
            ? it->second.string()
            : shard_path(shards.front().parent_path(), table.scene_name, k, shard_count).string();
    throw InputError(file + ": grid point " + std::to_string(i) + " of " + std::to_string(points) +
                     " is missing" + (it == shard_files.end() ? " (shard not given)" : ""));
  }
  for (auto& [index, cells] : rows) table.rows.emplace_back(index, std::move(cells));
  return write_full_outputs(table, out_dir);
}

}  // namespace bookspin::pipeline
