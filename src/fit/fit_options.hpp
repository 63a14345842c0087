#pragma once
// The fit's options as every door reads them (docs/phone-lab.md, "The flights by hand"): the
// command line's --tosses, --drag and --moments, the Python module's tosses=, drag= and
// moments=, the explorer lab's "Flights by hand (s)" field and "air drag" menu. One reader and
// one judge per option, so that a value one door takes every door takes, a value one door
// refuses every door refuses with the same cause, and each error line names the door's own
// argument (fit_option_names).
#include <Eigen/Dense>
#include <string>
#include <utility>
#include <vector>

#include "physics/drag.hpp"

namespace bookspin::fit {

enum class Reader;  // fit_tables.hpp: whose terms (the command line, the page, Python)

/// What each door calls the fit's options in its error lines: the command line "--tosses",
/// "--drag", "--moments"; Python "tosses", "drag", "moments" (its keyword arguments); the page
/// "flights by hand", "air drag" (its field and menu; it takes no moments).
struct FitOptionNames {
  const char* tosses;
  const char* drag;
  const char* moments;
};
FitOptionNames fit_option_names(Reader reader);

/// A time of a toss's range as error lines print it: three decimals ("2.930"), and past 1e6 s
/// the shortest text that reads back ("1e+308"), never a number hundreds of digits long.
std::string toss_time_text(double t);

/// The flights by hand as text, "START:END[,START:END…]" (s; spaces around a number allowed,
/// "1.82:2.71, 2.88:3.22"): the ranges in the order given (check_toss_ranges'd), for
/// hand_flights, which judges them against the recording (a reversed range too); none for a
/// blank text. Throws InputError naming `option` for a range that is not two numbers
/// ("--tosses: \"2\" is not START:END", "--tosses: \"a\" is not a number"), with a hint where
/// a decimal comma split a number ("2,93:3,58": "… (a decimal comma? write 2.93:3.58)"), and
/// for an end that is not finite (check_toss_ranges). The one reader of this syntax: the
/// command line, the explorer's lab and Python's tosses= given as a str.
std::vector<std::pair<double, double>> parse_toss_ranges(const std::string& text,
                                                         const std::string& option = "--tosses");

/// The one judge of ranges given as numbers, whichever door gave them (parse_toss_ranges' text,
/// Python's pairs): throws InputError "OPTION: \"nan\" is not a finite time (s)" for an end that
/// is NaN or infinite (the end spelled as toss_time_text's shortest form, "inf", "-inf",
/// "nan"). Each range is judged against the recording by hand_flights (reversed, too few
/// samples, a pause, overlapping, given twice), which calls this first.
void check_toss_ranges(const std::vector<std::pair<double, double>>& ranges,
                       const std::string& option);

/// The air drag's law from its name, "none", "linear" or "quadratic" (physics::parse_drag_law);
/// throws InputError "OPTION: \"x\" is not none, linear or quadratic".
physics::DragLaw parse_drag_option(const std::string& text, const std::string& option);

/// The principal moments as text "I1,I2,I3" (the command line's --moments): three numbers,
/// check_moments'd. Throws InputError naming `option`: "expected I1,I2,I3", "\"a\" is not a
/// number".
Eigen::Vector3d parse_moments(const std::string& text, const std::string& option);

/// The one judge of moments given as numbers (parse_moments' text, Python's (3,) array):
/// throws InputError "OPTION: \"-1\" is not a positive finite number" for one that is not,
/// and "OPTION: 1 + 1 < 3: no rigid body has these principal moments …" where the two smaller
/// sum to less than the largest (the triangle inequality, docs/physics.md §11).
void check_moments(const Eigen::Vector3d& moments, const std::string& option);

}  // namespace bookspin::fit
