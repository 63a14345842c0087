#include "fit/prepared_recording.hpp"

#include "common/errors.hpp"
#include "fit/joint_fit.hpp"
#include "fit/pool.hpp"
#include "fit/saturation.hpp"

namespace bookspin::fit {

PreparedRecording prepare_recording(const GyroRecording& recording, const FitSettings& settings) {
  const GyroRecording alone = pool_recordings({recording});
  PreparedRecording prepared;
  prepared.name = alone.parts.front().name;
  prepared.source = alone.parts.front().source;
  prepared.part = alone.parts.front();
  prepared.search = find_flights(alone);
  prepared.data = toss_data(alone, prepared.search, find_saturation(alone));
  if (prepared.data.empty()) return prepared;
  Parameters p = start(prepared.data, settings);
  p.e.assign(1, {0.0, 0.0, 0.0});
  prepared.omega0 = p.omega0;
  try {
    const BiasFreedom bias = bias_freedom(alone.parts, prepared.data, {});
    std::vector<bool> rate_held;
    joint_fit(prepared.data, p, bias, settings, alone.source, rate_held);
  } catch (const InputError&) {
    return prepared;  // no body of its own: its flights start from their first samples
  }
  prepared.omega0 = p.omega0;
  prepared.bias_correction = p.e.front();
  prepared.own_body = true;
  prepared.R0 = p.R0 * rotation_from_angle_axis(p.aa.data());
  prepared.log_ratios = p.log_ratios;
  return prepared;
}

std::size_t prepared_bytes(const PreparedRecording& prepared) {
  std::size_t bytes = sizeof prepared + prepared.name.size() + prepared.source.size();
  for (const TossData& d : prepared.data)
    bytes += sizeof d + d.tau.size() * sizeof(double) + d.omega.size() * sizeof(Eigen::Vector3d);
  bytes += prepared.omega0.size() * sizeof(prepared.omega0.front());
  bytes += prepared.search.flights.size() * sizeof(Flight);
  for (const DroppedStretch& s : prepared.search.dropped) bytes += sizeof s + s.reason.size();
  return bytes;
}

}  // namespace bookspin::fit
