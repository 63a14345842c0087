// A text laid out once and drawn from its value (src/overlay/cairo_canvas.hpp's
// draw_placed_text, as the plots draw their labels) against the text layout's own show_text:
// the same bytes, in any alphabet, face, size and turn, from any point.
#include "overlay/cairo_canvas.hpp"

#include <cairo.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "typeface/text_layout.hpp"
#include "typeface/typeface.hpp"

namespace bookspin::overlay {
namespace {

constexpr int kSide = 240;

// A white square with `draw` done on it in black; its bytes.
template <typename Draw>
std::string drawn(Draw draw) {
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, kSide, kSide);
  cairo_t* cr = cairo_create(surface);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  draw(cr);
  EXPECT_EQ(cairo_status(cr), CAIRO_STATUS_SUCCESS);
  cairo_surface_flush(surface);
  const std::string bytes(
      reinterpret_cast<const char*>(cairo_image_surface_get_data(surface)),
      static_cast<std::size_t>(cairo_image_surface_get_stride(surface)) * kSide);
  cairo_destroy(cr);
  cairo_surface_destroy(surface);
  return bytes;
}

TEST(CairoCanvas, APlacedTextIsWhatShowTextDraws) {
  const std::vector<std::string> texts{"time (s, phone's clock)",
                                       "\u03c9 (rad / time unit)",
                                       "-2.5e+06",
                                       "\u0627\u0644\u0643\u062a\u0627\u0628 12",
                                       "\u592a\u90ce \U0001F3B2, toss 1",
                                       "X\u0302 x\u0302 \u05d1\u05b0 \u0628\u0650"};
  int differ = 0;
  for (const std::string& text : texts)
    for (const typeface::Face face : {typeface::Face::sans, typeface::Face::sans_bold})
      for (const double size : {12.0, 17.3})
        for (const double angle : {0.0, -M_PI / 2}) {
          const double x = 120.4, y = 130.7, origin_x = -61.3, origin_y = 3.45;
          const std::string shown = drawn([&](cairo_t* cr) {
            cairo_translate(cr, x, y);
            cairo_rotate(cr, angle);
            typeface::select(cr, face, size);
            cairo_set_source_rgb(cr, 0, 0, 0);
            cairo_move_to(cr, origin_x, origin_y);
            typeface::show_text(cr, text.c_str());
          });
          const std::string placed = drawn([&](cairo_t* cr) {
            const std::vector<typeface::LaidOutText> laid =
                typeface::lay_out_texts(cr, {{text, face, size, angle, 0}});
            draw_placed_text(cr, {&laid[0], x, y, angle, origin_x, origin_y, 0, 0, 0});
          });
          if (shown != placed) ++differ;
          EXPECT_TRUE(shown == placed) << text << " at " << size << " px, turned " << angle;
        }
  EXPECT_EQ(differ, 0);
}

// A title wider than the width it may take is laid out again smaller: at its size times that
// width over its advance (hinting rounds each advance, so it fits only about); one that fits is
// laid out as it is.
TEST(CairoCanvas, ATitleLaidOutToAWidthFitsIt) {
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 1, 1);
  cairo_t* cr = cairo_create(surface);
  const std::string title = "Figure 9: rigid body with a rotation matrix, unstable spin about x";
  const auto laid = typeface::lay_out_texts(cr, {{title, typeface::Face::sans_bold, 16, 0, 0},
                                                 {title, typeface::Face::sans_bold, 16, 0, 200},
                                                 {title, typeface::Face::sans_bold, 16, 0, 1e6}});
  EXPECT_GT(laid[0].extents.x_advance, 200);
  EXPECT_EQ(laid[1].font_matrix.xx, 16 * 200 / laid[0].extents.x_advance);
  EXPECT_LT(laid[1].extents.x_advance, laid[0].extents.x_advance);
  EXPECT_NEAR(laid[1].extents.x_advance, 200, 0.1 * 200);
  EXPECT_EQ(laid[2].font_matrix.xx, 16);
  EXPECT_EQ(laid[2].extents.x_advance, laid[0].extents.x_advance);
  cairo_destroy(cr);
  cairo_surface_destroy(surface);
}

}  // namespace
}  // namespace bookspin::overlay
