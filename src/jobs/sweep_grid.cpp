#include "jobs/sweep_grid.hpp"

#include <cmath>
#include <cstdlib>
#include <map>

#include "common/errors.hpp"
#include "common/number_text.hpp"
#include "scene/limits.hpp"

namespace bookspin::jobs {

namespace {

[[noreturn]] void bad_vary(const std::string& text, const std::string& reason) {
  throw InputError("--vary " + text + ": " + reason);
}

/// Splits on ':' keeping empty fields.
std::vector<std::string> split_colons(const std::string& text) {
  std::vector<std::string> fields;
  std::size_t start = 0;
  for (std::size_t colon; (colon = text.find(':', start)) != std::string::npos; start = colon + 1)
    fields.push_back(text.substr(start, colon - start));
  fields.push_back(text.substr(start));
  return fields;
}

/// A whole-field number (strtod), or false.
bool read_number(const std::string& field, double& out) {
  if (field.empty()) return false;
  char* end = nullptr;
  out = std::strtod(field.c_str(), &end);
  return end == field.c_str() + field.size() && std::isfinite(out);
}

bool is_key_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
         c == '-' || c == '.';
}

/// The vector scene keys a `[i]` component may name, and their value in a parsed scene.
const Eigen::Vector3d* vector_value(const scene::Scene& scene, const std::string& key) {
  if (key == "book.size") return &scene.body.cage.size;
  if (key == "initial.angular_velocity") return &scene.initial.omega0_body;
  if (key == "render.camera_direction") return &scene.render.camera_direction;
  return nullptr;
}

}  // namespace

std::string full_precision(double value) {
  return finite_text(value, "sweep grid value", NumberStyle::digits17);
}

std::vector<double> VaryRange::values() const {
  std::vector<double> v(static_cast<std::size_t>(count));
  if (count == 1) {
    v[0] = start;
    return v;
  }
  const double a = log ? std::log(start) : start;
  const double b = log ? std::log(stop) : stop;
  for (int i = 0; i < count; ++i) {
    // (b − a)·i first: an integer range with a whole step stays integral (1:1000:1000).
    const double x = a + (b - a) * static_cast<double>(i) / (count - 1);
    v[static_cast<std::size_t>(i)] = log ? std::exp(x) : x;
  }
  // An integer key (model.normalize_every: 1, 3, 10, 32, … on a log range) takes the nearest
  // whole number, which the scene reader accepts.
  for (const scene::Limit& limit : scene::kLimits)
    if (limit.integer && limit.key == key)
      for (double& value : v) value = std::round(value);
  v.front() = start;
  v.back() = stop;
  return v;
}

std::string VaryRange::spec() const {
  return full_precision(start) + ":" + full_precision(stop) + ":" + std::to_string(count) +
         (log ? ":log" : "");
}

VaryRange parse_vary(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0)
    bad_vary(text, "expected KEY=START:STOP:COUNT[:log], e.g. time.dt=0.001:0.1:20:log");
  VaryRange r;
  r.key = text.substr(0, eq);
  r.scene_key = r.key;
  const auto bracket = r.key.find('[');
  if (bracket != std::string::npos) {
    const std::string index = r.key.substr(bracket);
    if (index.size() != 3 || index[2] != ']' || index[1] < '0' || index[1] > '2')
      bad_vary(text, "a vector component is written KEY[0], KEY[1] or KEY[2]");
    r.component = index[1] - '0';
    r.scene_key = r.key.substr(0, bracket);
  }
  bool key_ok = !r.scene_key.empty() && r.scene_key.front() != '.' && r.scene_key.back() != '.';
  for (char c : r.scene_key) key_ok = key_ok && is_key_char(c);
  if (!key_ok) bad_vary(text, "'" + r.key + "' is not a scene key");
  const auto fields = split_colons(text.substr(eq + 1));
  if (fields.size() < 3 || fields.size() > 4 || (fields.size() == 4 && fields[3] != "log"))
    bad_vary(text, "expected KEY=START:STOP:COUNT[:log], e.g. time.dt=0.001:0.1:20:log");
  if (!read_number(fields[0], r.start)) bad_vary(text, "START '" + fields[0] + "' is not a number");
  if (!read_number(fields[1], r.stop)) bad_vary(text, "STOP '" + fields[1] + "' is not a number");
  char* end = nullptr;
  const long count = std::strtol(fields[2].c_str(), &end, 10);
  if (fields[2].empty() || end != fields[2].c_str() + fields[2].size() || count < 1 ||
      count > kMaxVaryCount) {
    bad_vary(text, "COUNT '" + fields[2] + "' must be an integer from 1 to " +
                       std::to_string(kMaxVaryCount));
  }
  r.count = static_cast<int>(count);
  r.log = fields.size() == 4;
  if (r.log && !(r.start > 0.0 && r.stop > 0.0))
    bad_vary(text, "a :log range needs START and STOP greater than 0");
  return r;
}

SweepGrid::SweepGrid(std::vector<VaryRange> ranges) : ranges_(std::move(ranges)) {
  if (ranges_.empty()) throw InputError("sweep: give at least one --vary KEY=START:STOP:COUNT");
  for (std::size_t i = 0; i < ranges_.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (ranges_[i].scene_key == ranges_[j].scene_key &&
          (ranges_[i].component == ranges_[j].component || ranges_[i].component < 0 ||
           ranges_[j].component < 0)) {
        throw InputError("--vary " + ranges_[i].key + ": varied twice (also as --vary " +
                         ranges_[j].key + ")");
      }
    }
    values_.push_back(ranges_[i].values());
    size_ *= static_cast<std::size_t>(ranges_[i].count);
    if (size_ > kMaxGridPoints) {
      throw InputError("--vary: the grid has more than " + std::to_string(kMaxGridPoints) +
                       " points");
    }
  }
}

std::vector<double> SweepGrid::point(std::size_t index) const {
  std::vector<double> point(ranges_.size());
  for (std::size_t r = ranges_.size(); r-- > 0;) {
    const std::size_t count = values_[r].size();
    point[r] = values_[r][index % count];
    index /= count;
  }
  return point;
}

std::vector<std::string> point_overrides(const scene::Scene& base, const SweepGrid& grid,
                                         std::size_t index) {
  const std::vector<double> values = grid.point(index);
  std::vector<std::string> overrides;
  std::map<std::string, Eigen::Vector3d> vectors;  // ordered: the same overrides every time
  for (std::size_t r = 0; r < values.size(); ++r) {
    const VaryRange& range = grid.ranges()[r];
    if (range.component < 0) {
      overrides.push_back(range.key + "=" + full_precision(values[r]));
      continue;
    }
    auto it = vectors.find(range.scene_key);
    if (it == vectors.end()) {
      const Eigen::Vector3d* value = vector_value(base, range.scene_key);
      if (!value) {
        throw InputError("--vary " + range.key + ": '" + range.scene_key +
                         "' is not a vector scene key (book.size, initial.angular_velocity, "
                         "render.camera_direction)");
      }
      it = vectors.emplace(range.scene_key, *value).first;
    }
    it->second[range.component] = values[r];
  }
  for (const auto& [key, v] : vectors) {
    overrides.push_back(key + "=[" + full_precision(v[0]) + "," + full_precision(v[1]) + "," +
                        full_precision(v[2]) + "]");
  }
  return overrides;
}

}  // namespace bookspin::jobs
