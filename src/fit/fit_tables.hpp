#pragma once
// What the fit reports, as the command line writes it and the explorer's Phone-toss lab shows
// it (docs/outputs.md, "The fit"; docs/phone-lab.md): the per-toss table, the body's row and
// the summary lines. Text in memory only: no file is written here.
#include <string>
#include <vector>

#include "common/csv_writer.hpp"
#include "fit/toss_fit.hpp"

namespace bookspin::fit {

/// OUT/<recording>-fit.csv: one row per toss, columns toss, t_start, t_end (s), omega0_x/y/z
/// (rad/s, phone frame), the half periods (s) and the predicted one's σ (s), residual_rms (rad/s),
/// L_decay, drag_rate and its sigma (1/s), stable, poor_fit, flag.
CsvTable fit_toss_csv(const FitResult& fit);

/// OUT/<recording>-fit-body.csv: one row, the moment ratios I1/I3, I2/I3, 1 and their sigmas,
/// the principal axes' phone-frame components (axisN_x/y/z) and their sigmas (degrees), how
/// the moments were found, the toss count and the drag law; the bias removed (bias_x/y/z, rad/s,
/// phone frame: the rest's mean, or fitted from the flights where there is no rest) and its σ
/// per axis (bias_sigma_x/y/z: the rest's scatter, or the fitted bias's standard error; empty
/// where neither).
CsvTable fit_body_csv(const FitResult& fit);

/// Who reads the summary: the command line's user, or the explorer page's lab's, who has no
/// command-line options to give (its remedies are said in the page's terms), or the Python
/// module's (the command line's remedies; its errors name its own arguments, fit_options.hpp).
enum class Reader { command_line, page, python };

/// A toss's residual share (TossFit::residual_share) past which the summary warns first: a
/// quarter of |ω|, five times the flag's 5 % (docs/phone-lab.md, "Flags").
inline constexpr double kLargeResidualShare = 0.25;

/// What the fit says besides its CSVs: the result first (fit_result_lines: one table, measured
/// against predicted), then a warning for each toss whose residual is over kLargeResidualShare
/// of |ω| ("warning: toss 2's fit leaves 127 % of |ω| unexplained …"), the bias (one line a
/// recording), then the details: the flights kept, the
/// stretches dropped (one
/// line per reason with their count, a reason given once with its stretch's times:
/// fit_dropped_lines lists every one), the body's moments and notes
/// (one line each), for the command to print or the page to show. For the page, a note's
/// remedy "give --moments I1,I2,I3" is said in the page's terms (kMomentsRemedyPage).
std::vector<std::string> fit_summary(const FitResult& fit, Reader reader = Reader::command_line);

/// The result as one table, the summary's first lines (a header, then a row a toss, columns
/// aligned): toss, its recording, its flight (s, on its own recording's clock), T/2 measured,
/// T/2 predicted ± 2σ (its calibrated σ: "0.478 ± 0.10"; "(uncalibrated)" with no interval; "not
/// predicted"), and whether the measurement lies within 2σ ("yes", "no", "–" where either is
/// missing). docs/phone-lab.md, "Reading the result".
std::vector<std::string> fit_result_lines(const FitResult& fit);

/// Every stretch of motion the finder dropped, a line each ("dropped NAME A–B s: why", on its
/// own recording's clock): `bookspin fit --verbose` prints them, the page lists them apart.
std::vector<std::string> fit_dropped_lines(const FitResult& fit);

/// The page's words for the command line's "give --moments I1,I2,I3" (kGiveMoments).
inline constexpr const char* kMomentsRemedyPage =
    "fit it with a recording of the same body whose toss flips, dropped in together (or give "
    "the moments to the command line's bookspin fit)";

/// `value` with `digits` digits after the point ("0.170"): the summary's and the toss scenes'
/// words (fit_summary, toss_scene).
std::string fixed(double value, int digits);

}  // namespace bookspin::fit
