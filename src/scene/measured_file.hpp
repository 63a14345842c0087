#pragma once
// A measured motion a scene names to be shown beside its run (`measured.omega`,
// scenes/README.md): body-frame ω samples, the phone-toss lab's measured toss
// (docs/phone-lab.md, "A toss in the explorer"). Only the explorer draws it.
#include <Eigen/Dense>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace bookspin::scene {

/// The samples of a measured ω file.
struct MeasuredOmega {
  std::string file;        ///< the file, resolved against the scene file's folder
  std::vector<double> t;   ///< time units since the scene's start, ≥ 0, strictly increasing
  Eigen::Matrix3Xd omega;  ///< 3×N, body frame, rad per time unit
};

/// At most this many bytes in a measured ω file.
inline constexpr std::uintmax_t kMaxMeasuredFileBytes = 8 << 20;
/// At most this many samples (rows) in a measured ω file.
inline constexpr int kMaxMeasuredSamples = 100000;

/// Parses CSV `text` with the header `t,wx,wy,wz` and one sample a row (numbers; t ≥ 0 and
/// strictly increasing, each ω component within initial.angular_velocity's range, 1 …
/// kMaxMeasuredSamples rows). Returns "" and fills `out` (its t and omega), or one line saying
/// what is wrong, naming the row (the file's 1-based line) and column: the scene reader puts
/// the key and the file before it.
std::string parse_measured_omega(std::string_view text, MeasuredOmega& out);

}  // namespace bookspin::scene
