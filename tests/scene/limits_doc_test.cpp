// The one table of limits (src/scene/limits.hpp) against scenes/README.md's "Limits" table,
// and against what the reader does: each bound is the first value refused, each default
// what a missing key gives.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "scene/limits.hpp"
#include "scene_text.hpp"

namespace bookspin::scene {
namespace {

using testing::error_of;
using testing::parse;

struct DocumentedLimit {
  std::string type, minimum, maximum, smallest_nonzero, fallback;
};

std::string trim(const std::string& text) {
  const auto begin = text.find_first_not_of(' ');
  if (begin == std::string::npos) return "";
  return text.substr(begin, text.find_last_not_of(' ') - begin + 1);
}

/// The rows of the table under "## Limits" in scenes/README.md, by key.
std::map<std::string, DocumentedLimit> documented_limits() {
  std::ifstream readme(std::string(BOOKSPIN_SOURCE_DIR) + "/scenes/README.md");
  std::map<std::string, DocumentedLimit> rows;
  bool in_section = false;
  for (std::string line; std::getline(readme, line);) {
    if (line.rfind("## ", 0) == 0) in_section = line == "## Limits";
    if (!in_section || line.rfind("| `", 0) != 0) continue;
    std::vector<std::string> cells;
    for (auto at = std::size_t{1}; at < line.size();) {
      const auto bar = line.find('|', at);
      if (bar == std::string::npos) break;
      cells.push_back(trim(line.substr(at, bar - at)));
      at = bar + 1;
    }
    if (cells.size() != 6) {
      ADD_FAILURE() << "a Limits row needs 6 cells: " << line;
      continue;
    }
    const std::string key = cells[0].substr(1, cells[0].size() - 2);  // without the backticks
    EXPECT_EQ(rows.count(key), 0u) << key << " documented twice";
    rows[key] = {cells[1], cells[2], cells[3], cells[4], cells[5]};
  }
  return rows;
}

/// A documented number: decimal or e-notation, or a fraction such as "1/60".
double read_number(const std::string& text) {
  std::size_t used = 0;
  const double value = std::stod(text, &used);
  if (used < text.size() && text[used] == '/') return value / std::stod(text.substr(used + 1));
  EXPECT_EQ(used, text.size()) << "not a number: '" << text << "'";
  return value;
}

TEST(LimitsTable, MatchesScenesReadme) {
  const auto rows = documented_limits();
  EXPECT_EQ(rows.size(), kLimits.size()) << "a key in one table and not in the other";
  for (const Limit& limit : kLimits) {
    const std::string key(limit.key);
    SCOPED_TRACE(key);
    const auto it = rows.find(key);
    if (it == rows.end()) {
      ADD_FAILURE() << key << " is not in scenes/README.md's Limits table";
      continue;
    }
    const DocumentedLimit& doc = it->second;
    const bool vector = doc.type == "3 numbers";
    EXPECT_EQ(limit.integer, doc.type == "integer") << doc.type;
    if (!limit.integer) {
      EXPECT_TRUE(vector || doc.type == "number") << doc.type;
    }
    const std::string open = limit.min_open ? "> " : "≥ ";
    ASSERT_EQ(doc.minimum.rfind(open, 0), 0u) << "minimum '" << doc.minimum << "'";
    EXPECT_EQ(read_number(doc.minimum.substr(open.size())), limit.min);
    EXPECT_EQ(read_number(doc.maximum), limit.max);
    if (limit.smallest_nonzero == 0.0) {
      EXPECT_EQ(doc.smallest_nonzero, "");
    } else {
      EXPECT_EQ(read_number(doc.smallest_nonzero), limit.smallest_nonzero);
    }
    if (limit.fallback) {
      EXPECT_NEAR(read_number(doc.fallback), *limit.fallback, 1e-15 * std::abs(*limit.fallback));
    } else {
      EXPECT_EQ(doc.fallback, "—");
    }
  }
}

/// `key = value` as a scene; vector keys get the value in all three components. Keys that
/// need another key beside them (a body's mass, a GIF's width) get it.
std::string scene_with(const Limit& limit, const std::string& value, bool vector) {
  const std::string key(limit.key);
  const auto dot = key.find('.');
  const std::string table = key.substr(0, dot);
  std::string text = "[scene]\nname = \"limits\"\n";
  // A body key, or a lattice finer than the book's one cell: a non-book body.
  if (table == "body" || key == "model.lattice_cells") text += "[body]\nshape = \"phone\"\n";
  if (table != "body") text += "[" + table + "]\n";
  if (key == "model.normalize_every") text += "normalize = true\n";
  if (key == "model.drag_rate") text += "kind = \"exact\"\ndrag = \"linear\"\n";
  if (key == "time.duration") text += "steps_per_frame = 1000000\n";
  if (key == "render.gif_width") text += "width = 7680\n";
  if (key == "render.gif_fps") text += "fps = 240\n";
  if (key == "initial.spin_rate") text += "spin_axis = \"largest\"\n";
  text += key.substr(dot + 1) + " = ";
  text += vector ? "[" + value + ", " + value + ", " + value + "]\n" : value + "\n";
  return text;
}

std::string number_text(double value, bool integer) {
  if (integer) return std::to_string(static_cast<long long>(value));
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  std::string text = buffer;
  if (text.find_first_of(".en") == std::string::npos) text += ".0";
  return text;
}

/// The reader refuses each bound's first value outside and accepts the bound itself.
TEST(LimitsTable, BoundsAreWhatTheReaderEnforces) {
  for (const Limit& limit : kLimits) {
    const std::string key(limit.key);
    SCOPED_TRACE(key);
    const bool vector =
        key == "book.size" || key == "initial.angular_velocity" || key == "render.camera_direction";
    if (key == "initial.seed") continue;  // 2⁶³ − 1 is not a double; its bounds: below
    const double step = limit.integer ? 1.0 : 0.0;
    const double below = step > 0         ? limit.min - step
                         : limit.min_open ? limit.min
                                          : std::nextafter(limit.min, -INFINITY);
    const double above = step > 0 ? limit.max + step : std::nextafter(limit.max, INFINITY);
    // 16 and the largest widths are even; a width of 15 or 7681 is odd, which says more.
    if (key != "render.width" && key != "render.height") {
      EXPECT_NE(
          error_of(scene_with(limit, number_text(below, limit.integer), vector)).find(key + ": "),
          std::string::npos);
      EXPECT_NE(
          error_of(scene_with(limit, number_text(above, limit.integer), vector)).find(key + ": "),
          std::string::npos);
    }
    if (!limit.min_open) {
      EXPECT_EQ(error_of(scene_with(limit, number_text(limit.min, limit.integer), vector)), "");
    }
    EXPECT_EQ(error_of(scene_with(limit, number_text(limit.max, limit.integer), vector)), "");
    if (limit.smallest_nonzero > 0.0) {
      const double tiny = 0.99 * limit.smallest_nonzero / (vector ? std::sqrt(3.0) : 1.0);
      EXPECT_NE(
          error_of(scene_with(limit, number_text(tiny, false), vector)).find(key + ": must be "),
          std::string::npos);
      EXPECT_EQ(error_of(scene_with(limit, number_text(limit.smallest_nonzero, false), vector)),
                "");
    }
  }
  EXPECT_NE(error_of("[initial]\nseed = -1\n").find("initial.seed: "), std::string::npos);
  EXPECT_EQ(error_of("[initial]\nseed = 9223372036854775807\n"), "");
}

/// The number after "got " at the end of `message`, read back; NaN when there is none.
double got_value(const std::string& message) {
  const auto at = message.rfind("got ");
  if (at == std::string::npos) return NAN;
  return std::strtod(message.c_str() + at + 4, nullptr);
}

/// A value one double past a bound is printed as itself, never rounded onto the bound
/// ("must be <= 1e+12, got 1e+12"): the number after "got " reads back to the value typed.
TEST(LimitsTable, MessagesShowTheValueTypedNotTheBound) {
  for (const Limit& limit : kLimits) {
    const std::string key(limit.key);
    SCOPED_TRACE(key);
    if (limit.integer) continue;  // integers print exactly
    const bool vector =
        key == "book.size" || key == "initial.angular_velocity" || key == "render.camera_direction";
    const double above = std::nextafter(limit.max, INFINITY);
    const std::string error = error_of(scene_with(limit, number_text(above, false), vector));
    EXPECT_EQ(got_value(error), above) << error;
    if (!limit.min_open && limit.min != 0.0) {
      const double below = std::nextafter(limit.min, -INFINITY);
      const std::string low = error_of(scene_with(limit, number_text(below, false), vector));
      EXPECT_EQ(got_value(low), below) << low;
    }
    if (limit.smallest_nonzero > 0.0 && !vector) {
      const double tiny = std::nextafter(limit.smallest_nonzero, 0.0);
      const std::string small = error_of(scene_with(limit, number_text(tiny, false), vector));
      EXPECT_EQ(got_value(small), tiny) << small;
    }
  }
}

/// A scene without the key gets the table's default.
TEST(LimitsTable, DefaultsAreWhatAMissingKeyGives) {
  const Scene s = parse("[scene]\nname = \"defaults\"\n");
  const std::map<std::string, double> got{{"model.spring_constant", s.model.spring_constant},
                                          {"model.lattice_cells", s.model.lattice_cells},
                                          {"model.normalize_every", s.model.normalize_every},
                                          {"model.drag_rate", s.model.drag.rate},
                                          {"book.mass", s.body.cage.mass},
                                          {"initial.jiggle", s.initial.jiggle},
                                          {"initial.seed", static_cast<double>(s.initial.seed)},
                                          {"time.dt", s.dt},
                                          {"time.steps_per_frame", s.steps_per_frame},
                                          {"time.frames", s.frames},
                                          {"render.width", s.render.width},
                                          {"render.height", s.render.height},
                                          {"render.fps", s.render.fps},
                                          {"render.fov_y", s.render.fov_y_deg},
                                          {"render.camera_distance", s.render.camera_distance},
                                          {"render.crf", s.render.crf},
                                          {"render.png_compression", s.render.png_compression},
                                          {"render.anisotropy", s.render.anisotropy},
                                          {"render.msaa", s.render.msaa},
                                          {"render.webm_crf", s.render.webm_crf}};
  const Scene phone = parse("[body]\nshape = \"phone\"\n");
  const Scene twice = parse("[body]\nshape = \"phone\"\nscale = 2.0\n");
  for (const Limit& limit : kLimits) {
    const std::string key(limit.key);
    SCOPED_TRACE(key);
    if (!limit.fallback) continue;
    if (key == "body.mass") {
      EXPECT_EQ(phone.body.cage.mass, *limit.fallback);
    } else if (key == "body.scale") {  // moments grow as scale²: twice the default, 4 times
      const double ratio = 2.0 / *limit.fallback;
      EXPECT_NEAR(twice.body.moments[0], ratio * ratio * phone.body.moments[0],
                  1e-12 * twice.body.moments[0]);
    } else {
      ASSERT_EQ(got.count(key), 1u) << "no check for this default";
      EXPECT_EQ(got.at(key), *limit.fallback);
    }
  }
}

}  // namespace
}  // namespace bookspin::scene

namespace bookspin::scene {
namespace {

/// Whether `value` lies in `limit`'s range, judged here from the table's numbers alone: the
/// range on the signed value, and the smallest non-zero size on the magnitude (a vector key gets
/// `value` in all three components: its length is |value| √3).
bool in_range(const Limit& limit, double value, bool vector) {
  const bool above_min = limit.min_open ? value > limit.min : value >= limit.min;
  const double size = std::abs(value) * (vector ? std::sqrt(3.0) : 1.0);
  // The rules beside the table (scenes/README.md, "Limits"): even picture sizes, and MSAA's
  // sample counts.
  const std::string key(limit.key);
  if ((key == "render.width" || key == "render.height") && std::fmod(value, 2.0) != 0.0)
    return false;
  if (key == "render.msaa" && value != 1 && value != 2 && value != 4 && value != 8) return false;
  return above_min && value <= limit.max &&
         (value == 0.0 || limit.smallest_nonzero == 0.0 || size >= limit.smallest_nonzero);
}

/// Every limit, both signs, across the whole double range (seeded): a value is accepted exactly
/// where the table's range holds it, and a refused one names its key. A check made on the signed
/// value where the magnitude was meant (ω0 far below −1e6 accepted, above refused), or on one
/// side only, fails here for its key.
TEST(LimitsTable, EveryLimitHoldsOnBothSignsAcrossTheWholeRange) {
  std::mt19937_64 rng(6);
  std::uniform_real_distribution<double> exponent(-300.0, 300.0), unit(0.0, 1.0);
  for (const Limit& limit : kLimits) {
    const std::string key(limit.key);
    SCOPED_TRACE(key);
    const bool vector =
        key == "book.size" || key == "initial.angular_velocity" || key == "render.camera_direction";
    if (key == "initial.seed") continue;  // 2⁶³ − 1 is not a double: LimitsTable.BoundsAre…
    std::vector<double> values;
    for (double bound : {limit.min, limit.max})
      for (double sign : {-1.0, 1.0})
        for (double factor : {1.0, 1.5, 10.0, 1e6})
          values.push_back(sign * std::abs(bound) * factor);
    for (int n = 0; n < 60; ++n) {
      double v = std::pow(10.0, limit.integer ? exponent(rng) / 20.0 : exponent(rng));
      if (limit.integer) v = std::round(v);
      values.push_back(n % 2 ? -v : v);
      values.push_back(limit.min + (limit.max - limit.min) * unit(rng) * (n % 2 ? -1.0 : 1.0));
    }
    for (double value : values) {
      if (limit.integer) value = std::round(value);
      const std::string error =
          error_of(scene_with(limit, number_text(value, limit.integer), vector));
      if (in_range(limit, value, vector)) {
        EXPECT_EQ(error.find(key + ": "), std::string::npos) << value << ": " << error;
      } else {
        EXPECT_NE(error.find(key + ": "), std::string::npos) << value << " accepted: " << error;
      }
    }
  }
}

}  // namespace
}  // namespace bookspin::scene

namespace bookspin::scene {
namespace {

/// time.duration's rounding rule (scenes/README.md, "Keys"), on seeded durations, steps and
/// frame counts of every size: the last frame is at or just past the duration (within 1e-9 of a
/// frame's time short of it), and the frame before it is short of the duration, so neither a
/// frame too many nor one too few. A rule rounded to the nearest frame, or one-sided, fails.
TEST(LimitsTable, DurationCoversWithTheFewestFrames) {
  std::mt19937_64 rng(1082);
  std::uniform_real_distribution<double> exponent(-6.0, 3.0), unit(0.0, 1.0);
  for (int n = 0; n < 20000; ++n) {
    const double dt = std::pow(10.0, exponent(rng));
    const int steps = 1 + static_cast<int>(unit(rng) * 999);
    const double frame = dt * steps;
    // Whole numbers of frames (± a hair), and anywhere between.
    const double whole = std::floor(unit(rng) * 1000.0) + 1.0;
    const double duration = n % 3 == 0   ? whole * frame
                            : n % 3 == 1 ? whole * frame * (1.0 + (unit(rng) - 0.5) * 1e-12)
                                         : (whole + unit(rng)) * frame;
    const double frames = frames_covering(duration, dt, steps);
    SCOPED_TRACE(std::to_string(duration) + " at " + std::to_string(frame) + " a frame");
    EXPECT_GE((frames - 1.0) * frame, duration - 1.01e-9 * frame);
    EXPECT_LT((frames - 2.0) * frame, duration);
  }
}

}  // namespace
}  // namespace bookspin::scene
