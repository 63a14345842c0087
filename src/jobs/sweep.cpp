#include "jobs/sweep.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>

#include "common/errors.hpp"
#include "scene/key_label.hpp"

namespace bookspin::jobs {

charts::SweepChart sweep_chart(const SweepTable& table) {
  charts::SweepChart chart{table.scene_name, table.scene_title, {},
                           table.measures,   table.header,      {}};
  for (const VaryRange& r : table.ranges)
    chart.axes.push_back({r.key, r.start, r.stop, r.log, r.values(), scene::key_caption(r.key),
                          scene::key_words(r.key).words});
  for (const auto& row : table.rows) chart.rows.push_back(row.second);
  return chart;
}

SweepTable measure_sweep(const SweepRequest& request) {
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
  // Every point's scene first: a bad value fails the sweep before any run; a value the model's
  // engine refuses is that point's reason (unless it is every point's).
  std::vector<std::optional<scene::Scene>> scenes;
  std::vector<std::string> refused(indices.size());
  std::optional<scene::EngineRefusal> first_refusal;
  scenes.reserve(indices.size());
  for (std::size_t r = 0; r < indices.size(); ++r) {
    std::vector<std::string> overrides = request.overrides;
    for (auto& o : point_overrides(base, grid, indices[r])) overrides.push_back(std::move(o));
    try {
      scenes.emplace_back(scene::parse_scene(request.scene_path, overrides));
    } catch (const scene::EngineRefusal& e) {
      scenes.emplace_back();
      refused[r] = e.refused_key() + ": " + e.reason();
      if (!first_refusal) first_refusal = e;
    }
  }
  // Refused at every point of the grid (a shard's own points and, for a shard, the others'),
  // the sweep is bad input as a whole.
  const auto runs = [](const auto& s) { return s.has_value(); };
  if (first_refusal && std::none_of(scenes.begin(), scenes.end(), runs)) {
    bool elsewhere = false;
    for (std::size_t i = 0; sharded && !elsewhere && i < grid.size(); ++i) {
      if (i % static_cast<std::size_t>(request.shard_count) ==
          static_cast<std::size_t>(request.shard_index))
        continue;
      std::vector<std::string> overrides = request.overrides;
      for (auto& o : point_overrides(base, grid, i)) overrides.push_back(std::move(o));
      try {
        scene::parse_scene(request.scene_path, overrides);
        elsewhere = true;
      } catch (const scene::EngineRefusal&) {
      }
    }
    if (!elsewhere)
      throw InputError(std::string(first_refusal->what()) + " (at every one of the " +
                       std::to_string(grid.size()) + " points)");
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
      if (!scenes[i]) continue;  // refused: its row says why
      try {
        results[i] = analysis::measure_run(*scenes[i], abandon);
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
  if (signal > 0) throw Interrupted(signal);

  SweepTable table;
  table.scene_name = base.name;
  table.scene_title = base.title;
  table.ranges = grid.ranges();
  table.measures = request.measures;
  table.header = sweep_csv_header(table.ranges, table.measures);
  for (std::size_t r = 0; r < indices.size(); ++r) {
    const std::vector<double> point = grid.point(indices[r]);
    table.rows.emplace_back(
        indices[r], refused[r].empty() ? sweep_row_cells(point, table.measures, results[r])
                                       : sweep_refused_cells(point, table.measures, refused[r]));
  }
  return table;
}

}  // namespace bookspin::jobs
