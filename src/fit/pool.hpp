#pragma once
// Several recordings of one body as one (docs/phone-lab.md, "A class's recordings"): a class
// whose students each toss the same phone once and export, fitted with one body.
#include <vector>

#include "fit/recording.hpp"

namespace bookspin::fit {

/// `recordings` (two or more, of one body) as one recording: each one's bias measured on its own
/// rest (find_flights) and removed from its samples, its samples placed 1 s after the previous
/// recording's last, with a pause between them so that no flight spans two recordings; `parts`
/// says where each one went. Its flights are then found (find_flights) and fitted (fit_recording)
/// as any recording's: every toss with one body, each keeping its own drag rate and each
/// recording its own bias correction from its own flights (fit_recording); the tables name
/// each toss's recording and give its own times (fit_tables.hpp). Named after the first
/// recording, "<first>-and-<N−1>-more". Throws InputError for fewer than two recordings or one
/// given twice (the same source).
GyroRecording pool_recordings(const std::vector<GyroRecording>& recordings);

/// The part of `parts` (GyroRecording::parts) holding pooled time `t` (s): the last to start
/// before it; nullptr for no parts (a recording not pooled).
const RecordingPart* part_at(const std::vector<RecordingPart>& parts, double t);

}  // namespace bookspin::fit
