#pragma once
// "No rigid body": the one home of the moments no rigid body has and of each cut-off the fit's
// stages judge them by (docs/phone-lab.md, "The fit" and "Flags"). Every rigid body's principal
// moments obey the triangle inequality, I1 + I2 ≥ I3 (docs/physics.md §11: I1 + I2 − I3 =
// 2 ∫ z² dm ≥ 0; a flat body lies on it), and a body of finite width has I1 > 0 (a needle, a
// thin rod, tends to 0). Each stage asks with a margin of its own, for the reason given at it:
//
// | who asks | a needle: I1/I3 under | the triangle: I1 + I2 under | then |
// |---|---|---|---|
// | the restart (`suspect_body`) | kNeedle | I3 (no margin) | fitted again from rigid bodies |
// | a toss's flag (`toss_flags.hpp`) | kNeedle | kFlagTriangleShare I3 | the toss flagged |
// | the bridge (`flight_bridge.hpp`, `flights.cpp`) | kNeedle | (not asked) | not bridged |
// | far from rigid (`far_from_rigid`) | kFarNeedle | kFarTriangleShare I3 | no σ, no predictions |
#include <Eigen/Dense>
#include <cstdio>
#include <string>

namespace bookspin::fit {

/// I1/I3 below which a body is a needle (a rod ten times longer than wide has about 0.02; a
/// book, a phone, a racquet 0.1 or more). Where a fit ends at one, other starts are tried
/// (rigid_restart.hpp); a toss fitted at one is flagged; a flight whose Euler inertia is one is
/// no rigid body's flight and is not bridged (measured on the re-stamped lone flights of
/// tests/fit/lone_flight_test.cpp: the smallest moment 0.14 at least; the triangle inequality
/// is not asked there: that inertia, from a derivative the stamps spoil, puts a flat body's two
/// smaller moments up to 25 % under the largest).
inline constexpr double kNeedle = 0.1;

/// I2/I3 above which a fitted body lies at the edge where the fit's moment ratios meet (I2 = I3):
/// a fit from a poor start may end there, as at a needle (12-29-59 thinned to a browser's 55 Hz:
/// 0.45 : 0.999 : 1 with no σ, its cost 9 times the restart's 0.55 : 0.57 : 1), and whether it
/// does hangs on the solver's round-off, so the page's WebAssembly and the command line parted
/// there. A body with I2 = I3 (a cylinder) may be fitted so all the same: the other starts are
/// kept only where their cost is lower.
inline constexpr double kAxisymmetricEdge = 0.99;

/// The share of I3 the two smaller moments may sum to before a toss is flagged: 2 % under the
/// triangle inequality, for a flat body's, which lies on it (a bare phone's 0.22 + 0.80 of 1),
/// fitted within its noise.
inline constexpr double kFlagTriangleShare = 1.0 - 0.02;

/// Far past any rigid body a phone is tossed beside: I1/I3 under kFarNeedle (a rod fifteen times
/// longer than wide) or I1 + I2 under kFarTriangleShare I3 (5 % past the triangle inequality).
/// Where the restarts from rigid bodies still end there, the cost is flat and where the fit
/// stops (which needle) follows the solver's round-off: the page and the command line part, so
/// the body's σ and the predictions are withheld. A body at the edges (a racquet's 0.1 : 0.9 : 1,
/// suspect_body) is not this.
inline constexpr double kFarNeedle = 0.01;
inline constexpr double kFarTriangleShare = 0.95;

/// Whether moments `m` (sorted ascending, any scale) are a needle's: m1 under kNeedle m3.
inline bool needle(const Eigen::Vector3d& m) { return m[0] < kNeedle * m[2]; }

/// Whether moments `m` (sorted ascending) call for the restart from rigid bodies: past the
/// triangle inequality, a needle, or at the edge I2 = I3 (kAxisymmetricEdge).
inline bool suspect_moments(const Eigen::Vector3d& m) {
  return m[0] + m[1] < m[2] || needle(m) || m[1] > kAxisymmetricEdge * m[2];
}

/// Whether moments `m` (sorted ascending) flag a toss: a needle, or the two smaller under
/// kFlagTriangleShare of the largest.
inline bool flagged_moments(const Eigen::Vector3d& m) {
  return m[0] + m[1] < kFlagTriangleShare * m[2] || needle(m);
}

/// Whether moments `m` (sorted ascending) are far from any rigid body (kFarNeedle,
/// kFarTriangleShare).
inline bool far_from_rigid(const Eigen::Vector3d& m) {
  return m[0] < kFarNeedle * m[2] || m[0] + m[1] < kFarTriangleShare * m[2];
}

/// far_from_rigid() in words, made from its numbers: "I1/I3 under 0.01, or I1 + I2 under 0.95 I3".
inline std::string far_from_rigid_words() {
  char text[80];
  std::snprintf(text, sizeof text, "I1/I3 under %g, or I1 + I2 under %g I3", kFarNeedle,
                kFarTriangleShare);
  return text;
}

}  // namespace bookspin::fit
