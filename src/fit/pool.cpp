#include "fit/pool.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <tuple>

#include "common/errors.hpp"
#include "fit/flights.hpp"

namespace bookspin::fit {
namespace {

/// Throws InputError where `later` is `earlier` again: the same source as given, one file
/// however spelled (GyroRecording::file: relative or absolute, through a symlink), or the same
/// samples (an export given beside its own zip, or one file copied): each toss would otherwise
/// be predicted partly from its own copy.
void check_not_twice(const GyroRecording& earlier, const GyroRecording& later) {
  if (later.source == earlier.source) throw InputError(later.source + ": given twice");
  if (!later.file.empty() && later.file == earlier.file)
    throw InputError(later.source + ": the same file as " + earlier.source + ", given twice");
  if (later.t == earlier.t && later.omega == earlier.omega)
    throw InputError(later.source + ": the same samples as " + earlier.source +
                     " (an export beside its own zip, or a copy), given twice");
}

/// The canonical order of a pool's recordings: by name, then (one name twice, from two
/// folders) by their samples, first the count, then the times and ω read lexicographically. No
/// two recordings given compare equal (check_not_twice refuses the same samples), so any order
/// the recordings are given in sorts to one.
bool canonical_before(const GyroRecording& a, const GyroRecording& b) {
  if (a.name != b.name) return a.name < b.name;
  if (a.t.size() != b.t.size()) return a.t.size() < b.t.size();
  if (a.t != b.t) return a.t < b.t;
  for (std::size_t i = 0; i < a.omega.size(); ++i) {
    const Eigen::Vector3d &u = a.omega[i], &v = b.omega[i];
    if (u != v) return std::tie(u[0], u[1], u[2]) < std::tie(v[0], v[1], v[2]);
  }
  return a.source < b.source;
}

}  // namespace

GyroRecording pool_recordings(const std::vector<GyroRecording>& given) {
  if (given.empty()) throw InputError("pooling recordings: give one or more");
  for (std::size_t a = 0; a < given.size(); ++a)
    for (std::size_t b = 0; b < a; ++b) check_not_twice(given[b], given[a]);
  // A pool is a set: its recordings in their canonical order, whatever order they were given
  // in (a command line's, a dropped folder's), so that every toss, number and name is the same.
  std::vector<const GyroRecording*> order;
  for (const GyroRecording& recording : given) order.push_back(&recording);
  std::sort(order.begin(), order.end(), [](const GyroRecording* a, const GyroRecording* b) {
    return canonical_before(*a, *b);
  });
  std::vector<GyroRecording> recordings;
  recordings.reserve(order.size());
  for (const GyroRecording* recording : order) recordings.push_back(*recording);
  // Unique names: two files made file-safe alike ("anna:b.csv", "anna*b.csv"; "über.csv" typed
  // composed and decomposed) would name each other's tosses; the later in the canonical order takes
  // the first free "-2", "-3", ….
  for (std::size_t a = 1; a < recordings.size(); ++a) {
    const auto taken = [&](const std::string& name, std::size_t self) {
      for (std::size_t b = 0; b < recordings.size(); ++b)
        if (b != self && recordings[b].name == name) return true;
      return false;
    };
    bool earlier = false;
    for (std::size_t b = 0; b < a; ++b)
      earlier = earlier || recordings[b].name == recordings[a].name;
    if (!earlier) continue;
    const std::string base = recordings[a].name;
    for (int k = 2;; ++k)
      if (!taken(base + "-" + std::to_string(k), a)) {
        recordings[a].name = base + "-" + std::to_string(k);
        break;
      }
  }
  GyroRecording pooled;
  const std::size_t more = recordings.size() - 1;
  pooled.name = recordings.front().name;
  pooled.source = recordings.front().source;
  if (more > 0) {
    pooled.name += "-and-" + std::to_string(more) + "-more";
    pooled.source += " and " + std::to_string(more) + " more recording(s)";
  }
  pooled.gyroscope_range = recordings.front().gyroscope_range;
  for (const GyroRecording& recording : recordings) {
    const Rest rest = measure_rest(recording);
    RecordingPart part;
    part.name = recording.name;
    part.source = recording.source;
    // 1 s after the previous recording's last sample, a pause half way.
    if (!pooled.t.empty()) {
      const double start = pooled.t.back() + 1.0;
      part.t_offset = start - recording.t.front();
      pooled.pauses.push_back(pooled.t.back() + 0.5);
    }
    part.first = static_cast<int>(pooled.t.size());
    part.t_start = recording.t.front() + part.t_offset;
    part.bias = rest.mean;
    part.rest = rest;
    part.gyroscope_range = recording.gyroscope_range;
    for (std::size_t i = 0; i < recording.t.size(); ++i) {
      pooled.t.push_back(recording.t[i] + part.t_offset);
      pooled.omega.push_back(recording.omega[i]);
    }
    for (double pause : recording.pauses) pooled.pauses.push_back(pause + part.t_offset);
    part.last = static_cast<int>(pooled.t.size()) - 1;
    pooled.parts.push_back(part);
  }
  return pooled;
}

void check_pooled(const GyroRecording& recording) {
  std::size_t covered = 0;
  for (const RecordingPart& part : recording.parts)
    covered += static_cast<std::size_t>(part.last - part.first + 1);
  if (covered != recording.t.size() || recording.t.size() == 0)
    throw std::logic_error(recording.source +
                           ": its parts do not cover its samples: a recording not pooled "
                           "(fit/pool.hpp: pool_recordings) was fitted");
}

std::size_t part_index(const std::vector<RecordingPart>& parts, double t) {
  std::size_t found = 0;
  for (std::size_t k = 0; k < parts.size(); ++k)
    if (t >= parts[k].t_start - 0.5) found = k;
  return found;
}

const RecordingPart& part_at(const std::vector<RecordingPart>& parts, double t) {
  return parts.at(part_index(parts, t));  // std::out_of_range for no parts: not pooled
}

}  // namespace bookspin::fit
