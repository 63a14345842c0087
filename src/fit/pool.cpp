#include "fit/pool.hpp"

#include <string>

#include "common/errors.hpp"
#include "fit/flights.hpp"

namespace bookspin::fit {

GyroRecording pool_recordings(const std::vector<GyroRecording>& recordings) {
  if (recordings.size() < 2) throw InputError("pooling recordings: give two or more");
  for (std::size_t a = 0; a < recordings.size(); ++a)
    for (std::size_t b = 0; b < a; ++b)
      if (recordings[a].source == recordings[b].source)
        throw InputError(recordings[a].source + ": given twice");
  GyroRecording pooled;
  pooled.name = recordings.front().name + "-and-" + std::to_string(recordings.size() - 1) + "-more";
  pooled.source = recordings.front().source + " and " + std::to_string(recordings.size() - 1) +
                  " more recording(s)";
  for (const GyroRecording& recording : recordings) {
    const FlightSearch own = find_flights(recording);
    RecordingPart part;
    part.name = recording.name;
    part.source = recording.source;
    // 1 s after the previous recording's last sample, a pause half way.
    if (!pooled.t.empty()) {
      const double start = pooled.t.back() + 1.0;
      part.t_offset = start - recording.t.front();
      pooled.pauses.push_back(pooled.t.back() + 0.5);
    } else {
      part.t_offset = 0.0;
    }
    part.first = static_cast<int>(pooled.t.size());
    part.t_start = recording.t.front() + part.t_offset;
    part.bias = own.bias;
    part.rest = own.rest;
    part.gyroscope_range = recording.gyroscope_range;
    for (std::size_t i = 0; i < recording.t.size(); ++i) {
      pooled.t.push_back(recording.t[i] + part.t_offset);
      pooled.omega.push_back(recording.omega[i] - own.bias);
    }
    for (double pause : recording.pauses) pooled.pauses.push_back(pause + part.t_offset);
    part.last = static_cast<int>(pooled.t.size()) - 1;
    pooled.parts.push_back(part);
  }
  return pooled;
}

const RecordingPart* part_at(const std::vector<RecordingPart>& parts, double t) {
  const RecordingPart* found = parts.empty() ? nullptr : &parts.front();
  for (const RecordingPart& part : parts)
    if (t >= part.t_start - 0.5) found = &part;
  return found;
}

}  // namespace bookspin::fit
