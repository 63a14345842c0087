#pragma once
// Isotropic air drag on a spinning body (docs/physics.md §21): a torque −c·L (linear law) or
// −(r/|L0|)·|L|·L (quadratic law) along the angular momentum itself, so that L keeps its
// direction and only its size decays. Both laws are told by one rate: the initial fractional
// loss of |L| per time unit, −(d|L|/dt)/|L| at t = 0.
#include <string_view>

namespace bookspin::physics {

enum class DragLaw {
  none,       ///< torque-free
  linear,     ///< τ = −c·L: |L(t)| = |L0|·e^{−ct}
  quadratic,  ///< τ = −k·|L|·L with k = r/|L0|: |L(t)| = |L0|/(1 + r t)
};

/// A drag law and its rate r (1 per time unit; for the linear law r = c, for the quadratic law
/// r = k·|L0|). r = 0 or DragLaw::none is the torque-free motion. A negative r is a gain (a fit
/// may find one within its error of zero); the quadratic law then holds only while 1 + r t > 0.
struct Drag {
  DragLaw law = DragLaw::none;
  double rate = 0.0;
  bool active() const { return law != DragLaw::none && rate != 0.0; }
};

/// g(t) = |L(t)|/|L0| under `drag` (1 exactly without drag). docs/physics.md §21.
double drag_decay(const Drag& drag, double t);
/// The stretched time s(t) = ∫₀ᵗ g(t') dt' in which the damped motion is the free one
/// (docs/physics.md §21): (1 − e^{−rt})/r (linear), ln(1 + rt)/r (quadratic), t exactly
/// without drag. Time units.
double stretched_time(const Drag& drag, double t);
/// ∂g/∂r and ∂s/∂r at t (the fit's derivatives; docs/physics.md §21), accurate as r → 0.
double drag_decay_rate_derivative(const Drag& drag, double t);
double stretched_time_rate_derivative(const Drag& drag, double t);
/// The factor |L(t+h)|/|L(t)| of the drag's own flow (no rotation) over a step h from a state
/// whose |L| is `L_ratio`·|L0| (quadratic law) — the exact damping sub-step of the rigid models'
/// splitting (docs/physics.md §21).
double drag_step_factor(const Drag& drag, double L_ratio, double h);
/// True when the law holds over [0, t] (1 + r t > 0 for the quadratic law; always otherwise).
bool drag_defined_until(const Drag& drag, double t);

std::string_view to_string(DragLaw law);
/// Parses "none" | "linear" | "quadratic"; false if unknown.
bool parse_drag_law(std::string_view text, DragLaw& out);

}  // namespace bookspin::physics
