#pragma once
// Several recordings of one body as one (docs/phone-lab.md, "A class's recordings"): a class
// whose students each toss the same phone once and export, fitted with one body.
#include <vector>

#include "fit/recording.hpp"

namespace bookspin::fit {

/// `recordings` (one or more, of one body) as one recording, the form the finder and the fit
/// take (a recording alone is a pool of one): each one's still rest found and its bias measured
/// there (fit/rest.hpp), its samples kept as measured and placed 1 s after the previous
/// recording's last, with a pause between them so that no flight spans two recordings; `parts`
/// says where each one went and holds its bias. Its flights are then found (find_flights) and
/// fitted (fit_recording): every toss with one body, each keeping its own drag rate and each
/// recording its own bias correction from its own flights; with two or more, the tables name
/// each toss's recording and give its own times (fit_tables.hpp). A pool is a set: the
/// recordings are laid out in their canonical order (by name, then by their samples), whatever
/// order they are given in, so that any order gives the same tosses, numbers and names to the
/// last digit (docs/phone-lab.md, "A class's recordings"). One recording keeps its name and
/// times; several are named after the first by name, "<first>-and-<N−1>-more". Two recordings
/// whose names are alike (files made file-safe alike: "anna b.csv", "anna-b.csv") are told apart:
/// the later in the canonical order takes the first free "-2", "-3", … in every table, chart and
/// file name. Throws InputError
/// for none, or one given twice: the same source, the same file however spelled
/// (GyroRecording::file), or the same samples (an export beside its own zip).
GyroRecording pool_recordings(const std::vector<GyroRecording>& recordings);

/// Throws std::logic_error for a recording not pooled, whose parts do not cover its samples: the
/// finder and the fit take each sample's bias from its part.
void check_pooled(const GyroRecording& recording);

/// The part of `parts` (GyroRecording::parts, one or more) holding pooled time `t` (s): the last
/// to start before it (the first for a time before every part). Throws std::out_of_range for no
/// parts (a recording not pooled).
const RecordingPart& part_at(const std::vector<RecordingPart>& parts, double t);

/// The index of part_at(parts, t) in `parts`.
std::size_t part_index(const std::vector<RecordingPart>& parts, double t);

}  // namespace bookspin::fit
