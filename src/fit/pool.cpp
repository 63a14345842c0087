#include "fit/pool.hpp"

#include <stdexcept>
#include <string>

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

}  // namespace

GyroRecording pool_recordings(const std::vector<GyroRecording>& recordings) {
  if (recordings.empty()) throw InputError("pooling recordings: give one or more");
  for (std::size_t a = 0; a < recordings.size(); ++a)
    for (std::size_t b = 0; b < a; ++b) check_not_twice(recordings[b], recordings[a]);
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
