#pragma once
// A flight's ends cut by the fitted motion itself (docs/phone-lab.md, "How the flights are
// found"): the finder's ends come from a finite-difference torque residual before any fit, and
// may run 30–100 ms into the throw or the catch; the exact motion fitted to the flight shows
// them as samples it cannot follow.
#include <functional>
#include <optional>

#include "fit/flights.hpp"
#include "fit/recording.hpp"
#include "fit/toss_fit.hpp"

namespace bookspin::fit {

/// s: the most trimmed from either end of a found flight, over every pass together.
inline constexpr double kMaxTrim = 0.15;
/// An end sample is the throw's or the catch's while both its residual |ω measured − ω fitted|
/// and the torque its samples need (step_torque, the larger of its two steps) exceed this many
/// times the flight's median of each (its own noise): a residual without a torque is the fit
/// drifting off near the separatrix, and the phone still free there.
inline constexpr double kTrimFactor = 3.0;
/// The most trim-and-refit passes (trim_to_free_flight): each refit leaves the motion's own
/// residual lower, and so shows more of a landing that the previous fit spread its error over.
inline constexpr int kMaxTrimPasses = 8;

/// `fit`'s flights of `recording` with each end trimmed while its sample is the throw's or the
/// catch's (kTrimFactor, with `fit`'s body and motion): no end further than kMaxTrim
/// s inside the same flight of `found` (the flights as the finder gave them, of which `fit`'s
/// are trimmed copies, one for one), and never below FinderSettings::min_flight or 10 samples;
/// the stretches dropped as they were. nullopt where no end moves. Pure; never throws.
std::optional<FlightSearch> trimmed_flights(const GyroRecording& recording, const FitResult& fit,
                                            const FlightSearch& found,
                                            const FinderSettings& settings = {});

/// `fit` (of `recording`'s flights as found) trimmed and refitted by `refit` until no end moves
/// (trimmed_flights against the found flights; at most kMaxTrimPasses refits): the flights'
/// ends a fixed point of the rule, each end's residual within kTrimFactor × its flight's median
/// under its own fit, or at kMaxTrim. What `refit` throws passes through.
FitResult trim_to_free_flight(const GyroRecording& recording, FitResult fit,
                              const std::function<FitResult(const FlightSearch&)>& refit,
                              const FinderSettings& settings = {});

}  // namespace bookspin::fit
