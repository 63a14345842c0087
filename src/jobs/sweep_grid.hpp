#pragma once
// The grid of a parameter sweep (`bookspin sweep --vary`, docs/physics.md §14): ranges of
// scene keys, their product, and the `--set` overrides that place a scene at one grid point.
#include <cstddef>
#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace bookspin::jobs {

/// One `--vary KEY=START:STOP:COUNT[:log]`: COUNT values from START to STOP inclusive,
/// evenly spaced, or evenly spaced in log(value) with `:log`. KEY is a scalar scene key
/// (`time.dt`) or one component of a vector key (`initial.angular_velocity[1]`, index 0–2).
struct VaryRange {
  std::string key;        ///< as written, e.g. "initial.angular_velocity[1]"
  std::string scene_key;  ///< the scene key, e.g. "initial.angular_velocity"
  int component = -1;     ///< 0–2 for a vector component, −1 for a scalar key
  double start = 0.0, stop = 0.0;
  int count = 1;
  bool log = false;

  /// The COUNT values: start + (stop − start)·i/(COUNT − 1) (integral where the step is), or the
  /// same in log space (exp of the linear formula on log start, log stop); the ends are START and
  /// STOP exactly. For an integer scene key (scene::kLimits) each value is rounded to the
  /// nearest whole number.
  std::vector<double> values() const;
  /// The range as written after "KEY=", with the numbers in %.17g.
  std::string spec() const;
};

inline constexpr int kMaxVaryCount = 1000000;            ///< values per range
inline constexpr std::size_t kMaxGridPoints = 10000000;  ///< points of the whole grid

/// Parses "KEY=START:STOP:COUNT[:log]". Throws InputError ("--vary TEXT: reason") on bad
/// syntax, COUNT outside 1 … kMaxVaryCount, a non-finite number, a log range that is not
/// positive, or a component index outside 0–2.
VaryRange parse_vary(const std::string& text);

/// The product of the ranges. Grid index order: the FIRST range varies slowest and the LAST
/// fastest (nested loops in the order the --vary options were given), so index
/// i = Σ_r i_r · Π_{s>r} count_s.
class SweepGrid {
 public:
  /// Throws InputError when there is no range, a key is varied twice (the same component),
  /// or the grid has more than kMaxGridPoints points.
  explicit SweepGrid(std::vector<VaryRange> ranges);
  std::size_t size() const { return size_; }
  const std::vector<VaryRange>& ranges() const { return ranges_; }
  /// The varied values at grid point `index` (one per range, in range order).
  std::vector<double> point(std::size_t index) const;

 private:
  std::vector<VaryRange> ranges_;
  std::vector<std::vector<double>> values_;
  std::size_t size_ = 1;
};

/// The `--set` overrides that put `base` (the scene parsed with the user's own overrides)
/// at grid point `index`: "KEY=VALUE" for a scalar key, and for vector keys the whole vector
/// "KEY=[x,y,z]" from base's value with the varied components replaced. Values in %.17g
/// (an integral value reads as a TOML integer, so integer keys such as time.frames work).
/// Throws InputError naming a component key whose scene key is not a vector key
/// (book.size, initial.angular_velocity, render.camera_direction).
std::vector<std::string> point_overrides(const scene::Scene& base, const SweepGrid& grid,
                                         std::size_t index);

/// "%.17g" of `value` (NumberStyle::digits17 of common/number_text.hpp): 17 significant digits,
/// which read back to the same double. Throws InternalError for a value that is not finite.
std::string full_precision(double value);

}  // namespace bookspin::jobs
