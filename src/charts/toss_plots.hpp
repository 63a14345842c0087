#pragma once
// The phone-toss lab's chart (docs/phone-lab.md, "Reading the result"): one toss's measured ω
// as dots beside the fitted exact motion as lines, its flips marked.
#include "common/rgba_image.hpp"
#include "fit/fit.hpp"

namespace bookspin::charts {

/// Toss `toss` of `fit` (0-based) on a white width×height image: the measured ω's three
/// phone-frame components (rad/s, bias removed) as dots against the recording's time (s), the
/// fitted exact ω as lines in the same colours, and each flip of the fitted motion (a sign
/// change of ω about the intermediate axis) as a grey dashed vertical line.
RgbaImage toss_image(const fit::GyroRecording& recording, const fit::FitResult& fit, int toss,
                     int width, int height);

}  // namespace bookspin::charts
