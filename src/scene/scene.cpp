#include "scene/scene.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <sstream>

#include "common/file_name.hpp"
#include "common/number_text.hpp"
#include "common/text_file.hpp"
#include "common/text_lines.hpp"
#include "mesh/mesh.hpp"
#include "physics/exact_model.hpp"
#include "physics/presets.hpp"
#include "scene/model_reader.hpp"
#include "scene/texture_file.hpp"
#include "scene/toml_reader.hpp"

namespace bookspin::scene {

namespace {

bool is_key_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
}

/// "a.b_c.d-e": bare TOML keys joined by dots, none empty.
bool is_dotted_key(std::string_view key) {
  if (key.empty() || key.front() == '.' || key.back() == '.') return false;
  for (std::size_t i = 0; i < key.size(); ++i) {
    if (key[i] == '.' ? key[i + 1] == '.' : !is_key_char(key[i])) return false;
  }
  return true;
}

/// A file name that cannot leave the output directory: a letter or a digit of any script first,
/// no "..", and nothing a file's name cannot hold (common/file_name.hpp: no / \ : * ? " < > |,
/// no control character). Why `name` is not such a name, or "" when it is.
std::string unsafe_name_reason(std::string_view name) {
  if (name.empty()) return "it is empty";
  if (!starts_with_letter_or_digit(name)) return "it must start with a letter or a digit";
  if (name.find("..") != std::string_view::npos) return "it must not hold '..'";
  return file_name_problem(name);
}

std::string first_line(std::string_view text) {
  return std::string(text.substr(0, text.find('\n')));
}

void replace_all(std::string& text, std::string_view from, std::string_view to) {
  for (auto at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
    text.replace(at, from.size(), to);
  }
}

/// The character at a 1-based line and column of `text`, or '\0' past its end.
char char_at(std::string_view text, std::size_t line, std::size_t column) {
  std::size_t at = 0;
  for (std::size_t l = 1; l < line; ++l) {
    at = text.find('\n', at);
    if (at == std::string_view::npos) return '\0';
    ++at;
  }
  at += column - 1;
  return at < text.size() ? text[at] : '\0';
}

/// toml++'s description of a syntax error, reworded where its own words mislead: a string
/// left open at the end of its line is reported as a forbidden control character (the line
/// break), and a line break it "saw" is printed as an escape.
std::string describe_syntax_error(const toml::parse_error& e, std::string_view text) {
  std::string what = first_line(e.description());
  const bool in_string = what.rfind("Error while parsing string", 0) == 0 ||
                         what.rfind("Error while parsing literal string", 0) == 0;
  const auto& at = e.source().begin;
  const char bad = char_at(text, at.line, at.column);
  if (in_string && what.find("control characters") != std::string::npos &&
      (bad == '\n' || bad == '\r')) {
    return "string is not closed before the end of the line";
  }
  if (in_string && what.find("end-of-file") != std::string::npos) {
    return "string is not closed before the end of the file";
  }
  replace_all(what, "saw '\\n'", "saw the end of the line");
  replace_all(what, "saw '\\r'", "saw the end of the line");
  return what;
}

/// Applies one "key=value" override onto `root`, creating tables along the key's path.
std::string apply_override(toml::table& root, const std::string& assignment) {
  const auto eq = assignment.find('=');
  const std::string key = assignment.substr(0, eq);
  if (eq == std::string::npos || !is_dotted_key(key)) {
    throw InputError("--set " + escape_controls(assignment) +
                     ": expected key=value, e.g. time.dt=0.01");
  }
  // A number past the doubles is no TOML error nor 0 (TOML's reader refuses "2e308" as no
  // value and reads "1e-400" as 0): named in every door's words (common/number_text.hpp).
  const std::string given(trimmed(std::string_view(assignment).substr(eq + 1)));
  if (const std::string range = out_of_range_reason(given); !range.empty())
    throw InputError("--set " + key + ": \"" + given + "\" is " + range);
  toml::table parsed;
  try {
    const std::string doc = "value = " + assignment.substr(eq + 1);
    parsed = toml::parse(std::string_view(doc), std::string_view("--set"));
  } catch (const toml::parse_error& e) {
    throw InputError("--set " + key + ": value is not valid TOML (" +
                     escape_controls(first_line(e.description())) +
                     "); strings need quotes, e.g. key=\"text\"");
  }
  toml::table* table = &root;
  std::string_view rest = key;
  for (auto dot = rest.find('.'); dot != std::string_view::npos; dot = rest.find('.')) {
    const std::string part(rest.substr(0, dot));
    rest.remove_prefix(dot + 1);
    if (!table->contains(part)) table->insert(part, toml::table{});
    table = (*table)[part].as_table();
    if (!table) throw InputError("--set " + key + ": '" + part + "' is not a table");
  }
  table->insert_or_assign(std::string(rest), *parsed["value"].node());
  return key;
}

void read_time(TomlReader& r, Scene& s) {
  s.time_unit = r.string("time.unit", "");
  if (!s.time_unit.empty() && s.time_unit != "s")
    r.fail("time.unit", "expected \"s\" (the second) or no key (the abstract time unit), got \"" +
                            s.time_unit + "\"");
  s.dt = r.number(limit("time.dt"));
  s.steps_per_frame = static_cast<int>(r.integer(limit("time.steps_per_frame")));
  s.frames = static_cast<int>(r.integer(limit("time.frames")));
  if (!r.has("time.duration")) return;
  // A run of a given length whatever dt is (a sweep over dt): the frames that cover it.
  if (r.has("time.frames"))
    r.fail("time.duration", "give either time.frames or time.duration, not both");
  const double duration = r.number(limit("time.duration"), 0.0);
  const double frames = frames_covering(duration, s.dt, s.steps_per_frame);
  if (frames > limit("time.frames").max) {
    r.fail("time.duration", "needs " + std::to_string(static_cast<long long>(frames)) +
                                " frames at time.dt × time.steps_per_frame, more than 100000: "
                                "raise time.steps_per_frame");
  }
  s.frames = static_cast<int>(frames);
}

std::string read_texture(TomlReader& r, std::string_view key, const std::filesystem::path& origin) {
  const std::string value = r.string(key, "");
  if (value.empty()) return value;
  std::filesystem::path path(value);
  if (path.is_relative()) path = origin.parent_path() / path;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    r.fail(key, "texture file not found: " + path.string());
  if (const std::string problem = png_problem(path); !problem.empty())
    r.fail(key, path.string() + ": " + problem);
  return path.string();
}

/// measured.omega: the file (relative to the scene file) read and checked (measured_file.hpp).
MeasuredOmega read_measured(TomlReader& r, const std::filesystem::path& origin) {
  MeasuredOmega measured;
  const char* key = "measured.omega";
  const std::string value = r.string(key, "");
  if (value.empty()) return measured;
  std::filesystem::path path(value);
  if (path.is_relative()) path = origin.parent_path() / path;
  std::error_code ec;
  if (const std::string why = not_a_file_reason(path); !why.empty())
    r.fail(key, path.string() + ": " + why + " (the measured ω file)");
  if (std::filesystem::file_size(path, ec) > kMaxMeasuredFileBytes)
    r.fail(key,
           path.string() + ": larger than " + std::to_string(kMaxMeasuredFileBytes) + " bytes");
  if (const std::string problem =
          parse_measured_omega(read_text_file(path, "the measured ω file"), measured);
      !problem.empty())
    r.fail(key, path.string() + ": " + problem);
  measured.file = path.string();
  return measured;
}

int read_dimension(TomlReader& r, const Limit& limit) {
  const int value = static_cast<int>(r.integer(limit));
  if (value % 2 != 0) {
    r.fail(limit.key, "must be even (4:2:0 video needs even sizes), got " + std::to_string(value));
  }
  return value;
}

std::vector<std::string> read_formats(TomlReader& r, std::string_view key,
                                      std::vector<std::string> fallback) {
  const auto view = r.node(key);
  if (!view) return fallback;
  const toml::array* array = view.as_array();
  if (array == nullptr) r.fail(key, "expected an array of strings such as [\"mp4\", \"gif\"]");
  std::vector<std::string> formats;
  for (const toml::node& item : *array) {
    const auto* text = item.as_string();
    if (text == nullptr) r.fail(key, "expected an array of strings such as [\"mp4\", \"gif\"]");
    formats.push_back(text->get());
  }
  if (const std::string problem = video_formats_problem(formats); !problem.empty())
    r.fail(key, problem);
  return formats;
}

// The GIF keeps every round(fps / gif_fps)-th frame (video::gif_step) and so plays at
// fps / step frames per second. A GIF stores each frame's delay in whole centiseconds and
// browsers show delays under 2 cs as 10 cs: it plays at most 50 frames/s
// (video::kGifMaxFps; docs/outputs.md, "Video formats").
constexpr int kGifMaxFps = 50;

int gif_step(int fps, int gif_fps) {
  return std::max(1, static_cast<int>(std::lround(static_cast<double>(fps) / gif_fps)));
}

bool gif_rate_storable(int fps, int gif_fps) { return fps <= kGifMaxFps * gif_step(fps, gif_fps); }

/// Refuses a render.gif_fps whose GIF would play faster than a GIF can, naming the largest
/// one allowed with this render.fps.
void check_gif_rate(const TomlReader& r, int fps, int gif_fps) {
  if (gif_rate_storable(fps, gif_fps)) return;
  int allowed = std::min(fps, kGifMaxFps);
  while (allowed > 1 && !gif_rate_storable(fps, allowed)) --allowed;
  std::ostringstream rate;
  rate << static_cast<double>(fps) / gif_step(fps, gif_fps);
  r.fail("render.gif_fps", "the GIF would play at " + rate.str() +
                               " frames/s; a GIF plays at most " + std::to_string(kGifMaxFps) +
                               " (its frame delays are whole centiseconds, at least 2): at most " +
                               std::to_string(allowed) + " with render.fps = " +
                               std::to_string(fps) + ", got " + std::to_string(gif_fps));
}

RenderOptions read_render(TomlReader& r, const std::filesystem::path& origin) {
  RenderOptions o;
  o.width = read_dimension(r, limit("render.width"));
  o.height = read_dimension(r, limit("render.height"));
  o.fps = static_cast<int>(r.integer(limit("render.fps")));
  o.fov_y_deg = r.number(limit("render.fov_y"));
  o.camera_distance = r.number(limit("render.camera_distance"));
  o.camera_direction = r.vector3(limit("render.camera_direction"), o.camera_direction);
  // Any nonzero vector: one as short as [1e-300, 0, 0] (whose norm underflows) is a direction too.
  if (o.camera_direction.cwiseAbs().maxCoeff() == 0.0)
    r.fail("render.camera_direction", "must not be zero");
  o.show_angular_momentum = r.boolean("render.show_angular_momentum", false);
  o.show_body_axes = r.boolean("render.show_body_axes", false);
  o.texture_front = read_texture(r, "render.texture_front", origin);
  o.texture_back = read_texture(r, "render.texture_back", origin);
  o.texture_spine = read_texture(r, "render.texture_spine", origin);
  o.texture_pages = read_texture(r, "render.texture_pages", origin);
  o.codec = r.string("render.codec", o.codec);
  if (o.codec != "libx264" && o.codec != "h264_nvenc") {
    r.fail("render.codec", "unknown codec '" + o.codec + "' (expected libx264 or h264_nvenc)");
  }
  o.crf = static_cast<int>(r.integer(limit("render.crf")));
  o.preset = r.string("render.preset", o.preset);
  static constexpr std::array<std::string_view, 9> kPresets{"ultrafast", "superfast", "veryfast",
                                                            "faster",    "fast",      "medium",
                                                            "slow",      "slower",    "veryslow"};
  if (std::find(kPresets.begin(), kPresets.end(), o.preset) == kPresets.end())
    r.fail("render.preset", "unknown preset '" + o.preset + "'");
  o.png_compression = static_cast<int>(r.integer(limit("render.png_compression")));
  o.panel = r.boolean("render.panel", false);
  o.sphere = r.boolean("render.sphere", false);
  o.poinsot = r.boolean("render.poinsot", false);
  o.caption_twist = r.boolean("render.caption_twist", false);
  o.anisotropy = static_cast<int>(r.integer(limit("render.anisotropy")));
  o.msaa = static_cast<int>(r.integer(limit("render.msaa")));
  o.formats = read_formats(r, "render.formats", o.formats);
  o.gif_width = static_cast<int>(
      r.integer(limit("render.gif_width"), std::min(o.gif_width, o.width), o.width));
  o.gif_fps =
      static_cast<int>(r.integer(limit("render.gif_fps"), std::min(o.gif_fps, o.fps), o.fps));
  check_gif_rate(r, o.fps, o.gif_fps);
  o.webm_crf = static_cast<int>(r.integer(limit("render.webm_crf")));
  if (o.msaa != 1 && o.msaa != 2 && o.msaa != 4 && o.msaa != 8)
    r.fail("render.msaa", "must be 1, 2, 4 or 8, got " + std::to_string(o.msaa));
  return o;
}

}  // namespace

std::string video_formats_problem(const std::vector<std::string>& formats) {
  const std::string expected = " (expected mp4, webm or gif)";
  if (formats.empty()) return "no video format given" + expected;
  for (std::size_t i = 0; i < formats.size(); ++i) {
    if (std::find(kVideoFormats.begin(), kVideoFormats.end(), formats[i]) == kVideoFormats.end())
      return "unknown video format '" + formats[i] + "'" + expected;
    if (std::find(formats.begin(), formats.begin() + static_cast<long>(i), formats[i]) !=
        formats.begin() + static_cast<long>(i))
      return "video format '" + formats[i] + "' given twice";
  }
  return "";
}

namespace {

void read_identity(TomlReader& r, Scene& s) {
  s.name = r.string("scene.name", s.source.stem().string());
  if (const std::string why = unsafe_name_reason(s.name); !why.empty())
    r.fail("scene.name", "'" + s.name + "' is not a safe output name: " + why);
  s.title = r.string("scene.title", s.name);
  s.description = r.string("scene.description", "");
}

/// A body so small that the camera cannot frame it is bad input here, before anything runs:
/// the longest side of its box (principal frame, after body.scale) must be at least
/// kMinBodySize (scene/limits.hpp). Presets and books meet it by their keys' limits; a mesh
/// file in tiny units need not.
void check_body_size(TomlReader& r, const Scene& s, double scale) {
  const double size = s.body.cage.size.maxCoeff();
  if (size >= kMinBodySize) return;
  const bool mesh = s.body.shape == physics::BodyShape::mesh;
  // Three digits say how far off it is, unless they round up to the bound itself.
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", size);
  const std::string shown = std::strtod(text, nullptr) < kMinBodySize ? text : format_number(size);
  r.fail(mesh ? "body.mesh" : "body.scale",
         (mesh ? s.body_mesh + ": " : std::string()) + "the body is " + shown +
             " across at body.scale = " + format_number(scale) +
             " (the longest side of the box that holds it); a body must be at least " +
             format_number(kMinBodySize) + " across for the camera to frame it");
}

/// The [body] table, and [book] for the book (docs/physics.md §12, scenes/README.md).
void read_body(TomlReader& r, Scene& s, const std::filesystem::path& origin) {
  const std::string name = r.string("body.shape", "book");
  physics::BodyShape shape = physics::BodyShape::book;
  if (!physics::parse_body_shape(name, shape)) {
    r.fail("body.shape",
           "unknown shape '" + name + "' (expected book, t-handle, tennis-racket, phone, mesh)");
  }
  if (shape == physics::BodyShape::book) {
    physics::Book book;
    book.size = r.vector3(limit("book.size"), book.size);
    book.mass = r.number(limit("book.mass"));
    for (const char* key : {"body.mesh", "body.mass", "body.scale"}) {
      if (r.has(key))
        r.fail(key, "not used by the book (body.shape = \"book\"): give [book] size and mass");
    }
    s.body = physics::book_body(book);
    return;
  }
  for (const char* key : {"book.size", "book.mass"}) {
    if (r.has(key)) {
      r.fail(key, "[book] keys describe the book, but body.shape is '" + name +
                      "' (use body.mass and body.scale)");
    }
  }
  const double mass = r.number(limit("body.mass"));
  const double scale = r.number(limit("body.scale"));
  if (shape != physics::BodyShape::mesh) {
    if (r.has("body.mesh")) r.fail("body.mesh", "only with body.shape = \"mesh\"");
    s.body = physics::preset_body(shape, mass, scale);
  } else {
    if (!r.has("body.mesh")) r.fail("body.shape", "'mesh' needs body.mesh (a mesh file)");
    std::filesystem::path path(r.string("body.mesh", ""));
    if (path.empty()) r.fail("body.mesh", "must name a mesh file");
    if (path.is_relative()) path = origin.parent_path() / path;
    s.body_mesh = path.string();
    mesh::TriangleMesh mesh;
    try {
      mesh = mesh::load_mesh(path, scale);
    } catch (const InputError& e) {
      r.fail("body.mesh", e.what());
    }
    const physics::BodyResult body = physics::body_from_mesh(mesh.vertices, mesh.triangles, mass,
                                                             1.0, mesh.face_colours, mesh.smooth);
    if (!body.ok()) r.fail("body.mesh", path.string() + ": " + body.error);
    for (const std::string& warning : body.warnings)
      s.warnings.push_back(path.string() + ": " + warning);
    s.body = body.body;
  }
  check_body_size(r, s, scale);
}

/// initial.angular_velocity, or initial.spin_axis with initial.spin_rate (principal frame).
void read_spin(TomlReader& r, Scene& s) {
  const bool has_velocity = r.has("initial.angular_velocity");
  s.initial.omega0_body = r.vector3(limit("initial.angular_velocity"), s.initial.omega0_body);
  if (!r.has("initial.spin_axis")) {
    if (r.has("initial.spin_rate")) r.fail("initial.spin_rate", "only with initial.spin_axis");
    return;
  }
  if (has_velocity) {
    r.fail("initial.spin_axis",
           "give either initial.spin_axis (with initial.spin_rate) or initial.angular_velocity, "
           "not both");
  }
  const std::string axis = r.string("initial.spin_axis", "");
  static constexpr std::array<std::string_view, 3> kAxes{"smallest", "intermediate", "largest"};
  const auto it = std::find(kAxes.begin(), kAxes.end(), axis);
  if (it == kAxes.end()) {
    r.fail("initial.spin_axis",
           "unknown axis '" + axis + "' (expected smallest, intermediate, largest)");
  }
  if (!r.has("initial.spin_rate")) {
    r.fail("initial.spin_axis", "needs initial.spin_rate (rad per time unit)");
  }
  const double rate = r.number(limit("initial.spin_rate"), 0.0);
  const std::array<int, 3> order = physics::principal_order(s.body.moments);
  s.initial.omega0_body.setZero();
  s.initial.omega0_body[order[static_cast<std::size_t>(it - kAxes.begin())]] = rate;
}

/// The book is the one-cell lattice; model.lattice_cells refines the lattice of other bodies.
void check_lattice_cells(TomlReader& r, const Scene& s) {
  // The book is one cell of the lattice, today's particle model (docs/physics.md §13).
  if (s.body.shape == physics::BodyShape::book && s.model.lattice_cells > 1)
    r.fail("model.lattice_cells",
           "the book is one cell; a finer lattice is for other bodies (body.shape)");
}

/// render.caption_twist needs one run whose body-frame motion has a period (docs/physics.md
/// §19): not a comparison, not a body at rest, not a steady spin or the separatrix.
void check_caption_twist(TomlReader& r, const Scene& s) {
  if (!s.render.caption_twist) return;
  const char* key = "render.caption_twist";
  if (!s.compare.empty())
    r.fail(key, "the twist caption is for a single run, not a [[compare]] scene");
  if (s.initial.omega0_body.isZero(0.0) && s.initial.jiggle == 0.0)
    r.fail(key,
           "the twist needs a spinning body, but initial.angular_velocity is [0, 0, 0] and "
           "initial.jiggle is 0 (at rest: L = 0)");
  physics::ExactModel exact(s.body);
  exact.reset(s.initial);
  const physics::ExactCase motion = exact.rotation().motion_case();
  if (motion == physics::ExactCase::steady && physics::distinct_moments(s.body.moments) == 1)
    r.fail(key,
           "the twist needs a body-frame motion with a period, but the body's three principal "
           "moments are equal (a cube or a sphere): every spin is steady, whatever its jiggle");
  if (motion == physics::ExactCase::steady)
    r.fail(key,
           "the twist needs a body-frame motion with a period, but this spin is steady (about a "
           "principal axis, without initial.jiggle)");
  if (motion == physics::ExactCase::separatrix)
    r.fail(key,
           "the twist needs a body-frame motion with a period, but this spin is on the "
           "separatrix (no period)");
}

/// What the engines cannot run, refused here rather than aborting in them (scenes/README.md,
/// "Engine limits"): ODE asserts and aborts on a subnormal step (its quaternion update cannot
/// normalize), MuJoCo rejects a body whose mass or principal moment is at most its mjMINVAL
/// (1e-15). Checked for the scene's model and every [[compare]] tile's.
void check_engine_limits(TomlReader& r, const Scene& s) {
  std::vector<physics::ModelKind> kinds{s.model.kind};
  for (const CompareTile& tile : s.compare) kinds.push_back(tile.model.kind);
  const auto uses = [&kinds](physics::ModelKind kind) {
    return std::find(kinds.begin(), kinds.end(), kind) != kinds.end();
  };
  // r.fail's message (file and line, or --set), kept with the key and reason on their own.
  const auto refuse = [&r](const std::string& key, const std::string& reason) {
    try {
      r.fail(key, reason);
    } catch (const InputError& e) {
      throw EngineRefusal(e, key, reason);
    }
  };
  if (uses(physics::ModelKind::ode) && s.dt < std::numeric_limits<double>::min())
    refuse("time.dt", "ODE cannot step by a subnormal dt (below " +
                          format_number(std::numeric_limits<double>::min()) + ", got " +
                          format_number(s.dt) + "): its quaternion update cannot normalize");
  constexpr double kMujocoMinVal = 1e-15;  // MuJoCo's mjMINVAL (mjmodel.h)
  if (uses(physics::ModelKind::mujoco)) {
    const double smallest = s.body.moments.minCoeff();
    const char* key = s.body.shape == physics::BodyShape::book ? "book.size" : "body.scale";
    if (s.body.cage.mass <= kMujocoMinVal)
      refuse(
          s.body.shape == physics::BodyShape::book ? "book.mass" : "body.mass",
          "MuJoCo needs a mass above its mjMINVAL (1e-15), got " + format_number(s.body.cage.mass));
    if (smallest <= kMujocoMinVal)
      refuse(key,
             "MuJoCo needs every principal moment above its mjMINVAL (1e-15); this body's "
             "smallest is " +
                 format_number(smallest) + " (a larger or heavier body)");
  }
}

/// A negative quadratic rate (a gain) blows up at t = −1/r: the run must end before it
/// (docs/physics.md §21). Checked for the scene's model and every [[compare]] tile's.
void check_drag(TomlReader& r, const Scene& s) {
  const double end = s.dt * s.steps_per_frame * (s.frames - 1);
  std::vector<physics::Drag> drags{s.model.drag};
  for (const CompareTile& tile : s.compare) drags.push_back(tile.model.drag);
  for (const physics::Drag& drag : drags)
    if (!physics::drag_defined_until(drag, 2.0 * end))
      r.fail("model.drag_rate", "a negative quadratic rate " + format_number(drag.rate) +
                                    " blows up at t = " + format_number(-1.0 / drag.rate) +
                                    ", within twice the run (" + format_number(end) + ")");
}

Scene build_scene(const toml::table& root, const std::filesystem::path& origin,
                  const std::set<std::string>& overridden) {
  TomlReader r(root, origin.string(), overridden);
  Scene s;
  s.source = origin;
  read_identity(r, s);
  s.model = read_model(r, physics::ModelConfig{});
  read_body(r, s, origin);
  read_spin(r, s);
  s.initial.jiggle = r.number(limit("initial.jiggle"));
  s.initial.seed = static_cast<std::uint64_t>(r.integer(limit("initial.seed")));
  read_time(r, s);
  s.render = read_render(r, origin);
  s.compare = read_compare(r, origin.string(), overridden, s.model);
  s.measured = read_measured(r, origin);
  r.reject_unknown_keys();
  check_lattice_cells(r, s);
  if (s.render.poinsot && !s.compare.empty())
    r.fail("render.poinsot", "Poinsot's construction is for a single run, not a [[compare]] scene");
  // The invariable plane is normal to L (docs/physics.md §16): a body at rest has none.
  if (s.render.poinsot && s.initial.omega0_body.isZero(0.0) && s.initial.jiggle == 0.0)
    r.fail("render.poinsot",
           "Poinsot's construction needs a spinning body, but initial.angular_velocity is "
           "[0, 0, 0] and initial.jiggle is 0 (at rest: L = 0)");
  check_caption_twist(r, s);
  check_engine_limits(r, s);
  check_drag(r, s);
  return s;
}

}  // namespace

Scene tile_scene(const Scene& scene, const CompareTile& panel) {
  Scene s = scene;
  s.name = scene.name + "-" + panel.name;
  s.title = panel.label;
  s.model = panel.model;
  s.compare.clear();
  return s;
}

Scene parse_scene_text(std::string_view text, const std::filesystem::path& origin,
                       const std::vector<std::string>& overrides) {
  if (const auto nul = nul_byte_problem(text)) throw InputError(origin.string() + ": " + *nul);
  toml::table root;
  try {
    const std::string origin_name = origin.string();
    root = toml::parse(text, std::string_view(origin_name));
  } catch (const toml::parse_error& e) {
    throw InputError(escape_controls(origin.string()) + ":" +
                     std::to_string(e.source().begin.line) +
                     ": TOML syntax error: " + escape_controls(describe_syntax_error(e, text)));
  }
  // Valid TOML, and every key has a default, but a file with no keys at all is almost
  // certainly a mistake (a truncated copy, the wrong file), not a request for the defaults.
  if (root.empty()) throw InputError(origin.string() + ": scene file is empty (no keys)");
  std::set<std::string> overridden;
  for (const auto& assignment : overrides) overridden.insert(apply_override(root, assignment));
  return build_scene(root, origin, overridden);
}

Scene parse_scene(const std::filesystem::path& path, const std::vector<std::string>& overrides) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw InputError(path.string() + ": is a directory, not a scene file");
  }
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw InputError(path.string() + ": scene file not found");
  }
  const auto size = std::filesystem::file_size(path, ec);
  if (ec || size > kMaxSceneFileBytes) {
    throw InputError(path.string() + ": scene file is larger than " +
                     std::to_string(kMaxSceneFileBytes) + " bytes");
  }
  return parse_scene_text(read_text_file(path, "the scene file"), path, overrides);
}

}  // namespace bookspin::scene
