// embind bindings of the phone-toss lab's fit for the explorer page's "Phone-toss lab" panel
// (docs/explorer.md, docs/phone-lab.md): `bookspin fit` with the same code compiled unchanged:
// the recording's reader (src/fit/recording.cpp, the zip through Debian's minizip) and the fit's
// report (src/fit/report.cpp: the flights found, the fit by Ceres, built from Debian's source by
// web/build-wasm-deps.sh, its tables, each toss's chart data and scene values). This file only
// translates the report into JavaScript.
//
// The recording's bytes are written into the module's in-memory file system, in a folder of
// their own under the name the page was given, and read from there as the command line reads a
// file given by its name in the current folder: its messages name the file as the command
// line's do.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "common/csv_keyed.hpp"
#include "common/csv_writer.hpp"
#include "common/errors.hpp"
#include "common/file_name.hpp"
#include "common/number_text.hpp"
#include "common/stop.hpp"
#include "fit/fit.hpp"
#include "guarded.hpp"
#include "scene/limits.hpp"

namespace {

using bookspin::InputError;
using bookspin::web::guarded;
using emscripten::val;
namespace fit = bookspin::fit;

/// The folder the recordings are written into (the module's MEMFS), one slot per file; each
/// fit empties it.
constexpr const char* kFolder = "/recording";

/// The rows of a table's CSV text as the command line writes it (fit::FitReport), read back
/// (csv_keyed_rows) into objects keyed by its header's columns: an empty cell null, a number a
/// number, text as text.
std::vector<val> keyed_rows(const std::string& csv) {
  std::vector<val> rows;
  for (const auto& cells : bookspin::csv_keyed_rows(csv)) {
    val row = val::object();
    for (const auto& [column, value] : cells)
      row.set(column, std::visit(
                          [](const auto& v) -> val {
                            if constexpr (std::is_same_v<std::decay_t<decltype(v)>, std::monostate>)
                              return val::null();
                            else
                              return val(v);
                          },
                          value));
    rows.push_back(row);
  }
  return rows;
}

val array_of(const std::vector<val>& items) {
  val out = val::array();
  for (const val& item : items) out.call<void>("push", item);
  return out;
}

/// The toss's chart data: its own recording's name (of several pooled, the one it was thrown
/// in), t (s, that recording's own time), the measured ω (3×N, phone frame, bias
/// removed, flattened sample by sample) and the fitted ω at the same times (fit::TossChart).
val chart_data(const fit::TossChart& chart) {
  std::vector<double> measured, fitted;
  for (std::size_t i = 0; i < chart.t.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      measured.push_back(chart.measured[i][c]);
      fitted.push_back(chart.fitted[i][c]);
    }
  val out = val::object();
  out.set("recording", chart.recording);
  out.set("t", val::array(chart.t));
  out.set("measured", val::array(measured));
  out.set("fitted", val::array(fitted));
  return out;
}

/// The entries of `m` as a JavaScript array, column by column (a 3×N matrix flattened).
val flattened(const Eigen::Matrix3Xd& m) {
  return val::array(std::vector<double>(m.data(), m.data() + m.size()));
}

/// A toss's scene values (fit::TossScene) as the page's scene data, the keys `bookspin explore`
/// writes for the toss's scene file (scene::page_data) that the fitted motion sets; the rest
/// are the page's defaults, as a scene file's are the scene's.
val toss_scene_data(const fit::TossScene& scene) {
  val state = val::object();
  state.set("body", std::string("book"));
  state.set("model", std::string("exact"));
  if (scene.drag.active()) {
    state.set("drag", std::string(bookspin::physics::to_string(scene.drag.law)));
    state.set("dragRate", scene.drag.rate);
  }
  state.set("dt", scene.dt);
  state.set("axis", std::string("custom"));
  state.set("w", val::array(std::vector<double>(scene.omega0.data(), scene.omega0.data() + 3)));
  state.set("jiggle", 0.0);
  state.set("speed", scene.dt * scene.steps_per_frame * fit::kTossSceneFramesPerSecond);
  state.set("showL", true);
  // The measured ω in the scene's body frame and the direction of L where it is not zero, as
  // scene::page_data's measured data.
  std::vector<double> ut;
  for (const Eigen::Index i : scene.measured_L.samples)
    ut.push_back(scene.measured_t[static_cast<std::size_t>(i)]);
  val measured = val::object();
  measured.set("t", val::array(scene.measured_t));
  measured.set("w", flattened(scene.measured_omega));
  measured.set("ut", val::array(ut));
  measured.set("u", flattened(scene.measured_L.u));
  val book = val::object();
  book.set("size",
           val::array(std::vector<double>(scene.book.size.data(), scene.book.size.data() + 3)));
  book.set("mass", scene.book.mass);
  val out = val::object();
  out.set("name", scene.name);
  out.set("title", scene.title);
  out.set("description", scene.description);
  out.set("state", state);
  out.set("book", book);
  // The page's duration is the frames' (scene::page_data): those that cover it.
  const double frames =
      bookspin::scene::frames_covering(scene.duration, scene.dt, scene.steps_per_frame);
  out.set("duration", (frames - 1) * scene.dt * scene.steps_per_frame);
  out.set("measured", measured);
  return out;
}

/// The recording `bytes` (a phyphox zip, its Raw Data.csv, or a t,wx,wy,wz CSV), named
/// `file_name` (a file's name, or a folder's and a file's: "export/Raw Data.csv"), written into
/// the module's memory (slot `slot` of kFolder: several files kept apart) with its export's
/// `meta` files beside it (name, bytes: "time.csv", "device.csv" into the folder's meta/), and
/// read as `bookspin fit FILE` reads it. Throws InputError as the command line's reader does.
fit::GyroRecording read_given(const std::string& file_name, const std::string& bytes, int slot,
                              const std::vector<std::pair<std::string, std::string>>& meta = {}) {
  // The file's name, and its folder's where the page was given one ("export/Raw Data.csv"):
  // a Raw Data.csv's recording is named after its folder, as on the command line.
  const std::filesystem::path given(file_name);
  const std::filesystem::path name = given.filename();
  std::filesystem::path folder = given.parent_path().filename();
  if (name.empty() || name == "." || name == ".." || folder == "." || folder == "..")
    throw InputError("\"" + file_name + "\": not a file name");
  // A Raw Data.csv picked without its folder leaves no folder's name to go by: its recording
  // is "recording" ("recording-2", … for the others of a class), not the memory slot's number.
  if (folder.empty() && name == "Raw Data.csv")
    folder = slot == 0 ? "recording" : "recording-" + std::to_string(slot + 1);
  const std::filesystem::path path = folder / name;
  const std::filesystem::path here = std::filesystem::path(kFolder) / std::to_string(slot);
  std::filesystem::create_directories(here / folder);
  std::filesystem::current_path(here);
  // Into the module's memory (MEMFS): a failure there is the page's fault, not the file's.
  const auto put = [](const std::filesystem::path& to, const std::string& content) {
    std::ofstream file(to, std::ios::binary);
    file.write(content.data(), static_cast<std::streamsize>(content.size()));
    if (!file) throw std::runtime_error("cannot write " + to.string() + " into memory");
  };
  put(path, bytes);
  for (const auto& [meta_name, text] : meta) {
    if (meta_name != "time.csv" && meta_name != "device.csv") continue;  // read_recording's
    std::filesystem::create_directories(folder / "meta");
    put(folder / "meta" / meta_name, text);
  }
  return fit::read_recording(path);
}

/// `drag` (the lab's "air drag" menu) as the command line reads its --drag
/// (fit::parse_drag_option), its errors naming the menu.
bookspin::physics::DragLaw drag_arg(const std::string& drag) {
  return fit::parse_drag_option(drag, fit::fit_option_names(fit::Reader::page).drag);
}

/// `tosses` (the lab's "Flights by hand (s)" field, the command line's --tosses syntax) as the
/// command line reads its option (fit::parse_toss_ranges), its errors naming the field; none
/// for a blank field: the flights found.
std::vector<std::pair<double, double>> tosses_arg(const std::string& tosses) {
  return fit::parse_toss_ranges(tosses, fit::fit_option_names(fit::Reader::page).tosses);
}

/// The fit's progress told to `progress` (a JavaScript function, or undefined/null: none) as
/// the page's fit worker reports it (web/src/fit_worker.js): progress("read", name, index,
/// count) before each recording is read, then the fit's own stages as the command line's stop
/// poll is asked them (fit::fit_report: "fit flights" once, "fit" at each solver iteration, "fit
/// charts" before each toss's chart). Only told: the fit never stops at it, and its answer is
/// the same with or without it.
struct Progress {
  val progress;
  bool on() const { return !progress.isUndefined() && !progress.isNull(); }
  void read(const std::string& name, int index, int count) const {
    if (on()) progress(std::string("read"), name, index, count);
  }
  bookspin::StopPoll poll() const {
    if (!on()) return {};
    return [p = progress](std::string_view stage) {
      p(std::string(stage));
      return 0;
    };
  }
};

/// Empties kFolder (the folder in use cannot be removed: the root first).
void clear_memory() {
  std::filesystem::current_path("/");
  std::filesystem::remove_all(kFolder);
}

/// The fit of `recording` under `law`, of the flights `tosses` by hand (none: those found), as
/// the page's value: {recording, body (the -fit-body.csv
/// row keyed by its columns), tosses (the -fit.csv rows), summary (the lines the command prints
/// before "wrote …", its remedies in the page's terms), dropped (every stretch dropped, a line
/// each, as --verbose prints them), charts (per toss {t, measured, fitted}), scenes (per toss the
/// page's scene data; an empty array where the fitted moments make no body, as the command writes
/// no scene)}.
val report_value(const fit::GyroRecording& recording, bookspin::physics::DragLaw law,
                 const std::vector<std::pair<double, double>>& tosses, const Progress& progress) {
  fit::FitRequest request;
  request.tosses = tosses;  // by hand: refused for several recordings, as the command's
  request.settings.drag = law;
  request.reader = fit::Reader::page;  // its remedies in the page's terms, not the options'
  const fit::FitReport report = fit::fit_report(recording, request, progress.poll());
  std::vector<val> charts, scenes;
  for (const fit::TossReport& toss : report.tosses) {
    charts.push_back(chart_data(toss.chart));
    if (toss.scene) scenes.push_back(toss_scene_data(*toss.scene));
  }
  val summary = val::array(), dropped = val::array();
  for (const std::string& line : report.summary) summary.call<void>("push", line);
  for (const std::string& line : report.dropped) dropped.call<void>("push", line);
  val out = val::object();
  out.set("recording", report.recording);
  out.set("body", keyed_rows(report.body_csv).at(0));
  out.set("tosses", array_of(keyed_rows(report.toss_csv)));
  out.set("summary", summary);
  out.set("dropped", dropped);
  out.set("charts", array_of(charts));
  out.set("scenes", array_of(scenes));
  return out;
}

/// `bookspin fit FILE --drag DRAG [--tosses TOSSES]`: report_value of the recording `bytes`
/// named `file_name` (read_given), of the flights `tosses` by hand (tosses_arg; blank: those
/// found), or {error}; its progress told to `progress` (Progress).
val fit_recording(const std::string& file_name, const std::string& bytes, const std::string& drag,
                  const std::string& tosses, const val& progress) {
  return guarded([&] {
    const Progress told{progress};
    const bookspin::physics::DragLaw law = drag_arg(drag);
    const std::vector<std::pair<double, double>> ranges = tosses_arg(tosses);
    clear_memory();
    told.read(file_name, 0, 1);
    return report_value(fit::pool_recordings({read_given(file_name, bytes, 0)}), law, ranges, told);
  });
}

/// `bookspin fit FILE1 FILE2 … --drag DRAG [--tosses TOSSES]` (docs/phone-lab.md, "A class's
/// recordings"):
/// `files` an array of {name, bytes, meta} (as fit_recording's; meta, optional: an export's
/// [{name, bytes}] as read_given takes them); each read, those that cannot be read
/// refused and the others fitted as one body (fit::pool_recordings; alone, as fit_recording).
/// report_value plus fitted (the names fitted) and refused ([{file, error}: the command line's
/// one line]); {error} when none can be read or the fit fails, and for flights by hand with
/// two or more read (the command line's refusal: their times are one recording's). Its progress
/// told to `progress` (Progress).
val fit_recordings(const val& files, const std::string& drag, const std::string& tosses,
                   const val& progress) {
  return guarded([&] {
    const Progress told{progress};
    const bookspin::physics::DragLaw law = drag_arg(drag);
    const std::vector<std::pair<double, double>> ranges = tosses_arg(tosses);
    clear_memory();
    const int count = files["length"].as<int>();
    std::vector<fit::GyroRecording> read;
    // The names fitted and refused in their sorted order, as the pool is a set (fit::
    // pool_recordings): a folder dropped gives its files in the browser's order.
    std::vector<std::string> fitted_names;
    std::vector<std::pair<std::string, std::string>> refused_lines;
    std::string first_error;
    for (int i = 0; i < count; ++i) {
      const std::string name = files[i]["name"].as<std::string>();
      told.read(name, i, count);
      std::vector<std::pair<std::string, std::string>> meta;
      const val given = files[i]["meta"];
      if (!given.isUndefined() && !given.isNull())
        for (int m = 0; m < given["length"].as<int>(); ++m)
          meta.emplace_back(given[m]["name"].as<std::string>(),
                            given[m]["bytes"].as<std::string>());
      try {
        read.push_back(read_given(name, files[i]["bytes"].as<std::string>(), i, meta));
        fitted_names.push_back(name);
      } catch (const InputError& e) {
        refused_lines.emplace_back(name, e.what());
      }
    }
    std::sort(fitted_names.begin(), fitted_names.end());
    std::sort(refused_lines.begin(), refused_lines.end());
    if (!refused_lines.empty()) first_error = refused_lines.front().second;
    val fitted = val::array(), refused = val::array();
    for (const std::string& name : fitted_names) fitted.call<void>("push", name);
    for (const auto& [name, error] : refused_lines) {
      val line = val::object();
      line.set("file", name);
      line.set("error", error);
      refused.call<void>("push", line);
    }
    if (read.empty()) throw InputError(count ? first_error : "no recording given");
    val out = report_value(fit::pool_recordings(read), law, ranges, told);
    out.set("fitted", fitted);
    out.set("refused", refused);
    return out;
  });
}

/// Why `name` (UTF-8) cannot be a name under the project's one rule for names (a recording's, a
/// student's in a class: common/file_name.hpp), or "" where it can: the page checks a student's
/// name as the class's server does before it asks.
std::string name_problem(const std::string& name) { return bookspin::file_name_problem(name); }

}  // namespace

EMSCRIPTEN_BINDINGS(bookspin_fit) {
  emscripten::function("fitRecording", &fit_recording);
  emscripten::function("fitRecordings", &fit_recordings);
  emscripten::function("nameProblem", &name_problem);
}
