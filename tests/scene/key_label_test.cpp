// scene::key_words: every numeric scene key in words, as a sweep's axes and header name it.
#include "scene/key_label.hpp"

#include <gtest/gtest.h>

#include <map>
#include <ostream>
#include <set>
#include <stdexcept>
#include <string>

#include "scene/limits.hpp"

namespace bookspin::scene {
namespace {

// Every key of the limits table has words of its own: none left as the key, none shared.
TEST(KeyLabel, EveryNumericKeyHasItsOwnWords) {
  std::set<std::string> seen;
  for (const Limit& limit : kLimits) {
    const KeyWords w = key_words(limit.key);
    EXPECT_FALSE(w.words.empty()) << limit.key;
    EXPECT_EQ(w.words.find('.'), std::string::npos) << limit.key << ": " << w.words;
    EXPECT_TRUE(seen.insert(w.words).second) << limit.key << " shares '" << w.words << "'";
  }
}

TEST(KeyLabel, TheWordsLeadTheUnitFollowsAndTheKeyComesLast) {
  EXPECT_EQ(key_label("time.dt"), "time step dt (time units)");
  EXPECT_EQ(key_caption("time.dt"), "time step dt (time units) \u00b7 time.dt");
  // A count has no unit.
  EXPECT_EQ(key_label("model.normalize_every"), "steps between normalizations");
  EXPECT_EQ(key_caption("model.normalize_every"),
            "steps between normalizations \u00b7 model.normalize_every");
}

// A vector key's component is named by its axis, x y z for [0] [1] [2], before the frame.
TEST(KeyLabel, AComponentIsNamedByItsAxis) {
  EXPECT_EQ(key_words("initial.angular_velocity[0]").words, "ω0 x, body frame");
  EXPECT_EQ(key_label("initial.angular_velocity[1]"), "ω0 y, body frame (rad per time unit)");
  EXPECT_EQ(key_words("book.size[2]").words, "book size z");
  EXPECT_EQ(key_caption("initial.angular_velocity[2]"),
            "ω0 z, body frame (rad per time unit) \u00b7 initial.angular_velocity[2]");
}

TEST(KeyLabel, AKeyThatIsNoNumericKeyIsRefused) {
  EXPECT_THROW(key_words("model.kind"), std::invalid_argument);
  EXPECT_THROW(key_words("time.dtt"), std::invalid_argument);
  EXPECT_THROW(key_words("initial.angular_velocity[3]"), std::invalid_argument);
  EXPECT_THROW(key_words(""), std::invalid_argument);
}

}  // namespace
}  // namespace bookspin::scene

namespace bookspin::scene {
namespace {

/// A unit's dimension: exponents of mass, length, time, angle; and a named count (pixels,
/// frames, samples) or a ratio.
struct Dimension {
  int mass = 0, length = 0, time = 0, angle = 0;
  std::string count;  ///< "px", "frames", "samples per pixel", "degrees", "ratio", or ""
  bool operator==(const Dimension&) const = default;
};

std::ostream& operator<<(std::ostream& os, const Dimension& d) {
  return os << "M^" << d.mass << " L^" << d.length << " T^" << d.time << " angle^" << d.angle << " "
            << d.count;
}

/// The dimension a unit's words say, read word by word (not looked up by the unit's text):
/// "<unit> per <unit>", "<name> units", a trailing ² squares the unit it ends.
Dimension read_unit(const std::string& unit) {
  Dimension d;
  if (unit.empty()) return d;
  if (unit == "px") return {0, 0, 0, 0, "px"};
  if (unit == "degrees") return {0, 0, 0, 0, "degrees"};
  if (unit == "frames per second") return {0, 0, -1, 0, "frames"};
  if (unit == "samples per pixel") return {0, 0, 0, 0, "samples per pixel"};
  if (unit.rfind("fraction of ", 0) == 0) return {0, 0, 0, 0, "ratio"};
  const auto per = unit.find("per ");
  const std::string top = per == std::string::npos ? unit : unit.substr(0, per);
  const std::string bottom = per == std::string::npos ? "" : unit.substr(per + 4);
  auto add = [&d](const std::string& part, int sign) {
    const int power = part.find("²") != std::string::npos ? 2 : 1;
    if (part.find("mass") != std::string::npos) d.mass += sign * power;
    if (part.find("length") != std::string::npos) d.length += sign * power;
    if (part.find("time") != std::string::npos) d.time += sign * power;
    if (part.find("rad") != std::string::npos) d.angle += sign * power;
  };
  add(top, 1);
  add(bottom, -1);
  return d;
}

// Each numeric key's unit against its dimension, set here from the physics and scenes/README.md
// ("Keys"), not from the label table: a key's unit wrong (the drag rate labelled "time units"
// where −(d|L|/dt)/|L| is per time unit) fails for that key. Counts (cells, steps, frames, a
// seed, a quality level) have no unit.
TEST(KeyLabel, EveryKeysUnitHasTheKeysDimension) {
  const Dimension none{}, T{0, 0, 1, 0, ""}, L{0, 1, 0, 0, ""}, M{1, 0, 0, 0, ""},
      per_T{0, 0, -1, 0, ""}, rad_per_T{0, 0, -1, 1, ""};
  const std::map<std::string, Dimension> expected{
      {"model.spring_constant",
       {1, 0, -2, 0, ""}},  // a force per length: M T⁻² (docs/physics.md §2)
      {"model.lattice_cells", none},
      {"model.normalize_every", none},
      {"model.drag_rate", per_T},  // −(d|L|/dt)/|L| at t = 0 (scenes/README.md)
      {"body.mass", M},
      {"body.scale", none},  // a factor on the mesh's coordinates
      {"book.size", L},
      {"book.mass", M},
      {"initial.angular_velocity", rad_per_T},
      {"initial.spin_rate", rad_per_T},
      {"initial.jiggle", {0, 0, 0, 0, "ratio"}},
      {"initial.seed", none},
      {"time.dt", T},
      {"time.steps_per_frame", none},
      {"time.frames", none},
      {"time.duration", T},
      {"render.width", {0, 0, 0, 0, "px"}},
      {"render.height", {0, 0, 0, 0, "px"}},
      {"render.fps", {0, 0, -1, 0, "frames"}},
      {"render.fov_y", {0, 0, 0, 0, "degrees"}},
      {"render.camera_distance", L},
      {"render.camera_direction", none},  // a direction: its length does not count
      {"render.crf", none},
      {"render.png_compression", none},
      {"render.anisotropy", none},
      {"render.msaa", {0, 0, 0, 0, "samples per pixel"}},
      {"render.gif_width", {0, 0, 0, 0, "px"}},
      {"render.gif_fps", {0, 0, -1, 0, "frames"}},
      {"render.webm_crf", none},
  };
  ASSERT_EQ(expected.size(), kLimits.size());
  for (const Limit& limit : kLimits) {
    const std::string key(limit.key);
    ASSERT_EQ(expected.count(key), 1u) << key;
    const std::string unit = key_words(key).unit;
    EXPECT_EQ(read_unit(unit), expected.at(key)) << key << ": '" << unit << "'";
  }
}

}  // namespace
}  // namespace bookspin::scene
