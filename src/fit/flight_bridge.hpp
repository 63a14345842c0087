#pragma once
// The finder's bridge (docs/phone-lab.md, "Stamps off their samples"): a short stretch whose
// derivative the stamps spoil, between two stretches that keep Euler's equations, joined to them
// where ω keeps the two quantities a torque-free body keeps, |I ω| and ω·I ω (docs/physics.md §8):
// quantities of ω alone, which no time stamp enters and which a hand's torque changes at once.
#include <Eigen/Core>
#include <vector>

namespace bookspin::fit {

/// Samples each side of the derivative's quadratic (omega_rate), at least: one stamp off its
/// sample spoils the derivative of the samples within this many of it.
inline constexpr int kHalfWindow = 2;
/// The share of |I ω| and of ω·I ω by which ω may stray across a bridge: a bare phone's flight
/// re-stamped ±80 % of its step needed 2.6 % at most, and 95 in 100 of its bridges 4.4 % with
/// gyroscope gain and cross-axis errors of 3 %; the hands of the development recordings, nearest,
/// 12 % (the catch of 12-13-01 re-timed by a browser at 53 Hz: 79 % within 31 ms).
inline constexpr double kConserved = 0.08;
/// A bridged stretch is at most what one stamp off its sample spoils (the samples whose
/// derivative window holds it), or any stretch whose neighbours are at most kBridgeTime (s) apart.
inline constexpr int kBridgeSamples = 2 * kHalfWindow + 1;
inline constexpr double kBridgeTime = 0.05;

/// Whether omega[from + 1 … to] keep |I ω| and ω·I ω within kConserved of omega[from]'s
/// (I: 3×3, phone frame, any scale; omega: rad/s, phone frame).
bool conserved(const Eigen::Matrix3d& I, const std::vector<Eigen::Vector3d>& omega, int from,
               int to);

/// Marks in `mask` (sample i at mask[i - offset]), within samples [first, last], each stretch of
/// unmarked samples between two marked ones, of at most kBridgeSamples samples or with its
/// neighbours at most kBridgeTime apart (t: s), each of its samples `allowed[i]`, over which ω
/// keeps |I ω| and ω·I ω (`conserved`) from the marked sample before it through the marked
/// samples after it within kHalfWindow of its first (a catch's first sample may still look free;
/// the next ones, which the same derivative window reaches, are the catch's). Each sample marked
/// so is also marked in `bridged[i]` (its derivative not to be trusted). Nothing is marked where
/// I is not positive definite. `bridged` and `allowed` are indexed as omega and t.
void bridge_conserved(std::vector<char>& mask, int offset, int first, int last,
                      std::vector<char>& bridged, const Eigen::Matrix3d& I,
                      const std::vector<Eigen::Vector3d>& omega, const std::vector<double>& t,
                      const std::vector<char>& allowed);

}  // namespace bookspin::fit
