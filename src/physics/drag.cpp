#include "physics/drag.hpp"

#include <cmath>

namespace bookspin::physics {

double drag_decay(const Drag& drag, double t) {
  if (!drag.active()) return 1.0;
  const double r = drag.rate;
  return drag.law == DragLaw::linear ? std::exp(-r * t) : 1.0 / (1.0 + r * t);
}

// x = r t small: the series, so that s → t and its derivative stay exact as r → 0.
double stretched_time(const Drag& drag, double t) {
  if (!drag.active()) return t;
  const double x = drag.rate * t;
  if (drag.law == DragLaw::linear)
    return std::abs(x) < 1e-8 ? t * (1.0 - 0.5 * x) : -std::expm1(-x) / drag.rate;
  return std::abs(x) < 1e-8 ? t * (1.0 - 0.5 * x) : std::log1p(x) / drag.rate;
}

double drag_decay_rate_derivative(const Drag& drag, double t) {
  if (drag.law == DragLaw::none) return 0.0;
  const double x = drag.rate * t;
  if (drag.law == DragLaw::linear) return -t * std::exp(-x);  // ∂/∂r e^{−rt}
  return -t / ((1.0 + x) * (1.0 + x));                        // ∂/∂r 1/(1 + rt)
}

double stretched_time_rate_derivative(const Drag& drag, double t) {
  if (drag.law == DragLaw::none) return 0.0;
  const double r = drag.rate, x = r * t;
  // Both laws: ∂s/∂r = −t²/2 + O(r t³). Below |x| = 1e-3 the series to x³ (relative error
  // ~x⁴ < 1e-12); above, the closed form, which loses ~2/|x| < 2e3 ulps to cancellation.
  if (std::abs(x) < 1e-3) {
    if (drag.law == DragLaw::linear)
      return t * t * (-0.5 + x * (1.0 / 3.0 + x * (-0.125 + x / 30.0)));
    return t * t * (-0.5 + x * (2.0 / 3.0 + x * (-0.75 + x * 0.8)));
  }
  if (drag.law == DragLaw::linear)  // s = (1 − e^{−x})/r
    return (t * std::exp(-x) + std::expm1(-x) / r) / r;
  return (t / (1.0 + x) - std::log1p(x) / r) / r;  // s = ln(1 + x)/r
}

double drag_step_factor(const Drag& drag, double L_ratio, double h) {
  if (!drag.active()) return 1.0;
  if (drag.law == DragLaw::linear) return std::exp(-drag.rate * h);
  return 1.0 / (1.0 + drag.rate * L_ratio * h);  // d|L|/dt = −(r/|L0|)|L|²
}

bool drag_defined_until(const Drag& drag, double t) {
  return drag.law != DragLaw::quadratic || 1.0 + drag.rate * t > 0.0;
}

std::string_view to_string(DragLaw law) {
  switch (law) {
    case DragLaw::linear:
      return "linear";
    case DragLaw::quadratic:
      return "quadratic";
    default:
      return "none";
  }
}

bool parse_drag_law(std::string_view text, DragLaw& out) {
  if (text == "none")
    out = DragLaw::none;
  else if (text == "linear")
    out = DragLaw::linear;
  else if (text == "quadratic")
    out = DragLaw::quadratic;
  else
    return false;
  return true;
}

}  // namespace bookspin::physics
