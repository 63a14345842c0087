// The typeface built in: every face from Debian's DejaVu 2.37 files and the fallbacks (Droid Sans
// Fallback, Symbola), their bytes whole, and the text options set in code (the picture tests
// under another machine's text set-up are Pictures.SameUnderAnotherTextSetUp,
// tests/CMakeLists.txt).
#include "typeface/typeface.hpp"

#include <cairo.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <string>

#include "common/sha256.hpp"
#include "typeface/embedded_fonts.hpp"

namespace bookspin::typeface {
namespace {

TEST(Typeface, EveryFaceIsDejaVu237ThenTheFallbacksBuiltInWhole) {
  const auto list = faces();
  ASSERT_EQ(list.size(), 8u);
  const char* names[] = {
      "DejaVu Sans",       "DejaVu Sans Bold",    "DejaVu Sans Mono",    "DejaVu Serif",
      "DejaVu Serif Bold", "DejaVu Serif Italic", "Droid Sans Fallback", "Symbola"};
  for (std::size_t i = 0; i < list.size(); ++i) {
    EXPECT_EQ(list[i].name, names[i]);
    if (i < 6) {
      EXPECT_EQ(list[i].version, "Version 2.37") << list[i].file;
    }
    EXPECT_FALSE(list[i].version.empty()) << list[i].file;
  }
  for (const EmbeddedFont& font : embedded_fonts()) {
    // The bytes built in hash to what the configure step read, and are the file's own.
    EXPECT_EQ(sha256_text({reinterpret_cast<const char*>(font.data), font.size}), font.sha256)
        << font.file;
    std::ifstream in(font.source_path, std::ios::binary);
    if (!in) continue;  // built elsewhere: the hash above is the check
    const std::string bytes{std::istreambuf_iterator<char>(in), {}};
    EXPECT_EQ(bytes.size(), font.size) << font.source_path;
    EXPECT_TRUE(bytes == std::string(reinterpret_cast<const char*>(font.data), font.size))
        << font.source_path;
  }
}

struct Context {
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 400, 60);
  cairo_t* cr = cairo_create(surface);
  ~Context() {
    cairo_destroy(cr);
    cairo_surface_destroy(surface);
  }
};

TEST(Typeface, TheOptionsAreSetOnTheContextNotTakenFromTheMachine) {
  Context c;
  select(c.cr, Face::sans, 20);
  cairo_font_options_t* options = cairo_font_options_create();
  cairo_get_font_options(c.cr, options);
  EXPECT_EQ(cairo_font_options_get_antialias(options), CAIRO_ANTIALIAS_GRAY);
  EXPECT_EQ(cairo_font_options_get_hint_style(options), CAIRO_HINT_STYLE_SLIGHT);
  EXPECT_EQ(cairo_font_options_get_hint_metrics(options), CAIRO_HINT_METRICS_ON);
  EXPECT_EQ(cairo_font_options_get_subpixel_order(options), CAIRO_SUBPIXEL_ORDER_DEFAULT);
  cairo_font_options_destroy(options);
  EXPECT_EQ(cairo_font_face_get_type(cairo_get_font_face(c.cr)), CAIRO_FONT_TYPE_FT);
  const std::string words = text_options();
  EXPECT_NE(words.find("hint style slight"), std::string::npos) << words;
  EXPECT_NE(words.find("no fontconfig"), std::string::npos) << words;
}

// DejaVu Sans' digits are 1303/2048 em wide (the font's hmtx); with metrics hinted, each
// advance is rounded to whole pixels: ten "0" at 20 px are 10 × round(12.72) = 130 px, not 127.2.
TEST(Typeface, DigitAdvancesAreTheFontsRoundedToWholePixels) {
  Context c;
  select(c.cr, Face::sans, 20);
  cairo_text_extents_t e;
  cairo_text_extents(c.cr, "0000000000", &e);
  EXPECT_DOUBLE_EQ(e.x_advance, 10 * std::round(20.0 * 1303 / 2048));
  select(c.cr, Face::sans, 31);
  cairo_text_extents(c.cr, "0000000000", &e);
  EXPECT_DOUBLE_EQ(e.x_advance, 10 * std::round(31.0 * 1303 / 2048));
}

TEST(Typeface, FacesDrawDifferentlyAndTheSameTextTheSameWay) {
  const auto draw = [](Face face) {
    Context c;
    cairo_set_source_rgb(c.cr, 1, 1, 1);
    cairo_paint(c.cr);
    cairo_set_source_rgb(c.cr, 0, 0, 0);
    select(c.cr, face, 24);
    cairo_move_to(c.cr, 4, 40);
    cairo_show_text(c.cr, "Face mapping: t = 0.0");
    cairo_surface_flush(c.surface);
    const unsigned char* data = cairo_image_surface_get_data(c.surface);
    return std::string(reinterpret_cast<const char*>(data),
                       static_cast<std::size_t>(cairo_image_surface_get_stride(c.surface)) * 60);
  };
  const std::string sans = draw(Face::sans);
  EXPECT_EQ(sans, draw(Face::sans));
  for (Face other :
       {Face::sans_bold, Face::sans_mono, Face::serif, Face::serif_bold, Face::serif_italic})
    EXPECT_NE(sans, draw(other)) << static_cast<int>(other);
}

}  // namespace
}  // namespace bookspin::typeface
