#pragma once
// The motion file the conformance kit judges (`bookspin flipcheck judge`, docs/flipcheck.md,
// "The motion file"): a CSV written by any engine, read into analysis::MotionSample rows. The
// parser (motion_csv.cpp) is pure, text in and rows out, and goes into the explorer page's
// WebAssembly (web/build-wasm.sh); reading the file is motion_file.cpp's.
#include <array>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/judgement.hpp"

namespace bookspin::jobs {

/// Which columns a motion file gave its ω in.
enum class OmegaFrame { body, world };

struct MotionFile {
  std::vector<analysis::MotionSample> rows;  ///< step 0 first, then every `stride` steps
  long long stride = 1;                      ///< steps of dt between rows
  OmegaFrame omega_frame = OmegaFrame::body;
};

/// Parses a motion CSV's `text` (named `file` in messages) for a scenario of step `dt` (time
/// units) and `steps` steps. A header row naming `t`, the orientation `qw,qx,qy,qz` (body →
/// world, either sign; bookspin's `q_w,q_x,q_y,q_z` too) and ω either in the body frame
/// `wx,wy,wz` (bookspin's `omega_x,omega_y,omega_z` too) or in the world frame
/// `wx_world,wy_world,wz_world` (body frame preferred when both are there; turned into the
/// body frame by R(q)ᵀ); other columns ignored; lines starting with `#` and empty lines
/// skipped; CRLF read as LF. Each row's t must be a whole number of steps of dt (to 1e-6 of a
/// step), the first 0, the next ones one stride apart, none outside 0 … `steps`. Throws InputError
/// "FILE:LINE: COLUMN: reason" (the line of the file; the column where there is one) for a
/// missing column, a missing or extra cell, a cell that is not a finite number, q = 0 (all four
/// components; any other norm is read, 1e300 and 1e-300 alike: q is divided by its largest
/// component first when that is beyond 1e±100), an ω component beyond ±1e100 (its energy would
/// overflow), a misplaced t, a quoted cell over a line end that cannot be a cell of text (in
/// the header, in a column read, or holding a whole row: "a quote opens a cell on this row (…)
/// and closes it on line N: a quote left open?"), and for a file without rows. A UTF-8 byte-order
/// mark before the header is read past.
MotionFile parse_motion_csv(std::string_view text, const std::string& file, double dt,
                            long long steps);

/// A motion given as numbers rather than a file (the Python module's `flipcheck.judge`,
/// docs/python.md): rows[i] = t, qw, qx, qy, qz, then ω x, y, z in `frame`, checked and turned
/// as parse_motion_csv() checks and turns a file's rows (the same rules, the same numbers). A
/// bad row throws InputError "WHAT: ARRAY[i]: reason" (ARRAY t, q, omega_world or omega_body;
/// i from 0): a value that is not finite, a misplaced t, q = 0, an ω component beyond ±1e100;
/// and "WHAT: no rows (t is empty)".
MotionFile motion_from_rows(const std::vector<std::array<double, 8>>& rows, OmegaFrame frame,
                            const std::string& what, double dt, long long steps);

/// parse_motion_csv() of the file at `path`, read whole (motion_file.cpp); InputError when it
/// cannot be read.
MotionFile read_motion_csv(const std::filesystem::path& path, double dt, long long steps);

}  // namespace bookspin::jobs
