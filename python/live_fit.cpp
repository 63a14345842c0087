// bookspin.prepare_recording and bookspin.live_fit: a class's live pooled fit (docs/python.md,
// "The live fit"; docs/phone-lab.md, "The live fit"): each recording prepared once
// (fit/prepared_recording.hpp), the set fitted warm from the last live fit (fit/live_fit.hpp).
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bindings.hpp"
#include "common/errors.hpp"
#include "fit/fit.hpp"

namespace bookspin::python {

namespace {

const char* kPrepareDoc = R"(prepare_recording(recording) -> bookspin.PreparedRecording

What a recording needs of its own for the class's live fit, done once: read as `bookspin fit`
reads it (a phyphox export, its folder, "Raw Data.csv" or zip, or a t,wx,wy,wz CSV: a str or
os.PathLike), its still rest and bias measured, its free flights found, and its own joint fit
(each flight's omega0 and drag rate, its bias correction, its body), the start its flights take
in every live fit. A recording with no flight is prepared with none.

Raises bookspin.Error with `bookspin fit`'s one line for a recording it cannot read;
KeyboardInterrupt on Ctrl-C. The GIL is released while it works.)";

const char* kLiveDoc = R"(live_fit(recordings, start=None) -> bookspin.LiveFit

The live estimate of the recordings' pooled body (docs/phone-lab.md, "The live fit"): every
flight of `recordings` (a list of bookspin.PreparedRecording, one or more, any order) fitted
with one body in one joint solve, warm-started from `start` (a bookspin.LiveFit of some of them:
its body, each recording's flights' omega0, drag rate and bias correction kept; a recording new
to it starts from its own fit), or with no start from the own body of the recording with the
most flights. No growing stages, no folds, no predictions, no trimmed flight ends: it is not
`bookspin fit`'s numbers (bookspin.fit of the same files is), only near them; its sigma is the
covariance's alone.

Returns a bookspin.LiveFit:
  body        {"I1_over_I3", "I2_over_I3", "I3_over_I3", "I1_sigma", "I2_sigma" (None where
              the covariance cannot be computed), "axis1_x" ... "axis3_z" (phone frame),
              "recordings", "tosses"}
  tosses      one dict per flight, the recordings in their canonical order (by name): recording,
              flight (1..n within it), toss (1..N in the set), t_start, t_end (s, its own time),
              omega0_x/y/z (rad/s), drag_rate (1/s), half_period_measured, half_period_fitted
              (s or None), residual_rms (rad/s)
Raises bookspin.Error for no recordings, one given twice, no flight in any, or a solve that
does not converge. The GIL is released while it fits.)";

/// A prepared recording as Python holds it: shared, never copied.
struct Prepared {
  std::shared_ptr<const fit::PreparedRecording> value;
};

/// A live fit as Python sees it, and the value the next one starts from.
struct Live {
  fit::LiveFit value;
  py::dict body;
  py::list tosses;
};

py::object optional_float(const std::optional<double>& v) {
  return v ? py::object(py::float_(*v)) : py::object(py::none());
}

Prepared prepare(const py::object& recording) {
  bool is_path = false;
  const std::string path = path_arg(recording, is_path, "recording");
  if (!is_path)
    throw InputError("recording: expected a path, got " +
                     std::string(py::str(py::type::handle_of(recording).attr("__name__"))));
  fit::FitSettings settings;
  settings.stop = python_stop();
  std::shared_ptr<fit::PreparedRecording> prepared;
  {
    py::gil_scoped_release release;
    prepared = std::make_shared<fit::PreparedRecording>(
        fit::prepare_recording(fit::read_recording(path), settings));
  }
  return Prepared{std::move(prepared)};
}

Live live(const py::sequence& recordings, const py::object& start) {
  std::vector<std::shared_ptr<const fit::PreparedRecording>> held;
  std::vector<const fit::PreparedRecording*> given;
  for (const py::handle item : recordings) {
    if (!py::isinstance<Prepared>(item))
      throw InputError("recordings: expected bookspin.PreparedRecording items, got " +
                       std::string(py::str(py::type::handle_of(item).attr("__name__"))));
    held.push_back(item.cast<const Prepared&>().value);
    given.push_back(held.back().get());
  }
  std::optional<fit::LiveFit> from;
  if (!start.is_none()) {
    if (!py::isinstance<Live>(start))
      throw InputError("start: expected a bookspin.LiveFit or None, got " +
                       std::string(py::str(py::type::handle_of(start).attr("__name__"))));
    from = start.cast<const Live&>().value;
  }
  fit::FitSettings settings;
  settings.stop = python_stop();
  Live out;
  {
    py::gil_scoped_release release;
    out.value = fit::live_fit(given, from ? &*from : nullptr, settings);
  }
  const fit::LiveFit& f = out.value;
  out.body["I1_over_I3"] = f.ratios[0];
  out.body["I2_over_I3"] = f.ratios[1];
  out.body["I3_over_I3"] = f.ratios[2];
  out.body["I1_sigma"] = f.ratio_sigma ? optional_float((*f.ratio_sigma)[0]) : py::none();
  out.body["I2_sigma"] = f.ratio_sigma ? optional_float((*f.ratio_sigma)[1]) : py::none();
  const char* xyz = "xyz";
  for (int a = 0; a < 3; ++a)
    for (int c = 0; c < 3; ++c)
      out.body[py::str("axis" + std::to_string(a + 1) + "_" + xyz[c])] = f.axes(c, a);
  out.body["recordings"] = f.recordings;
  out.body["tosses"] = f.tosses.size();
  for (const fit::LiveToss& t : f.tosses) {
    py::dict row;
    row["recording"] = t.recording;
    row["flight"] = t.flight;
    row["toss"] = t.toss;
    row["t_start"] = t.t_start;
    row["t_end"] = t.t_end;
    for (int c = 0; c < 3; ++c) row[py::str(std::string("omega0_") + xyz[c])] = t.omega0[c];
    row["drag_rate"] = t.drag_rate;
    row["half_period_measured"] = optional_float(t.half_period_measured);
    row["half_period_fitted"] = optional_float(t.half_period_fitted);
    row["residual_rms"] = t.residual_rms;
    out.tosses.append(row);
  }
  return out;
}

}  // namespace

void add_live_fit(py::module_& m) {
  py::class_<Prepared>(m, "PreparedRecording",
                       "A recording prepared once for the live fit (bookspin.prepare_recording).")
      .def_property_readonly(
          "name", [](const Prepared& p) { return p.value->name; }, "its file-safe stem")
      .def_property_readonly(
          "source", [](const Prepared& p) { return p.value->source; }, "the file read")
      .def_property_readonly(
          "flights", [](const Prepared& p) { return p.value->search.flights.size(); },
          "its free flights found")
      .def_property_readonly(
          "nbytes", [](const Prepared& p) { return fit::prepared_bytes(*p.value); },
          "the bytes it holds (its samples in flight and its values)")
      .def("__repr__", [](const Prepared& p) {
        return "<bookspin.PreparedRecording " + p.value->name + ": " +
               std::to_string(p.value->search.flights.size()) + " flight(s)>";
      });
  py::class_<Live>(m, "LiveFit", "A live pooled fit (bookspin.live_fit): body, tosses.")
      .def_readonly("body", &Live::body, "the body's ratios, sigma and axes: a dict")
      .def_readonly("tosses", &Live::tosses, "one dict per flight")
      .def("__repr__", [](const Live& l) {
        return "<bookspin.LiveFit of " + std::to_string(l.value.recordings) +
               " recording(s): " + std::to_string(l.value.tosses.size()) + " toss(es)>";
      });
  m.def("prepare_recording", &prepare, py::arg("recording"), kPrepareDoc);
  m.def("live_fit", &live, py::arg("recordings"), py::arg("start") = py::none(), kLiveDoc);
}

}  // namespace bookspin::python
