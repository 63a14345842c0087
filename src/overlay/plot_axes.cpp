#include "overlay/plot_axes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

namespace bookspin::overlay {

double Axis::map(double v, double a, double b) const {
  const double f = log ? (std::log10(v) - lo) / (hi - lo) : (v - lo) / (hi - lo);
  return a + f * (b - a);
}

bool usable(double v, bool log) { return std::isfinite(v) && (!log || v > 0.0); }

namespace {

/// The data range of the x or y values; a span below `min_span` (linear axes) is widened
/// around its middle, a degenerate one to ±0.5.
Axis fit_axis(const std::vector<Series>& series, bool use_x, bool log, double min_span = 0.0) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const auto& s : series) {
    for (double v : use_x ? s.x : s.y) {
      if (!usable(v, log)) continue;
      lo = std::min(lo, log ? std::log10(v) : v);
      hi = std::max(hi, log ? std::log10(v) : v);
    }
  }
  if (!std::isfinite(lo)) lo = 0, hi = 1;
  if (!log && hi - lo < min_span) {
    const double mid = 0.5 * (lo + hi);
    lo = mid - 0.5 * min_span, hi = mid + 0.5 * min_span;
    return {lo, hi, false};
  }
  // A (nearly) constant series: widen it by ±0.5, or by a millionth of its size where ±0.5
  // would be lost in rounding (values of 10¹⁶ and more).
  const double size = std::max(std::abs(lo), std::abs(hi));
  if (hi - lo < 1e-12 * std::max(1.0, size)) {
    const double half = std::max(0.5, 1e-6 * size);
    lo -= half, hi += half;
  }
  if (log) {
    lo = std::floor(lo), hi = std::ceil(hi);
  } else if (!use_x) {
    const double pad = 0.06 * (hi - lo);
    lo -= pad, hi += pad;
  }
  return {lo, hi, log};
}

}  // namespace

bool fixed_y_range(const PlotSpec& spec) {
  return spec.y_range && spec.y_range->second > spec.y_range->first &&
         (!spec.log_y || spec.y_range->first > 0.0);
}

Axis fit_x(const PlotSpec& spec) {
  if (spec.x_range && !spec.log_x && spec.x_range->second > spec.x_range->first) {
    return {spec.x_range->first, spec.x_range->second, false};
  }
  return fit_axis(spec.series, true, spec.log_x);
}

Axis fit_y(const PlotSpec& spec) {
  if (fixed_y_range(spec)) {
    const auto [lo, hi] = *spec.y_range;
    return spec.log_y ? Axis{std::log10(lo), std::log10(hi), true} : Axis{lo, hi, false};
  }
  return fit_axis(spec.series, false, spec.log_y, spec.min_y_span);
}

namespace {

double nice_step(double span, double intervals) {
  const double raw = span / intervals, magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * magnitude >= raw) return m * magnitude;
  return 10.0 * magnitude;
}

/// The ticks of a linear axis `step` apart within it.
std::vector<double> linear_ticks(const Axis& a, double step) {
  std::vector<double> out;
  if (!(step > 0.0) || !std::isfinite(step)) return out;
  // Counted, not summed: the k-th tick is k × step, and at most kMaxTicks of them, so that
  // a step lost in rounding next to huge values cannot loop forever.
  constexpr int kMaxTicks = 50;
  const double first = std::ceil(a.lo / step - 1e-9);  // an end on a tick keeps it
  for (int i = 0; i < kMaxTicks; ++i) {
    const double v = (first + i) * step;
    if (!(v <= a.hi + 1e-9 * step) || (!out.empty() && !(v > out.back()))) break;
    out.push_back(std::abs(v) < 1e-12 * step ? 0.0 : v);
  }
  return out;
}

}  // namespace

std::vector<double> ticks(const Axis& a) {
  std::vector<double> out;
  if (a.log) {
    const int stride = std::max(1, static_cast<int>((a.hi - a.lo) / 8.0) + 1);
    for (int e = static_cast<int>(a.lo); e <= static_cast<int>(a.hi); e += stride)
      out.push_back(std::pow(10.0, e));
    return out;
  }
  // At least two ticks, so that the axis has a scale: a short axis of few intervals may
  // round its step up past the span's half (±2.4 in two intervals: a step of 5).
  for (double intervals = a.intervals;; intervals += 1.0) {
    out = linear_ticks(a, nice_step(a.hi - a.lo, intervals));
    if (out.size() >= 2 || intervals >= 10.0) return out;
  }
}

std::string tick_label(double v, bool log) {
  char text[32];
  if (log) {
    std::snprintf(text, sizeof text, "1e%d", static_cast<int>(std::lround(std::log10(v))));
  } else {
    std::snprintf(text, sizeof text, "%g", v);
  }
  return text;
}

/// The labels of every tick a y axis can have drawn but those of `fitted` (its ticks as
/// fitted): ticks() steps by nice_step(span, n) for n from its intervals (2 … 5 as drawn) up to
/// 11 at most, so by each step m·10^e (m = 1, 2, 5, 10) from nice_step(span, 11) to
/// nice_step(span, 2), computed as nice_step computes it.
std::vector<std::string> other_y_tick_labels(const Axis& a,
                                             const std::vector<std::string>& fitted) {
  std::vector<std::string> out;
  const double span = a.hi - a.lo;
  if (a.log || !(span > 0) || !std::isfinite(span)) return out;
  const double least = nice_step(span, 11.0), most = nice_step(span, 2.0);
  const int e0 = static_cast<int>(std::floor(std::log10(span / 11.0))) - 1;
  const int e1 = static_cast<int>(std::floor(std::log10(span / 2.0))) + 1;
  for (int e = e0; e <= e1; ++e) {
    const double magnitude = std::pow(10.0, static_cast<double>(e));
    for (double m : {1.0, 2.0, 5.0, 10.0}) {
      const double step = m * magnitude;
      if (step < least || step > most) continue;
      for (double t : linear_ticks(a, step)) {
        const std::string label = tick_label(t, false);
        if (std::find(fitted.begin(), fitted.end(), label) == fitted.end() &&
            std::find(out.begin(), out.end(), label) == out.end())
          out.push_back(label);
      }
    }
  }
  return out;
}

Axis drawn_y(Axis ay, const Area& area) {
  ay.intervals = std::clamp((area.y1 - area.y0) / (2.4 * area.font), 2.0, 5.0);
  return ay;
}

}  // namespace bookspin::overlay
