// embind bindings of the phone-toss lab's fit for the explorer page's "Phone-toss lab" panel
// (docs/explorer.md, docs/phone-lab.md): `bookspin fit` with the same code compiled unchanged:
// the recording's reader (src/fit/recording.cpp, the zip through Debian's minizip), the flight
// finder, the fit (Ceres, built from Debian's source by web/build-wasm-deps.sh), its tables
// (src/fit/fit_tables.cpp) and each toss as a scene (src/products/fit_scene.cpp). This file only
// translates between them and JavaScript.
//
// The recording's bytes are written into the module's in-memory file system, in a folder of
// their own under the name the page was given, and read from there as the command line reads a
// file given by its name in the current folder: its messages name the file as the command
// line's do.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "common/csv_writer.hpp"
#include "common/errors.hpp"
#include "common/number_text.hpp"
#include "fit/fit.hpp"
#include "guarded.hpp"
#include "products/fit_scene.hpp"

namespace {

using bookspin::InputError;
using bookspin::web::guarded;
using emscripten::val;
namespace fit = bookspin::fit;
namespace products = bookspin::products;

/// The folder the recordings are written into (the module's MEMFS); each fit empties it.
constexpr const char* kFolder = "/recording";

/// One CSV cell as the page's value: an empty cell null, a number a number, text as text.
val cell_value(const std::string& cell) {
  if (cell.empty()) return val::null();
  if (const std::optional<double> value = bookspin::read_number(cell)) return val(*value);
  return val(cell);
}

/// The rows of `table` as the command line writes them (the one CSV writer), read back into
/// objects keyed by the table's columns.
std::vector<val> keyed_rows(const bookspin::CsvTable& table, const char* what) {
  const std::string csv = bookspin::csv_text(table, what);
  std::vector<val> rows;
  std::size_t at = csv.find('\n') + 1;
  while (at < csv.size()) {
    const std::size_t end = csv.find('\n', at);
    const std::vector<std::string> cells = bookspin::csv_cells(csv.substr(at, end - at));
    val row = val::object();
    for (std::size_t c = 0; c < table.columns.size() && c < cells.size(); ++c)
      row.set(table.columns[c], cell_value(cells[c]));
    rows.push_back(row);
    at = end + 1;
  }
  return rows;
}

val array_of(const std::vector<val>& items) {
  val out = val::array();
  for (const val& item : items) out.call<void>("push", item);
  return out;
}

/// The toss's chart data: t (s, the recording's time), the measured ω (3×N, phone frame, bias
/// removed, flattened sample by sample) and the fitted ω at the same times.
val chart_data(const fit::GyroRecording& recording, const fit::FitResult& result, int toss) {
  std::vector<double> t;
  std::vector<Eigen::Vector3d> omega;
  fit::measured_omega(recording, result, toss, t, omega);
  std::vector<double> measured, fitted;
  for (std::size_t i = 0; i < t.size(); ++i) {
    const Eigen::Vector3d f = fit::fitted_omega(result, toss, t[i]);
    for (int c = 0; c < 3; ++c) {
      measured.push_back(omega[i][c]);
      fitted.push_back(f[c]);
    }
  }
  val out = val::object();
  out.set("t", val::array(t));
  out.set("measured", val::array(measured));
  out.set("fitted", val::array(fitted));
  return out;
}

/// Toss `toss` as the page's scene data, the keys `bookspin explore` writes for the toss's scene
/// file (scene::page_data) that the fitted motion sets; the rest are the page's
/// defaults, as a scene file's are the scene's.
val toss_scene_data(const fit::GyroRecording& recording, const fit::FitResult& result, int toss) {
  const products::TossScene scene = products::toss_scene(result, toss, recording.name);
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
  state.set("speed", scene.dt * scene.steps_per_frame * products::kTossSceneFramesPerSecond);
  state.set("showL", true);
  // The measured ω in the scene's body frame (products::toss_measured_csv) and, where L = I·ω
  // is not zero, the direction of L (as scene::page_data's measured data).
  const bookspin::CsvTable table = products::toss_measured_csv(recording, result, toss);
  const Eigen::Vector3d moments = scene.book.principal_moments();
  std::vector<double> t, w, ut, u;
  // Each cell's number is the one its shortest text in the CSV reads back as (round trip).
  const auto number = [](const bookspin::CsvCell& cell) {
    return std::get<bookspin::CsvNumber>(cell).value.value();
  };
  for (const std::vector<bookspin::CsvCell>& row : table.rows) {
    const double time = number(row[0]);
    const Eigen::Vector3d omega(number(row[1]), number(row[2]), number(row[3]));
    t.push_back(time);
    w.insert(w.end(), omega.data(), omega.data() + 3);
    const Eigen::Vector3d L = moments.cwiseProduct(omega);
    const double norm = L.norm();
    if (!(norm > 0.0) || !std::isfinite(norm)) continue;
    ut.push_back(time);
    for (int c = 0; c < 3; ++c) u.push_back(L[c] / norm);
  }
  val measured = val::object();
  measured.set("t", val::array(t));
  measured.set("w", val::array(w));
  measured.set("ut", val::array(ut));
  measured.set("u", val::array(u));
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
/// `file_name` (a file's name, or a folder's and a file's: "export/Raw Data.csv"), fitted as
/// `bookspin fit FILE --drag DRAG` does: {body: the -fit-body.csv row keyed by its columns, tosses:
/// the -fit.csv rows, summary: the lines the command prints before "wrote …", charts: per toss {t,
/// measured, fitted}, scenes: per toss the page's scene data (an empty array where the fitted
/// moments make no body, as the command writes no scene)}, or {error}.
val fit_recording(const std::string& file_name, const std::string& bytes, const std::string& drag) {
  return guarded([&] {
    // The file's name, and its folder's where the page was given one ("export/Raw Data.csv"):
    // a Raw Data.csv's recording is named after its folder, as on the command line.
    const std::filesystem::path given(file_name);
    const std::filesystem::path name = given.filename();
    const std::filesystem::path folder = given.parent_path().filename();
    if (name.empty() || name == "." || name == ".." || folder == "." || folder == "..")
      throw InputError("\"" + file_name + "\": not a file name");
    const std::filesystem::path path = folder / name;
    bookspin::physics::DragLaw law = bookspin::physics::DragLaw::linear;
    if (!bookspin::physics::parse_drag_law(drag, law))
      throw InputError("--drag: \"" + drag + "\" is not none, linear or quadratic");
    std::filesystem::current_path("/");  // the folder in use cannot be removed
    std::filesystem::remove_all(kFolder);
    std::filesystem::create_directories(std::filesystem::path(kFolder) / folder);
    std::filesystem::current_path(kFolder);
    {
      std::ofstream file(path, std::ios::binary);
      file.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
      if (!file) throw std::runtime_error("cannot write the recording into memory");
    }
    const fit::GyroRecording recording = fit::read_recording(path);
    const fit::FlightSearch search = fit::find_flights(recording);
    fit::FitSettings settings;
    settings.drag = law;
    const fit::FitResult result = fit::fit_recording(recording, search, settings);
    std::vector<val> charts, scenes;
    const bool has_scenes = products::toss_book(result.body).has_value();
    for (int k = 0; k < static_cast<int>(result.tosses.size()); ++k) {
      charts.push_back(chart_data(recording, result, k));
      if (has_scenes) scenes.push_back(toss_scene_data(recording, result, k));
    }
    val summary = val::array();
    for (const std::string& line : fit::fit_summary(result)) summary.call<void>("push", line);
    val out = val::object();
    out.set("recording", recording.name);
    out.set("body", keyed_rows(fit::fit_body_csv(result), "fit body CSV").at(0));
    out.set("tosses", array_of(keyed_rows(fit::fit_toss_csv(result), "fit CSV")));
    out.set("summary", summary);
    out.set("charts", array_of(charts));
    out.set("scenes", array_of(scenes));
    return out;
  });
}

}  // namespace

EMSCRIPTEN_BINDINGS(bookspin_fit) { emscripten::function("fitRecording", &fit_recording); }
