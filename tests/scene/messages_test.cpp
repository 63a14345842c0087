// Messages that say what is wrong: one line whatever the value holds (control characters
// escaped), and a body too small to frame refused by the scene check, naming its key.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "scene/scene.hpp"
#include "scene_text.hpp"
#include "support/mesh_files.hpp"
#include "support/scratch.hpp"

namespace bookspin::scene {
namespace {

namespace fs = std::filesystem;
using testing::error_of;

/// Whether `text` holds a byte a terminal acts on: C0 controls, DEL, or a C1 control in UTF-8.
bool has_control(const std::string& text) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto u = static_cast<unsigned char>(text[i]);
    if (u < 0x20 || u == 0x7f) return true;
    if (u == 0xc2 && i + 1 < text.size() && static_cast<unsigned char>(text[i + 1]) >= 0x80 &&
        static_cast<unsigned char>(text[i + 1]) <= 0x9f)
      return true;
  }
  return false;
}

std::string error_with_overrides(const std::string& text, const std::vector<std::string>& sets) {
  try {
    parse_scene_text(text, "test.toml", sets);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Messages, ControlCharactersInAValueAreEscaped) {
  // TOML's escapes put a newline, a tab, ESC (a colour sequence) and CSI (U+009B) in the name.
  const std::string name_error = error_of("[scene]\nname = \"a\\nb\\tc\\u001b[31md\\u009b2J\"\n");
  EXPECT_EQ(name_error,
            "test.toml:2: scene.name: 'a\\nb\\tc\\x1b[31md\\u009b2J' is not a safe output name: "
            "it must not hold / \\ : * ? \" < > | or a control character");
  const std::string kind_error = error_of("[model]\nkind = \"rk4\\r\\u007f\"\n");
  EXPECT_NE(kind_error.find("unknown model 'rk4\\r\\x7f'"), std::string::npos) << kind_error;
  EXPECT_FALSE(has_control(kind_error)) << kind_error;
  // The same through --set: the value, and an assignment without '='.
  const std::string set_error =
      error_with_overrides("[time]\nframes = 2\n", {"render.codec=\"x\\n264\""});
  EXPECT_EQ(set_error.rfind("--set render.codec: unknown codec 'x\\n264'", 0), 0u) << set_error;
  const std::string no_equals = error_with_overrides("[time]\nframes = 2\n", {"time.dt\n0.1"});
  EXPECT_EQ(no_equals, "--set time.dt\\n0.1: expected key=value, e.g. time.dt=0.01");
  for (const std::string& e : {name_error, kind_error, set_error, no_equals})
    EXPECT_FALSE(has_control(e)) << e;
  // Printable text beyond ASCII is kept as it is.
  EXPECT_NE(error_of("[model]\nkind = \"Präzession\"\n").find("'Präzession'"), std::string::npos);
}

/// A closed box a × b × c (tests/support), written to `dir/name`.
fs::path write_box(const fs::path& dir, const std::string& name, const test::Point& size) {
  test::write_box_obj(dir / name, size);
  return dir / name;
}

std::string mesh_scene(const fs::path& mesh, const std::string& scale) {
  return "[model]\nkind = \"rigid-matrix\"\n[body]\nshape = \"mesh\"\nmesh = \"" + mesh.string() +
         "\"\nscale = " + scale + "\n";
}

TEST(Messages, ABodyTooSmallToFrameIsRefusedNamingItsKey) {
  const fs::path dir = test::fresh_dir("messages_test/size");
  // A box's principal axes are its edges and its centre of mass its centre, so the box that
  // holds it in its principal frame is the box itself: 3e-30 along its longest side.
  const fs::path tiny = write_box(dir, "tiny.obj", {1e-30f, 2e-30f, 3e-30f});
  EXPECT_EQ(error_of(mesh_scene(tiny, "1.0")),
            "test.toml:5: body.mesh: " + tiny.string() +
                ": the body is 3e-30 across at body.scale = 1 (the longest side of the box that "
                "holds it); a body must be at least 1e-06 across for the camera to frame it");
  // The bound holds for the body as scaled: 0.2 × 0.3 × 0.4 at body.scale 2e-6 is 8e-7 across,
  // at 3e-6 it is 1.2e-6.
  const fs::path small = write_box(dir, "small.obj", {0.2f, 0.3f, 0.4f});
  EXPECT_NE(
      error_of(mesh_scene(small, "2e-6")).find("the body is 8e-07 across at body.scale = 2e-06 "),
      std::string::npos);
  EXPECT_EQ(error_of(mesh_scene(small, "3e-6")), "");
  // A value just below the bound is not printed as the bound.
  const std::string edge = error_of(
      mesh_scene(write_box(dir, "edge.obj", {0.5e-6f, 0.5e-6f, 0.99999999999e-6f}), "1.0"));
  const auto at = edge.find("the body is ");
  ASSERT_NE(at, std::string::npos) << edge;
  EXPECT_LT(std::strtod(edge.c_str() + at + 12, nullptr), 1e-6) << edge;
  // Every preset at the smallest body.scale, and the smallest book, are large enough.
  for (const char* shape : {"t-handle", "tennis-racket", "phone"})
    EXPECT_EQ(error_of(std::string("[model]\nkind = \"exact\"\n[body]\nshape = \"") + shape +
                       "\"\nscale = 1e-6\n"),
              "")
        << shape;
  EXPECT_EQ(error_of("[book]\nsize = [1e-6, 1e-6, 1e-6]\nmass = 1.0\n"), "");
}

}  // namespace
}  // namespace bookspin::scene
