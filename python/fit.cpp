// bookspin.fit: a gyroscope recording's tosses fitted as `bookspin fit` fits them
// (docs/phone-lab.md), presented from the fit stage's report (fit::fit_report): the body CSV's
// row, the fit CSV's rows and the summary lines, with each toss's chart data as arrays.
#include "fit/fit.hpp"

#include <cmath>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "bindings.hpp"
#include "common/csv_keyed.hpp"
#include "common/csv_writer.hpp"
#include "common/errors.hpp"
#include "common/number_text.hpp"
#include "physics/drag.hpp"

namespace bookspin::python {

namespace {

const char* kDoc = R"(fit(recording, drag="linear", tosses=None, moments=None) -> bookspin.Fit

Fits a gyroscope recording's free flights with the exact torque-free motion, as
`bookspin fit RECORDING [--drag D] [--tosses A:B,...] [--moments I1,I2,I3]` does
(docs/phone-lab.md; the motion docs/physics.md §8, air drag §21), and returns what the command
writes, without writing a file.

Arguments:
  recording  a phyphox export (its folder, its "Raw Data.csv" or a zip of it) or a CSV with
             the header t,wx,wy,wz (a str or os.PathLike); or a pair (t, omega) of arrays,
             t (N,) in s, strictly increasing, and omega (N, 3) in rad/s, the phone frame
             (x right of the screen, y up it, z out of it), as measured (bias included);
             or a list of paths: recordings of one body fitted as one, as
             `bookspin fit REC1 REC2 ...` does (docs/phone-lab.md, "A class's recordings")
  drag       the air drag's law fitted with each toss: "none", "linear" or "quadratic"
  tosses     the flights by hand, a list of (t_start, t_end) pairs in s, an (N, 2) array, or
             the command line's text "START:END,START:END" (--tosses, read by the same
             reader); None, [] or "": found
  moments    (3,) principal moments, any scale and order, each > 0 (--moments): fixed, not
             fitted

Returns a bookspin.Fit:
  body     the -fit-body.csv row as a dict keyed by its columns (I1_over_I3, I2_over_I3, ...,
           axis1_x ... in the phone frame, moments, tosses, drag, bias_x ...); for recordings
           fitted as one, the first recording's row
  bodies   every -fit-body.csv row: one, or for recordings fitted as one a row per recording
           (the body repeated, with its recording's name and own bias)
  tosses   the -fit.csv rows, one dict per toss (toss, t_start, t_end, omega0_x ...,
           half_period_measured ..., residual_rms, drag_rate, flag ...)
  summary  the lines the command prints before "wrote ..." (bias, flights, body, notes)
  charts   per toss a dict: recording, its own recording's name (of several pooled, the one it
           was thrown in), and float64 arrays: t (N,) s, that recording's own time; measured (N, 3)
           rad/s, phone frame, bias removed; fitted (N, 3) the fitted omega at t; curve_t (M,)
           every millisecond of the flight and curve (M, 3) the fitted omega there; flips (K,)
           s, the fitted motion's flips
  recording  the recording's name
A cell the CSV leaves empty is None, a number a float (the very number the CSV's text reads
back as), and a word a str.

Raises bookspin.Error with the command line's one line for a bad recording, a bad toss, no
flight found or a bad argument; KeyboardInterrupt on Ctrl-C (checked at every iteration of the
solver). The GIL is released while it fits.)";

/// One fit as Python sees it.
struct Fit {
  std::string recording;
  py::dict body;
  py::list bodies, tosses, summary, charts;
};

/// The rows of a table's CSV text as the command line writes it (fit::FitReport), read back
/// (csv_keyed_rows) into dicts keyed by its header's columns: an empty cell None, a number a
/// float, text a str.
py::list keyed_rows(const std::string& csv) {
  py::list rows;
  for (const auto& cells : csv_keyed_rows(csv)) {
    py::dict row;
    for (const auto& [column, value] : cells)
      row[py::str(column)] = std::visit(
          [](const auto& v) -> py::object {
            using V = std::decay_t<decltype(v)>;
            if constexpr (std::is_same_v<V, std::monostate>)
              return py::none();
            else if constexpr (std::is_same_v<V, double>)
              return py::float_(v);
            else
              return py::str(v);
          },
          value);
    rows.append(row);
  }
  return rows;
}

py::array_t<double> values_array(const std::vector<double>& values) {
  py::array_t<double> out = new_array(values.size());
  std::copy(values.begin(), values.end(), out.mutable_data());
  return out;
}

py::array_t<double> vectors_array(const std::vector<Eigen::Vector3d>& vectors) {
  py::array_t<double> out = new_array(vectors.size(), 3);
  double* data = out.mutable_data();
  for (std::size_t i = 0; i < vectors.size(); ++i)
    for (int c = 0; c < 3; ++c) data[3 * i + static_cast<std::size_t>(c)] = vectors[i][c];
  return out;
}

py::dict chart_arrays(const fit::TossChart& chart) {
  py::dict out;
  out["recording"] = chart.recording;
  out["t"] = values_array(chart.t);
  out["measured"] = vectors_array(chart.measured);
  out["fitted"] = vectors_array(chart.fitted);
  out["curve_t"] = values_array(chart.curve_t);
  out["curve"] = vectors_array(chart.curve);
  out["flips"] = values_array(chart.flips);
  return out;
}

/// The recording argument: a path read as the command line reads it, or a (t, omega) pair.
fit::GyroRecording recording_arg(const py::object& recording) {
  bool is_path = false;
  const std::string path = path_arg(recording, is_path, "recording");
  if (is_path) return fit::pool_recordings({fit::read_recording(path)});
  if (!py::isinstance<py::tuple>(recording) && !py::isinstance<py::list>(recording))
    throw InputError("recording: expected a path or a (t, omega) pair of arrays, got " +
                     std::string(py::str(py::type::handle_of(recording).attr("__name__"))));
  const py::sequence pair = recording;
  // A list of paths: recordings of one body fitted as one (`bookspin fit REC1 REC2 ...`).
  std::vector<fit::GyroRecording> several;
  for (const py::handle item : pair) {
    bool item_is_path = false;
    const std::string item_path =
        path_arg(py::reinterpret_borrow<py::object>(item), item_is_path, "recording");
    if (!item_is_path) break;
    several.push_back(fit::read_recording(item_path));
  }
  if (!several.empty() && several.size() == pair.size()) return fit::pool_recordings(several);
  if (pair.size() != 2)
    throw InputError("recording: expected a (t, omega) pair, got " + std::to_string(pair.size()) +
                     " items");
  const std::vector<double> t = vector_arg(pair[0], "t", -1);
  const std::vector<double> w = matrix_arg(pair[1], "omega", -1, 3);
  same_rows({{"t", t.size()}, {"omega", w.size() / 3}});
  std::vector<Eigen::Vector3d> omega;
  for (std::size_t i = 0; i < t.size(); ++i)
    omega.emplace_back(w[3 * i], w[3 * i + 1], w[3 * i + 2]);
  return fit::pool_recordings({fit::samples_recording("recording", t, std::move(omega))});
}

/// The fit's arguments read and judged as every door reads its options (fit/fit_options.hpp),
/// each error naming the argument: tosses as the command line's --tosses text or as (N, 2)
/// numbers, drag by name, moments as (3,) numbers.
fit::FitRequest request_arg(const std::string& drag, const py::object& tosses,
                            const py::object& moments) {
  fit::FitRequest request;
  request.reader = fit::Reader::python;  // hand_flights' errors name tosses=, not --tosses
  const fit::FitOptionNames names = fit::fit_option_names(request.reader);
  request.settings.drag = fit::parse_drag_option(drag, names.drag);
  if (py::isinstance<py::str>(tosses)) {
    request.tosses = fit::parse_toss_ranges(unicode_arg(tosses, names.tosses), names.tosses);
  } else if (!tosses.is_none() && py::len(tosses) > 0) {
    const std::vector<double> ends = matrix_arg(tosses, names.tosses, -1, 2);
    for (std::size_t i = 0; i + 1 < ends.size(); i += 2)
      request.tosses.emplace_back(ends[i], ends[i + 1]);
    fit::check_toss_ranges(request.tosses, names.tosses);
  }
  if (!moments.is_none()) {
    const Eigen::Vector3d m = vector3_arg(moments, names.moments);
    fit::check_moments(m, names.moments);
    request.settings.moments = m;
  }
  return request;
}

Fit fit(const py::object& recording_input, const std::string& drag, const py::object& tosses,
        const py::object& moments) {
  const fit::FitRequest request = request_arg(drag, tosses, moments);
  const fit::GyroRecording recording = recording_arg(recording_input);
  std::optional<fit::FitReport> report;
  {
    const StopPoll stop = python_stop();
    py::gil_scoped_release release;
    report = fit::fit_report(recording, request, stop);
  }
  Fit out;
  out.recording = report->recording;
  out.bodies = keyed_rows(report->body_csv);
  out.body = out.bodies[0].cast<py::dict>();
  out.tosses = keyed_rows(report->toss_csv);
  for (const std::string& line : report->summary) out.summary.append(line);
  for (const fit::TossReport& toss : report->tosses) out.charts.append(chart_arrays(toss.chart));
  return out;
}

const char* kReadDoc = R"(read_gyro_csv(text, file="recording.csv") -> dict

Reads a gyroscope recording's CSV text (a phyphox "Raw Data.csv" or a plain t,wx,wy,wz CSV, as
the lab's Download writes it) with the reader `bookspin fit` reads a file with, without a file
and without fitting: what a server checks before it holds a recording.

Returns {"t": (N,) float64 s, "omega": (N, 3) float64 rad/s, phone frame, as measured}.
Raises bookspin.Error with the reader's one line naming `file`, the row and the column (a text
or NaN cell, too few cells, time not increasing, fewer than 10 samples, not a recording).)";

py::dict read_gyro_csv(const std::string& text, const std::string& file) {
  std::optional<fit::GyroRecording> recording;
  {
    py::gil_scoped_release release;
    recording = fit::parse_gyro_csv(text, file, file);
  }
  py::dict out;
  out["t"] = values_array(recording->t);
  out["omega"] = vectors_array(recording->omega);
  return out;
}

}  // namespace

void add_fit(py::module_& m) {
  py::class_<Fit>(m, "Fit",
                  "A recording's fit (bookspin.fit): body, tosses, summary, charts, recording.")
      .def_readonly("recording", &Fit::recording, "the recording's name (its file-safe stem)")
      .def_readonly("body", &Fit::body,
                    "the -fit-body.csv row (the first, for recordings fitted as one): dict keyed "
                    "by its columns")
      .def_readonly("bodies", &Fit::bodies, "every -fit-body.csv row: a dict per recording")
      .def_readonly("tosses", &Fit::tosses, "the -fit.csv rows: one dict per toss")
      .def_readonly("summary", &Fit::summary, "the lines the command prints, as str")
      .def_readonly("charts", &Fit::charts,
                    "per toss: t, measured, fitted, curve_t, curve, flips (float64 arrays)")
      .def("__repr__", [](const Fit& f) {
        return "<bookspin.Fit of " + f.recording + ": " + std::to_string(py::len(f.tosses)) +
               " toss(es)>";
      });
  m.def("fit", &fit, py::arg("recording"), py::arg("drag") = "linear",
        py::arg("tosses") = py::none(), py::arg("moments") = py::none(), kDoc);
  m.def("read_gyro_csv", &read_gyro_csv, py::arg("text"), py::arg("file") = "recording.csv",
        kReadDoc);
  // What a recording must hold for the finder to keep a flight (fit::FinderSettings, the
  // defaults every door uses; docs/phone-lab.md, "How the flights are found"): what a server
  // tells a student to record again by.
  const fit::FinderSettings finder;
  py::dict requirements;
  requirements["flight_omega"] = finder.flight_omega;
  requirements["min_flight"] = finder.min_flight;
  requirements["rest_omega"] = finder.rest_omega;
  m.attr("flight_requirements") = requirements;
}

}  // namespace bookspin::python
