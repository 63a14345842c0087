#pragma once
// A flight's ends cut by the fitted motion itself (docs/phone-lab.md, "How the flights are
// found"): the finder's ends come from a finite-difference torque residual before any fit, and
// may run 30–100 ms into the throw or the catch; the exact motion fitted to the flight shows
// them as samples it cannot follow.
#include <optional>

#include "fit/flights.hpp"
#include "fit/recording.hpp"
#include "fit/toss_fit.hpp"

namespace bookspin::fit {

/// s: the most trimmed from either end of a flight.
inline constexpr double kMaxTrim = 0.15;
/// An end sample is the throw's or the catch's while its residual |ω measured − ω fitted|
/// exceeds this many times the flight's median residual (its own noise).
inline constexpr double kTrimFactor = 3.0;

/// `fit`'s flights of `recording` with each end trimmed while the fitted motion's residual
/// there stays above kTrimFactor × the flight's median residual (at most kMaxTrim s an end,
/// and never below FinderSettings::min_flight or 10 samples); the stretches dropped as they
/// were. nullopt where no end moves. Pure; never throws.
std::optional<FlightSearch> trimmed_flights(const GyroRecording& recording, const FitResult& fit,
                                            const FinderSettings& settings = {});

}  // namespace bookspin::fit
