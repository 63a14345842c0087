#include "scene/key_label.hpp"

#include <array>
#include <stdexcept>

#include "scene/limits.hpp"

namespace bookspin::scene {

namespace {

struct Entry {
  std::string_view key, words, unit;
};

/// One entry per kLimits key, in its order (tests/scene/key_label_test.cpp checks both hold).
constexpr std::array kWords{
    Entry{"model.spring_constant", "spring constant k", "mass per time unit²"},
    Entry{"model.lattice_cells", "lattice cells along the longest side", ""},
    Entry{"model.normalize_every", "steps between normalizations", ""},
    Entry{"model.drag_rate", "air drag rate", "per time unit"},
    Entry{"body.mass", "body mass", "mass units"},
    Entry{"body.scale", "body scale", ""},
    Entry{"book.size", "book size", "length units"},
    Entry{"book.mass", "book mass", "mass units"},
    Entry{"initial.angular_velocity", "ω0, body frame", "rad per time unit"},
    Entry{"initial.spin_rate", "spin rate |ω0|", "rad per time unit"},
    Entry{"initial.jiggle", "jiggle of L0", "fraction of |L0|"},
    Entry{"initial.seed", "jiggle's seed", ""},
    Entry{"time.dt", "time step dt", "time units"},
    Entry{"time.steps_per_frame", "steps per frame", ""},
    Entry{"time.frames", "frames", ""},
    Entry{"time.duration", "duration", "time units"},
    Entry{"render.width", "picture width", "px"},
    Entry{"render.height", "picture height", "px"},
    Entry{"render.fps", "video frame rate", "frames per second"},
    Entry{"render.fov_y", "vertical field of view", "degrees"},
    Entry{"render.camera_distance", "camera distance", "length units"},
    Entry{"render.camera_direction", "camera direction", ""},
    Entry{"render.crf", "MP4 quality (CRF)", ""},
    Entry{"render.png_compression", "PNG compression level", ""},
    Entry{"render.anisotropy", "anisotropic filtering", ""},
    Entry{"render.msaa", "multisampling", "samples per pixel"},
    Entry{"render.gif_width", "GIF width", "px"},
    Entry{"render.gif_fps", "GIF frame rate", "frames per second"},
    Entry{"render.webm_crf", "WebM quality (CRF)", ""},
};
static_assert(kWords.size() == kLimits.size(), "a numeric key without its words");

}  // namespace

KeyWords key_words(std::string_view key) {
  // A vector key's component: "key[i]", i = 0, 1, 2 (x, y, z of its frame).
  std::string_view base = key;
  int component = -1;
  if (key.size() > 3 && key.back() == ']' && key[key.size() - 3] == '[' &&
      key[key.size() - 2] >= '0' && key[key.size() - 2] <= '2') {
    base = key.substr(0, key.size() - 3);
    component = key[key.size() - 2] - '0';
  }
  for (const Entry& e : kWords) {
    if (e.key != base) continue;
    std::string words(e.words);
    if (component >= 0) {
      // "ω0, body frame" → "ω0 y, body frame", "book size" → "book size y".
      const std::string axis = std::string(" ") + "xyz"[component];
      const auto note = words.find(',');
      words = note == std::string::npos ? words + axis : words.insert(note, axis);
    }
    return {words, std::string(e.unit)};
  }
  throw std::invalid_argument("scene::key_words: '" + std::string(key) +
                              "' is not a numeric scene key");
}

std::string key_label(std::string_view key) {
  const KeyWords w = key_words(key);
  return w.unit.empty() ? w.words : w.words + " (" + w.unit + ")";
}

std::string key_caption(std::string_view key) {
  return key_label(key) + " \u00b7 " + std::string(key);
}

}  // namespace bookspin::scene
