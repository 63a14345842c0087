// The text layout (src/typeface/text_layout.hpp): text in any alphabet drawn by the pixels it
// makes, against cairo's own calls: Latin, Greek and Cyrillic the bytes cairo draws; CJK and an
// emoji their own glyphs, not the missing-glyph box; Arabic joined and right to left; a mixed
// line its pieces end to end; the extents the ink drawn; and the layout as a value, where its
// pieces go: right-to-left runs in visual order as a whole, marks above or below their letters.
#include "typeface/text_layout.hpp"

#include <cairo.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <string>
#include <vector>

#include "typeface/built_in.hpp"
#include "typeface/typeface.hpp"

namespace bookspin::typeface {
namespace {

constexpr int kWidth = 700, kHeight = 100;
constexpr double kSize = 40, kX = 20, kY = 65;

// A white picture with black text drawn by `draw` from (kX, kY) in DejaVu Sans at kSize px.
struct Picture {
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, kWidth, kHeight);
  cairo_t* cr = cairo_create(surface);
  double end_x = 0, end_y = 0;  // the current point after drawing
  explicit Picture(const std::function<void(cairo_t*)>& draw, Face face = Face::sans) {
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    select(cr, face, kSize);
    cairo_move_to(cr, kX, kY);
    draw(cr);
    cairo_get_current_point(cr, &end_x, &end_y);
    EXPECT_EQ(cairo_status(cr), CAIRO_STATUS_SUCCESS);
    cairo_surface_flush(surface);
  }
  ~Picture() {
    cairo_destroy(cr);
    cairo_surface_destroy(surface);
  }
  Picture(const Picture&) = delete;
  Picture& operator=(const Picture&) = delete;
  std::string bytes() const {
    return std::string(reinterpret_cast<const char*>(cairo_image_surface_get_data(surface)),
                       static_cast<std::size_t>(cairo_image_surface_get_stride(surface)) * kHeight);
  }
  // Ink: a pixel darker than mid-grey (the blue byte of ARGB32; the text is black on white).
  bool ink(int x, int y) const {
    const unsigned char* row =
        cairo_image_surface_get_data(surface) +
        static_cast<std::ptrdiff_t>(y) * cairo_image_surface_get_stride(surface);
    return row[4 * x] < 128;
  }
  // Any ink at all: a pixel not white.
  bool touched(int x, int y) const {
    const unsigned char* row =
        cairo_image_surface_get_data(surface) +
        static_cast<std::ptrdiff_t>(y) * cairo_image_surface_get_stride(surface);
    return row[4 * x] < 255;
  }
  struct Box {
    int left = kWidth, top = kHeight, right = -1, bottom = -1;  // inclusive pixel bounds
  };
  // The box of every touched pixel in columns [from, to).
  Box ink_box(int from = 0, int to = kWidth) const {
    Box b;
    for (int y = 0; y < kHeight; ++y)
      for (int x = from; x < to; ++x)
        if (touched(x, y)) {
          b.left = std::min(b.left, x), b.right = std::max(b.right, x);
          b.top = std::min(b.top, y), b.bottom = std::max(b.bottom, y);
        }
    return b;
  }
  // The 8-connected groups of ink pixels.
  int components() const {
    std::vector<char> seen(static_cast<std::size_t>(kWidth * kHeight), 0);
    int count = 0;
    for (int y0 = 0; y0 < kHeight; ++y0)
      for (int x0 = 0; x0 < kWidth; ++x0) {
        if (!ink(x0, y0) || seen[static_cast<std::size_t>(y0 * kWidth + x0)]) continue;
        ++count;
        std::vector<std::pair<int, int>> stack{{x0, y0}};
        seen[static_cast<std::size_t>(y0 * kWidth + x0)] = 1;
        while (!stack.empty()) {
          const auto [x, y] = stack.back();
          stack.pop_back();
          for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
              const int nx = x + dx, ny = y + dy;
              if (nx < 0 || ny < 0 || nx >= kWidth || ny >= kHeight) continue;
              auto& s = seen[static_cast<std::size_t>(ny * kWidth + nx)];
              if (s || !ink(nx, ny)) continue;
              s = 1;
              stack.push_back({nx, ny});
            }
        }
      }
    return count;
  }
};

std::function<void(cairo_t*)> shown(const std::string& text) {
  return [text](cairo_t* cr) { show_text(cr, text.c_str()); };
}
std::function<void(cairo_t*)> shown_by_cairo(const std::string& text) {
  return [text](cairo_t* cr) { cairo_show_text(cr, text.c_str()); };
}
std::function<void(cairo_t*)> filled_path(const std::string& text) {
  return [text](cairo_t* cr) {
    text_path(cr, text.c_str());
    double x = 0, y = 0;
    cairo_get_current_point(cr, &x, &y);
    cairo_fill(cr);
    cairo_move_to(cr, x, y);
  };
}

const char* const kArabic = "الكتاب";  // al-kitāb, "the book": ا ل ك ت ا ب
const char* const kMixed = "太郎 الكتاب 🎲, toss 1";

// Every text the pictures draw today is in DejaVu, left to right and unshaped: drawn, measured
// and outlined by cairo's own calls, byte for byte (the goldens hold).
TEST(TextLayout, LatinGreekCyrillicAreCairosOwnBytes) {
  for (const std::string text :
       {"time (s, phone's clock)", "toss 1: measured (dots) and fitted exact motion",
        "ω₁ = 2.5 rad/s, Ω λ", "Жук über dem Bett", "t = 0.0 s · |L| ≈ 1"}) {
    for (const Face face : {Face::sans, Face::sans_bold, Face::serif_italic}) {
      const Picture ours(shown(text), face), cairos(shown_by_cairo(text), face);
      EXPECT_TRUE(ours.bytes() == cairos.bytes()) << text;
      EXPECT_EQ(ours.end_x, cairos.end_x) << text;
      const Picture our_path(filled_path(text), face);
      const Picture cairo_path(
          [&](cairo_t* cr) {
            cairo_text_path(cr, text.c_str());
            cairo_fill(cr);
          },
          face);
      EXPECT_TRUE(our_path.bytes() == cairo_path.bytes()) << text;
      Picture measure([](cairo_t*) {}, face);
      cairo_text_extents_t a, b;
      text_extents(measure.cr, text.c_str(), &a);
      cairo_text_extents(measure.cr, text.c_str(), &b);
      EXPECT_EQ(a.x_bearing, b.x_bearing) << text;
      EXPECT_EQ(a.y_bearing, b.y_bearing) << text;
      EXPECT_EQ(a.width, b.width) << text;
      EXPECT_EQ(a.height, b.height) << text;
      EXPECT_EQ(a.x_advance, b.x_advance) << text;
    }
  }
}

// DejaVu has no CJK nor emoji: alone it draws each as the same missing-glyph box. Drawn through
// the fallbacks, every character is its own glyph: distinct from every other and from the box
// of a character no face has (a private-use one).
TEST(TextLayout, CjkAndEmojiAreTheirOwnGlyphsNotBoxes) {
  const std::vector<std::string> characters{"太", "郎", "花", "子", "🎲"};
  const Picture box(shown("\U0010FFFD"));
  ASSERT_GT(box.ink_box().right, 0);  // the box is drawn: there is something to differ from
  std::vector<std::string> drawn;
  for (const std::string& c : characters) {
    const Picture p(shown(c));
    EXPECT_GE(p.ink_box().right, 0) << c;
    EXPECT_FALSE(p.bytes() == box.bytes()) << c << " is drawn as the missing-glyph box";
    drawn.push_back(p.bytes());
  }
  for (std::size_t i = 0; i < drawn.size(); ++i)
    for (std::size_t j = i + 1; j < drawn.size(); ++j)
      EXPECT_FALSE(drawn[i] == drawn[j]) << characters[i] << " and " << characters[j];
  // The words too: 太郎 and 花子 differ, as their letters do.
  EXPECT_FALSE(Picture(shown("太郎")).bytes() == Picture(shown("花子")).bytes());
}

// الكتاب joined: alef does not join the letter after it, so the word is three bodies (ا, لكتا,
// ب) and the dots; drawn letter by letter (cairo's own call, no shaping) it is six bodies.
TEST(TextLayout, ArabicIsJoined) {
  const Picture joined(shown(kArabic)), apart(shown_by_cairo(kArabic));
  EXPECT_LT(joined.components(), apart.components())
      << "joined " << joined.components() << ", letter by letter " << apart.components();
  // Joined forms are narrower than the isolated ones.
  EXPECT_LT(joined.end_x, apart.end_x);
}

// Right to left: the first letter (alef, a tall stem) is drawn rightmost, the last (ba, a bowl
// with a dot below the baseline) leftmost.
TEST(TextLayout, ArabicReadsRightToLeft) {
  const Picture p(shown(kArabic));
  const auto all = p.ink_box();
  const int fifth = (all.right - all.left + 1) / 5;
  const auto left = p.ink_box(all.left, all.left + fifth);
  const auto right = p.ink_box(all.right + 1 - fifth, all.right + 1);
  EXPECT_LT(right.top, left.top - kSize / 5) << "the rightmost letter is not alef's stem";
  EXPECT_GT(left.bottom, kY + 2) << "the leftmost letter is not ba, its dot under the line";
}

// A line of several alphabets is its pieces laid end to end (the layout's advances and current
// point), the CJK left of the Arabic, the Arabic left of the die.
TEST(TextLayout, MixedLineIsItsPiecesEndToEnd) {
  const std::vector<std::string> pieces{"太郎 ", kArabic, " 🎲, toss 1"};
  const Picture whole(shown(kMixed));
  const Picture laid([&](cairo_t* cr) {
    for (const std::string& piece : pieces) show_text(cr, piece.c_str());
  });
  EXPECT_TRUE(whole.bytes() == laid.bytes());
  EXPECT_NEAR(whole.end_x, laid.end_x, 1e-9);
  cairo_text_extents_t e;
  text_extents(whole.cr, kMixed, &e);
  double sum = 0;
  for (const std::string& piece : pieces) {
    cairo_text_extents_t p;
    text_extents(whole.cr, piece.c_str(), &p);
    sum += p.x_advance;
  }
  EXPECT_NEAR(e.x_advance, sum, 1e-9);
  EXPECT_NEAR(whole.end_x, kX + e.x_advance, 1e-9);
}

// What text_extents says is what show_text and text_path draw: the ink box within a pixel of
// the extents' box (antialiasing touches the pixel the outline enters), the current point the
// advance.
TEST(TextLayout, ExtentsAreTheInkDrawn) {
  for (const std::string& text : {std::string("太郎"), std::string("花子"), std::string("🎲"),
                                  std::string(kArabic), std::string(kMixed)}) {
    for (const auto& draw : {shown(text), filled_path(text)}) {
      const Picture p(draw);
      cairo_text_extents_t e;
      text_extents(p.cr, text.c_str(), &e);
      const auto box = p.ink_box();
      EXPECT_NEAR(box.left, kX + e.x_bearing, 1.0) << text;
      EXPECT_NEAR(box.right + 1, kX + e.x_bearing + e.width, 1.0) << text;
      EXPECT_NEAR(box.top, kY + e.y_bearing, 1.0) << text;
      EXPECT_NEAR(box.bottom + 1, kY + e.y_bearing + e.height, 1.0) << text;
      EXPECT_NEAR(p.end_x, kX + e.x_advance, 1e-9) << text;
      EXPECT_EQ(p.end_y, kY) << text;
    }
  }
}

// The layout as a value is what show_text draws: the same bytes, the same current point.
TEST(TextLayout, LaidOutTextDrawsAsShowText) {
  for (const std::string& text : {std::string("time (s)"), std::string(kArabic),
                                  std::string(kMixed), std::string("\u05e1\u05e4\u05e8 12")}) {
    const Picture direct(shown(text));
    const Picture laid([&](cairo_t* cr) { show_laid_out(cr, lay_out_text(cr, text.c_str())); });
    EXPECT_TRUE(direct.bytes() == laid.bytes()) << text;
    EXPECT_EQ(direct.end_x, laid.end_x) << text;
  }
}

// Every glyph of `text` whose cluster lies in bytes [from, to): its x (user units).
std::vector<double> xs_of(const LaidOutText& text, std::size_t from, std::size_t to) {
  std::vector<double> xs;
  for (const GlyphRun& run : text.runs)
    for (const PlacedGlyph& g : run.glyphs)
      if (g.cluster >= from && g.cluster < to) xs.push_back(g.x);
  return xs;
}

// A right-to-left stretch of two or more runs (an Arabic or Hebrew word, then a number) is
// reversed as a whole within the left-to-right line: the number left of the word, its digits
// still left to right, the line's English words where they were.
TEST(TextLayout, RightToLeftRunsAreReversedAsAWhole) {
  const std::string hebrew = "\u05e1\u05e4\u05e8";  // "book"
  for (const std::string& word : {std::string(kArabic), hebrew}) {
    for (const std::string& before : {std::string(), std::string("toss ")}) {
      const std::string after = before.empty() ? "" : " ends";
      const std::string text = before + word + " 12" + after;
      Picture measure([](cairo_t*) {});
      const LaidOutText laid = lay_out_text(measure.cr, text.c_str());
      ASSERT_FALSE(laid.whole) << text;
      const std::size_t w0 = before.size(), w1 = w0 + word.size(), n0 = w1 + 1;
      const std::vector<double> word_x = xs_of(laid, w0, w1), one = xs_of(laid, n0, n0 + 1),
                                two = xs_of(laid, n0 + 1, n0 + 2);
      ASSERT_FALSE(word_x.empty() || one.size() != 1 || two.size() != 1) << text;
      const double word_left = *std::min_element(word_x.begin(), word_x.end());
      EXPECT_LT(two[0], word_left) << text << ": the number is not left of the word";
      EXPECT_LT(one[0], two[0]) << text << ": 12 is drawn 21";
      if (before.empty()) continue;
      const std::vector<double> toss = xs_of(laid, 0, w0), ends = xs_of(laid, n0 + 3, text.size());
      const double word_right = *std::max_element(word_x.begin(), word_x.end());
      EXPECT_LT(*std::max_element(toss.begin(), toss.end()), one[0]) << text;
      EXPECT_GT(*std::min_element(ends.begin(), ends.end()), word_right) << text;
    }
  }
}

// A glyph's ink box as drawn (user units: left, top, right, bottom; y down).
struct Ink {
  double left, top, right, bottom;
};
Ink ink_of(cairo_t* cr, const GlyphRun& run, const PlacedGlyph& g) {
  cairo_save(cr);
  cairo_set_font_face(cr, built_in_face(run.face));
  const cairo_glyph_t glyph{g.index, g.x, g.y};
  cairo_text_extents_t e;
  cairo_glyph_extents(cr, &glyph, 1, &e);
  cairo_restore(cr);
  return {g.x + e.x_bearing, g.y + e.y_bearing, g.x + e.x_bearing + e.width,
          g.y + e.y_bearing + e.height};
}

// The glyph index `code` has in built-in face `face` (its cmap), or 0.
unsigned long nominal_glyph(cairo_t* cr, std::size_t face, const std::string& code) {
  cairo_save(cr);
  cairo_set_font_face(cr, built_in_face(face));
  cairo_glyph_t* glyphs = nullptr;
  int count = 0;
  cairo_scaled_font_text_to_glyphs(cairo_get_scaled_font(cr), 0, 0, code.c_str(),
                                   static_cast<int>(code.size()), &glyphs, &count, nullptr, nullptr,
                                   nullptr);
  const unsigned long index = count == 1 ? glyphs[0].index : 0;
  cairo_glyph_free(glyphs);
  cairo_restore(cr);
  return index;
}

// A shaped mark sits where its letter's anchor puts it, HarfBuzz's offset up drawn up (cairo's
// y grows down): a circumflex, an Arabic fatha or damma wholly above its letter's ink; a Hebrew
// point or an Arabic kasra wholly under the baseline. Some of them HarfBuzz moves from where
// the mark's glyph is drawn alone (a vertical offset): a sign taken the wrong way round moves
// those through their letters.
TEST(TextLayout, MarksSitAboveOrBelowTheirLetters) {
  struct Case {
    std::string base, mark;
    bool above;
  };
  const std::vector<Case> cases{
      {"x", "\u0302", true},       {"X", "\u0302", true},       {"\u0436", "\u0302", true},
      {"\u0628", "\u064e", true},  {"\u0628", "\u064f", true},  {"\u0628", "\u0650", false},
      {"\u05d1", "\u05b0", false}, {"\u05d3", "\u05b7", false}, {"\u05e7", "\u05b8", false},
      {"\u05e0", "\u05b4", false},
  };
  Picture measure([](cairo_t*) {});
  cairo_t* cr = measure.cr;
  int moved = 0;  // marks HarfBuzz moved vertically: the cases that can see a sign taken wrong
  for (const Case& c : cases) {
    const std::string text = c.base + c.mark;
    const LaidOutText laid = lay_out_text(cr, text.c_str());
    ASSERT_EQ(laid.runs.size(), 1u) << text;
    const GlyphRun& run = laid.runs[0];
    // The letter's glyph is its own (cmap); the mark's may be a variant (over a capital).
    ASSERT_EQ(run.glyphs.size(), 2u) << text;
    const unsigned long base_glyph = nominal_glyph(cr, run.face, c.base);
    const PlacedGlyph *base = nullptr, *mark = nullptr;
    for (const PlacedGlyph& g : run.glyphs) (g.index == base_glyph ? base : mark) = &g;
    ASSERT_TRUE(base != nullptr && mark != nullptr) << text << ": not a letter and its mark";
    EXPECT_EQ(base->cluster, 0u) << text;
    if (mark->y != 0) ++moved;
    const Ink letter = ink_of(cr, run, *base), point = ink_of(cr, run, *mark);
    // Over the letter, not beside it.
    EXPECT_LT(point.left, letter.right) << text;
    EXPECT_GT(point.right, letter.left) << text;
    if (c.above) {
      EXPECT_LE(point.bottom, letter.top + 0.02 * kSize)
          << text << ": the mark is not above its letter (" << point.bottom
          << " vs the letter's top " << letter.top << ")";
    } else {
      EXPECT_GE(point.top, -0.02 * kSize)
          << text << ": the point is not under the baseline (its top " << point.top << ")";
    }
  }
  EXPECT_GT(moved, 0) << "no mark is moved vertically: the cases cannot see the offset's sign";
}

// The same two faults seen in the pixels drawn, not the layout's values: in "الكتاب 12" the
// number is drawn first, at the left, exactly as "12" alone draws it (its columns the same
// bytes); a circumflex over X inks rows above X's own top, a kasra under ب rows below ب's own
// bottom.
TEST(TextLayout, TheNumberAndTheMarksInkWhereTheyBelong) {
  const std::string number = "12";
  for (const std::string& word : {std::string(kArabic), std::string("\u05e1\u05e4\u05e8")}) {
    const Picture whole(shown(word + " " + number)), alone(shown(number));
    const auto digits = alone.ink_box();
    ASSERT_GE(digits.right, digits.left);
    const Picture::Box left = whole.ink_box(0, digits.right + 1);
    EXPECT_EQ(left.left, digits.left) << word;
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x <= digits.right; ++x)
        ASSERT_EQ(whole.touched(x, y), alone.touched(x, y))
            << word << " 12: the number is not drawn at the left (" << x << ", " << y << ")";
  }
  const Picture capital(shown("X")), accented(shown("X\u0302"));
  EXPECT_LT(accented.ink_box().top, capital.ink_box().top - kSize / 10)
      << "no circumflex above the X";
  const Picture ba(shown("\u0628")), kasra(shown("\u0628\u0650"));
  EXPECT_GT(kasra.ink_box().bottom, ba.ink_box().bottom + kSize / 20) << "no kasra under the ba";
}

}  // namespace
}  // namespace bookspin::typeface
