#pragma once
// The body's notes on what it rests on (docs/phone-lab.md, "Flags"): the lines BodyEstimate::notes
// gives where the tosses cannot pin the moment ratios (stable, flagged or too little flight), or
// where the moments given have no intermediate axis.
#include "fit/toss_fit.hpp"

namespace bookspin::fit {

/// s: a prediction whose held-out body rests on less flight time than this (a bounce, not a
/// throw) is said to be poorly founded.
inline constexpr double kShortBasis = 0.6;

/// The body's notes on what it rests on: stable tosses, flipping tosses that fit cleanly and
/// their flight time (under kShortBasis s pins no body, docs/phone-lab.md, "Flags"), one toss
/// with nothing to predict from, two equal moments given. Reads `result`'s tosses; appends to
/// body.notes and clears body.moments_determined where the tosses cannot pin the ratios.
void body_notes(const FitResult& result, const FitSettings& settings, BodyEstimate& body);

}  // namespace bookspin::fit
