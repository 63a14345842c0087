#include "fit/recording.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <optional>
#include <regex>
#include <utility>

#include "common/errors.hpp"
#include "common/file_name.hpp"
#include "common/number_text.hpp"
#include "common/text_file.hpp"
#include "fit/median.hpp"
#include "fit/recording_text.hpp"
#include "fit/recording_zip.hpp"

namespace bookspin::fit {

using recording_text::kMinSamples;
using recording_text::lower;

std::string time_unit_cause(const std::vector<double>& t, double stated) {
  if (t.size() < 2) return {};
  std::vector<double> steps;
  steps.reserve(t.size() - 1);
  for (std::size_t i = 1; i < t.size(); ++i) steps.push_back(t[i] - t[i - 1]);
  const double step = median_of(std::move(steps));
  if (!(step > kMaxSampleStep)) return {};
  // The unit that puts the median step as written within a gyroscope's 0.1–100 ms.
  const std::array<std::pair<const char*, double>, 3> units{
      {{"ms", 1e-3}, {"µs", 1e-6}, {"ns", 1e-9}}};
  const double written = step / stated;
  const char* likely = nullptr;
  for (const auto& [unit, seconds] : units)
    if (written * seconds >= 1e-4 && written * seconds <= 0.1) {
      likely = unit;
      break;
    }
  std::string read_as;  // what the header stated, where it named a unit
  for (const auto& [unit, seconds] : units)
    if (stated == seconds) read_as = std::string(", read in ") + unit + " as the header names them";
  char text[400];
  std::snprintf(text, sizeof text,
                "the samples lie %.4g s apart (the median step%s), where a phone's gyroscope "
                "samples every 1–40 ms: are the times %s%s? Give them in seconds, or name %s "
                "unit in the header (\"t (%s)\")",
                step, read_as.c_str(), likely ? "in " : "in another unit", likely ? likely : "",
                read_as.empty() ? "the" : "their", likely ? likely : "ms");
  return text;
}

GyroRecording samples_recording(const std::string& name, std::vector<double> t,
                                std::vector<Eigen::Vector3d> omega) {
  const std::string where = name + ": ";
  if (t.size() != omega.size())
    throw InputError(where + std::to_string(t.size()) + " times and " +
                     std::to_string(omega.size()) + " samples of omega");
  for (std::size_t i = 0; i < t.size(); ++i) {
    const std::string index = std::string(1, '[').append(std::to_string(i)).append(1, ']');
    // An infinity is named as the command line names one typed (docs/phone-lab.md, "Numbers"),
    // whether typed or the caller's own reading of a number past the largest double.
    const auto not_finite = [&](const char* what, bool infinite) {
      return InputError(where + what + index + ": " + (infinite ? "inf" : "nan") +
                        " is not a finite number");
    };
    if (!std::isfinite(t[i])) throw not_finite("t", std::isinf(t[i]));
    if (!omega[i].allFinite()) throw not_finite("omega", omega[i].array().isInf().any());
    if (i > 0 && !(t[i] > t[i - 1]))
      throw InputError(where + "t" + index + ": time does not increase");
  }
  if (static_cast<int>(t.size()) < kMinSamples)
    throw InputError(where + "a gyroscope recording of " + std::to_string(t.size()) +
                     " samples; at least " + std::to_string(kMinSamples) + " are needed");
  if (const std::string unit = time_unit_cause(t); !unit.empty())
    throw InputError(where + "t: " + unit);
  GyroRecording recording;
  recording.name = file_name_of(name);
  recording.source = name;
  recording.t = std::move(t);
  recording.omega = std::move(omega);
  return recording;
}

namespace {

/// Whether `file_name` is phyphox's name for one sensor's CSV export: the sensor, then the
/// date and time it was recorded ("Gyroscope rotation rate 2022-05-03 12-10-56.csv").
bool single_sensor_export(const std::string& file_name) {
  static const std::regex pattern(R"(.+ \d{4}-\d{2}-\d{2} \d{2}-\d{2}-\d{2}\.[cC][sS][vV])");
  return std::regex_match(file_name, pattern);
}

/// Whether `path`'s folder holds no other CSV.
bool only_csv_of_its_folder(const std::filesystem::path& path) {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::path folder = fs::absolute(path).parent_path();
  for (const fs::directory_entry& entry : fs::directory_iterator(folder, error))
    if (entry.is_regular_file(error) && lower(entry.path().extension().string()) == ".csv" &&
        entry.path().filename() != path.filename())
      return false;
  return !error;
}

}  // namespace

GyroRecording read_recording(const std::filesystem::path& path) {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (!fs::exists(status))
    throw InputError(path.string() + ": " +
                     (error.value() == ELOOP ? kLinkLoop : "no such file or folder"));
  if (fs::is_directory(status)) {
    const fs::path raw = path / "Raw Data.csv";
    if (fs::exists(raw)) return read_recording(raw);
    // phyphox's single-CSV exports are kept one to a folder ("Gyroscope rotation rate
    // 2022-05-03 12-07-27.csv"): a folder holding exactly one CSV is that CSV, named after the
    // folder as an export is.
    std::vector<fs::path> csvs;
    for (const fs::directory_entry& entry : fs::directory_iterator(path, error))
      if (entry.is_regular_file(error) && lower(entry.path().extension().string()) == ".csv")
        csvs.push_back(entry.path());
    std::sort(csvs.begin(), csvs.end());
    if (csvs.empty())
      throw InputError(path.string() +
                       ": not a gyroscope recording: the folder holds no \"Raw Data.csv\" and no "
                       "other CSV");
    if (csvs.size() > 1) {
      std::string names;
      for (const fs::path& csv : csvs)
        names += (names.empty() ? "\"" : ", \"") + csv.filename().string() + "\"";
      throw InputError(path.string() + ": holds " + std::to_string(csvs.size()) +
                       " CSVs and no \"Raw Data.csv\" (" + names + "): which one? Give that file");
    }
    GyroRecording recording = read_recording(csvs.front());
    fs::path folder = fs::absolute(path).lexically_normal();
    if (folder.filename().empty()) folder = folder.parent_path();  // "anna/" as "anna"
    recording.name = file_name_of(folder.filename().string());
    return recording;
  }
  const std::string name = path.stem().string();
  if (lower(path.extension().string()) == ".zip") {
    const std::optional<std::string> raw = zip_entry(path, "Raw Data.csv");
    if (!raw)
      throw InputError(path.string() +
                       ": not a gyroscope recording: the zip holds no \"Raw Data.csv\"");
    GyroRecording recording = parse_gyro_csv(*raw, path.string() + ":Raw Data.csv", name);
    if (const std::optional<std::string> time = zip_entry(path, "meta/time.csv"))
      recording.pauses = parse_time_csv(*time, path.string() + ":meta/time.csv");
    if (const std::optional<std::string> device = zip_entry(path, "meta/device.csv"))
      recording.gyroscope_range = parse_device_csv(*device, path.string() + ":meta/device.csv");
    recording.file = fs::weakly_canonical(path, error);
    return recording;
  }
  const std::string text = read_text_file(path, "the recording");
  // A phyphox export is named after its folder; so is a single sensor's export given with its
  // folder ("12-10-56/Gyroscope rotation rate … .csv", a dropped folder's file) that holds no
  // other CSV, as that folder given is named, so that the file, its folder or a dropped folder
  // name one recording alike and a pooled set sorts alike; another CSV, or one given by its
  // bare name, after itself.
  const bool in_export = path.filename() == "Raw Data.csv";
  const fs::path folder = fs::absolute(path).parent_path();
  const bool named_by_folder =
      in_export || (single_sensor_export(path.filename().string()) && path.has_parent_path() &&
                    only_csv_of_its_folder(path) && !folder.filename().empty());
  GyroRecording recording =
      parse_gyro_csv(text, path.string(), named_by_folder ? folder.filename().string() : name);
  // Named in messages as the recording was given ("anna/meta/time.csv").
  const fs::path time_csv = folder / "meta" / "time.csv";
  const fs::path meta_named = path.parent_path() / "meta";
  if (in_export && fs::exists(time_csv))
    recording.pauses =
        parse_time_csv(read_text_file(time_csv, "the pauses"), (meta_named / "time.csv").string());
  const fs::path device_csv = folder / "meta" / "device.csv";
  if (in_export && fs::exists(device_csv))
    recording.gyroscope_range = parse_device_csv(read_text_file(device_csv, "the device"),
                                                 (meta_named / "device.csv").string());
  recording.file = fs::weakly_canonical(path, error);
  return recording;
}

}  // namespace bookspin::fit
