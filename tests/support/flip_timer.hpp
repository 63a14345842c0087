#pragma once
// The tests' one flip timer: the times at which a sampled signal (cos(intermediate axis, L),
// or ω about that axis) changes sign, each placed by linear interpolation between the two
// samples around it. Written apart from analysis::FlipDetector, so that tests of that code
// have an independent reference (docs/physics.md §14).
#include <cstddef>
#include <vector>

namespace bookspin::test {

class FlipTimer {
 public:
  /// Feeds the sample `value` at time `t` (increasing). A change is counted when the sign
  /// (value > 0) differs from the previous sample's.
  void sample(double t, double value) {
    if (has_previous_ && (value > 0.0) != (previous_value_ > 0.0) && value != previous_value_)
      flips_.push_back(previous_t_ +
                       (t - previous_t_) * previous_value_ / (previous_value_ - value));
    previous_t_ = t;
    previous_value_ = value;
    has_previous_ = true;
  }
  const std::vector<double>& flips() const { return flips_; }  ///< times, ascending
  std::size_t count() const { return flips_.size(); }
  /// The first flip's time, or `none` before any.
  double first(double none = -1.0) const { return flips_.empty() ? none : flips_.front(); }

 private:
  bool has_previous_ = false;
  double previous_t_ = 0.0, previous_value_ = 0.0;
  std::vector<double> flips_;
};

}  // namespace bookspin::test
