#include "typeface/text_layout.hpp"

#include <fribidi.h>
#include <hb.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "common/errors.hpp"
#include "typeface/built_in.hpp"
#include "typeface/laid_out_text.hpp"
#include "typeface/typeface.hpp"

namespace bookspin::typeface {

namespace {

// The text's characters and where each starts in its UTF-8 (offset.size() == code.size() + 1).
struct Decoded {
  std::vector<std::uint32_t> code;
  std::vector<std::size_t> offset;
};

// Strict UTF-8 (no overlong forms, no surrogates, nothing above U+10FFFF), or nothing.
std::optional<Decoded> decode(std::string_view text) {
  Decoded d;
  std::size_t i = 0;
  while (i < text.size()) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
    const unsigned lead = byte(i);
    std::size_t length = 0;
    std::uint32_t c = 0, least = 0;
    if (lead < 0x80) {
      length = 1, c = lead;
    } else if ((lead & 0xE0) == 0xC0) {
      length = 2, c = lead & 0x1F, least = 0x80;
    } else if ((lead & 0xF0) == 0xE0) {
      length = 3, c = lead & 0x0F, least = 0x800;
    } else if ((lead & 0xF8) == 0xF0) {
      length = 4, c = lead & 0x07, least = 0x10000;
    } else {
      return std::nullopt;
    }
    if (i + length > text.size()) return std::nullopt;
    for (std::size_t k = 1; k < length; ++k) {
      if ((byte(i + k) & 0xC0) != 0x80) return std::nullopt;
      c = (c << 6) | (byte(i + k) & 0x3F);
    }
    if (c < least || c > 0x10FFFF || (c >= 0xD800 && c <= 0xDFFF)) return std::nullopt;
    d.code.push_back(c);
    d.offset.push_back(i);
    i += length;
  }
  d.offset.push_back(text.size());
  return d;
}

// HarfBuzz's fonts of the built-in files, read from the same bytes as the FreeType faces (and so
// the same glyph indices), by HarfBuzz's own OpenType functions: made once, immutable, shaped
// from any thread.
struct Shapers {
  std::array<hb_font_t*, kBuiltInFaces> font{};
  std::array<unsigned, kBuiltInFaces> units_per_em{};
};

const Shapers& shapers() {
  static const Shapers shapers = [] {
    Shapers s;
    for (std::size_t i = 0; i < kBuiltInFaces; ++i) {
      const EmbeddedFont& file = built_in_file(i);
      hb_blob_t* blob =
          hb_blob_create(reinterpret_cast<const char*>(file.data), static_cast<unsigned>(file.size),
                         HB_MEMORY_MODE_READONLY, nullptr, nullptr);
      hb_face_t* face = hb_face_create(blob, 0);
      hb_blob_destroy(blob);
      s.units_per_em[i] = hb_face_get_upem(face);
      s.font[i] = hb_font_create(face);
      hb_face_destroy(face);
      hb_font_make_immutable(s.font[i]);
      if (s.units_per_em[i] == 0)
        throw InternalError("the text layout: HarfBuzz cannot read the built-in " +
                            std::string(file.file));
    }
    return s;
  }();
  return shapers;
}

bool has_glyph(std::size_t face, std::uint32_t c) {
  hb_codepoint_t glyph = 0;
  return hb_font_get_nominal_glyph(shapers().font[face], c, &glyph) != 0;
}

hb_unicode_funcs_t* unicode() { return hb_unicode_funcs_get_default(); }

// A character that belongs with the one before it (a combining mark, a variation selector, a
// joiner, an emoji skin-tone modifier): drawn in that one's face.
bool clings(std::uint32_t c) {
  switch (hb_unicode_general_category(unicode(), c)) {
    case HB_UNICODE_GENERAL_CATEGORY_NON_SPACING_MARK:
    case HB_UNICODE_GENERAL_CATEGORY_SPACING_MARK:
    case HB_UNICODE_GENERAL_CATEGORY_ENCLOSING_MARK:
    case HB_UNICODE_GENERAL_CATEGORY_FORMAT:
      return true;
    default:
      return c >= 0x1F3FB && c <= 0x1F3FF;
  }
}

// Whether a character needs shaping: one of a script whose letters join, reorder or combine,
// or a mark, joiner or selector. Those of the scripts below, drawn one glyph a character
// left to right, do not.
bool needs_shaping(std::uint32_t c) {
  if (clings(c)) return true;
  switch (hb_unicode_script(unicode(), c)) {
    case HB_SCRIPT_COMMON:
    case HB_SCRIPT_LATIN:
    case HB_SCRIPT_GREEK:
    case HB_SCRIPT_CYRILLIC:
    case HB_SCRIPT_ARMENIAN:
    case HB_SCRIPT_GEORGIAN:
    case HB_SCRIPT_HAN:
    case HB_SCRIPT_HIRAGANA:
    case HB_SCRIPT_KATAKANA:
    case HB_SCRIPT_BOPOMOFO:
      return false;
    default:
      return true;
  }
}

// One run: characters [begin, end) of one bidirectional level, face and script, in logical
// order; `shaped` when HarfBuzz shapes it.
struct Run {
  std::size_t begin = 0, end = 0;
  std::size_t face = 0;
  FriBidiLevel level = 0;
  hb_script_t script = HB_SCRIPT_COMMON;
  bool shaped = false;
};

// Reorders runs from logical to visual order (the Unicode Bidirectional Algorithm, rule L2):
// from the highest level down to the lowest odd one, every sequence of runs at that level or
// above is reversed.
void reorder(std::vector<Run>& runs) {
  int highest = 0, lowest_odd = 1000;
  for (const Run& run : runs) {
    highest = std::max(highest, static_cast<int>(run.level));
    if (run.level % 2 == 1) lowest_odd = std::min(lowest_odd, static_cast<int>(run.level));
  }
  for (int level = highest; level >= lowest_odd && level > 0; --level) {
    for (std::size_t i = 0; i < runs.size();) {
      if (runs[i].level < level) {
        ++i;
        continue;
      }
      std::size_t j = i;
      while (j < runs.size() && runs[j].level >= level) ++j;
      std::reverse(runs.begin() + static_cast<std::ptrdiff_t>(i),
                   runs.begin() + static_cast<std::ptrdiff_t>(j));
      i = j;
    }
  }
}

// The runs of `utf8` in visual order, or nothing when cairo's own call draws it as it is: text
// wholly in the selected face, left to right, needing no shaping; text that is not UTF-8; a
// face not built in.
std::optional<std::pair<Decoded, std::vector<Run>>> itemize(cairo_t* cr, const char* utf8) {
  if (utf8 == nullptr || cairo_status(cr) != CAIRO_STATUS_SUCCESS) return std::nullopt;
  const std::string_view text(utf8);
  // Printable ASCII: every built-in face draws it, left to right, unshaped.
  if (std::all_of(text.begin(), text.end(), [](char ch) { return ch >= 0x20 && ch < 0x7F; }))
    return std::nullopt;
  std::optional<Decoded> decoded = decode(text);
  const std::optional<std::size_t> primary = built_in_index(cairo_get_font_face(cr));
  if (!decoded || decoded->code.empty() || !primary) return std::nullopt;
  const std::vector<std::uint32_t>& code = decoded->code;
  const auto n = static_cast<FriBidiStrIndex>(code.size());

  // The levels: one paragraph, left to right (the pictures' own words are English).
  std::vector<FriBidiCharType> types(code.size());
  std::vector<FriBidiBracketType> brackets(code.size());
  std::vector<FriBidiLevel> levels(code.size());
  fribidi_get_bidi_types(code.data(), n, types.data());
  fribidi_get_bracket_types(code.data(), n, types.data(), brackets.data());
  FriBidiParType direction = FRIBIDI_PAR_LTR;
  if (n > 0 && fribidi_get_par_embedding_levels_ex(types.data(), brackets.data(), n, &direction,
                                                   levels.data()) == 0)
    throw InternalError("the text layout: FriBidi could not resolve the text's levels");

  // Each character's face: the first built-in face that has it; a clinging character stays
  // with the one before; one in none is the selected face's missing-glyph box.
  std::array<std::size_t, 4> chain{*primary, 0, kFirstFallback, kFirstFallback + 1};
  std::vector<std::size_t> face(code.size(), *primary);
  std::vector<hb_script_t> script(code.size(), HB_SCRIPT_COMMON);
  bool plain = true;
  for (std::size_t i = 0; i < code.size(); ++i) {
    if (i > 0 && clings(code[i])) {
      face[i] = face[i - 1];
    } else {
      for (std::size_t candidate : chain)
        if (has_glyph(candidate, code[i])) {
          face[i] = candidate;
          break;
        }
    }
    script[i] = hb_unicode_script(unicode(), code[i]);
    if (face[i] != *primary || levels[i] != 0 || needs_shaping(code[i])) plain = false;
  }
  if (plain) return std::nullopt;
  // A character of no script of its own (spaces, digits, punctuation, marks) takes the one
  // before it, or at the start the first after.
  const auto own_script = [](hb_script_t sc) {
    return sc != HB_SCRIPT_COMMON && sc != HB_SCRIPT_INHERITED;
  };
  for (std::size_t i = 1; i < code.size(); ++i)
    if (!own_script(script[i])) script[i] = script[i - 1];
  for (std::size_t i = code.size() - 1; i-- > 0;)
    if (!own_script(script[i])) script[i] = script[i + 1];

  std::vector<Run> runs;
  for (std::size_t i = 0; i < code.size(); ++i) {
    if (runs.empty() || runs.back().face != face[i] || runs.back().level != levels[i] ||
        runs.back().script != script[i])
      runs.push_back({i, i, face[i], levels[i], script[i], levels[i] % 2 == 1});
    runs.back().end = i + 1;
    if (needs_shaping(code[i])) runs.back().shaped = true;
  }
  reorder(runs);
  return std::make_pair(std::move(*decoded), std::move(runs));
}

// Places every run's glyphs from the origin, left to right in visual order, each with the byte
// offset of its cluster; returns the advance. Leaves the last run's face set on `cr` (callers
// save and restore around it).
double place(cairo_t* cr, const char* utf8, const Decoded& decoded, const std::vector<Run>& runs,
             std::vector<GlyphRun>& out) {
  cairo_matrix_t font_matrix;
  cairo_get_font_matrix(cr, &font_matrix);
  double pen = 0;
  for (const Run& run : runs) {
    cairo_set_font_face(cr, built_in_face(run.face));
    GlyphRun placed{
        run.face,
        std::shared_ptr<cairo_font_face_t>(cairo_font_face_reference(built_in_face(run.face)),
                                           cairo_font_face_destroy),
        run.level % 2 == 1,
        {}};
    if (!run.shaped) {
      // cairo's own glyphs and advances, as cairo_show_text would draw these characters.
      cairo_scaled_font_t* scaled = cairo_get_scaled_font(cr);
      cairo_glyph_t* glyphs = nullptr;
      cairo_text_cluster_t* clusters = nullptr;
      int count = 0, cluster_count = 0;
      cairo_text_cluster_flags_t flags{};
      const std::size_t from = decoded.offset[run.begin], to = decoded.offset[run.end];
      if (cairo_scaled_font_text_to_glyphs(scaled, pen, 0, utf8 + from, static_cast<int>(to - from),
                                           &glyphs, &count, &clusters, &cluster_count,
                                           &flags) != CAIRO_STATUS_SUCCESS)
        throw InternalError("the text layout: cairo cannot map a run to glyphs");
      std::size_t byte = from;
      int g = 0;
      for (int c = 0; c < cluster_count; ++c) {
        for (int k = 0; k < clusters[c].num_glyphs && g < count; ++k, ++g)
          placed.glyphs.push_back({glyphs[g].index, glyphs[g].x, glyphs[g].y, byte});
        byte += static_cast<std::size_t>(clusters[c].num_bytes);
      }
      if (count > 0) {
        cairo_text_extents_t last;
        cairo_scaled_font_glyph_extents(scaled, &glyphs[count - 1], 1, &last);
        pen = glyphs[count - 1].x + last.x_advance;
      }
      cairo_glyph_free(glyphs);
      cairo_text_cluster_free(clusters);
    } else {
      // HarfBuzz's glyphs (joined, reordered, marks placed), in font units scaled to the
      // size; the whole text is the context, so letters join across a run's ends.
      const Shapers& s = shapers();
      hb_buffer_t* buffer = hb_buffer_create();
      hb_buffer_add_codepoints(buffer, decoded.code.data(), static_cast<int>(decoded.code.size()),
                               static_cast<unsigned>(run.begin),
                               static_cast<int>(run.end - run.begin));
      hb_buffer_set_direction(buffer, run.level % 2 == 1 ? HB_DIRECTION_RTL : HB_DIRECTION_LTR);
      hb_buffer_set_script(buffer, run.script);
      hb_buffer_set_language(buffer, hb_language_from_string("und", -1));  // not the locale's
      hb_shape(s.font[run.face], buffer, nullptr, 0);
      unsigned count = 0;
      const hb_glyph_info_t* info = hb_buffer_get_glyph_infos(buffer, &count);
      const hb_glyph_position_t* position = hb_buffer_get_glyph_positions(buffer, &count);
      const double sx = font_matrix.xx / s.units_per_em[run.face];
      const double sy = font_matrix.yy / s.units_per_em[run.face];
      for (unsigned g = 0; g < count; ++g) {
        // HarfBuzz's y grows up, cairo's down: an offset up is a smaller y.
        placed.glyphs.push_back({info[g].codepoint, pen + position[g].x_offset * sx,
                                 -position[g].y_offset * sy, decoded.offset[info[g].cluster]});
        pen += position[g].x_advance * sx;
      }
      hb_buffer_destroy(buffer);
    }
    out.push_back(std::move(placed));
  }
  return pen;
}

// The glyphs of `run` as cairo draws them, moved by (x, y).
std::vector<cairo_glyph_t> cairo_glyphs(const GlyphRun& run, double x, double y) {
  std::vector<cairo_glyph_t> glyphs;
  glyphs.reserve(run.glyphs.size());
  for (const PlacedGlyph& g : run.glyphs) glyphs.push_back({g.index, x + g.x, y + g.y});
  return glyphs;
}

// The ink box of the runs' glyphs, from the origin, as cairo_text_extents gives it; zero where
// there is no ink. Leaves the last run's face set on `cr`.
void ink_extents(cairo_t* cr, const std::vector<GlyphRun>& runs, cairo_text_extents_t& out) {
  double left = 0, top = 0, right = 0, bottom = 0;
  bool inked = false;
  for (const GlyphRun& run : runs) {
    cairo_set_font_face(cr, built_in_face(run.face));
    if (run.glyphs.empty()) continue;
    const std::vector<cairo_glyph_t> glyphs = cairo_glyphs(run, 0, 0);
    cairo_text_extents_t e;
    cairo_glyph_extents(cr, glyphs.data(), static_cast<int>(glyphs.size()), &e);
    if (e.width <= 0 && e.height <= 0) continue;
    // cairo measures the bearings from the run's first glyph; the text's from its origin.
    e.x_bearing += glyphs.front().x;
    e.y_bearing += glyphs.front().y;
    if (!inked) {
      left = e.x_bearing, top = e.y_bearing;
      right = e.x_bearing + e.width, bottom = e.y_bearing + e.height;
      inked = true;
    } else {
      left = std::min(left, e.x_bearing), top = std::min(top, e.y_bearing);
      right = std::max(right, e.x_bearing + e.width);
      bottom = std::max(bottom, e.y_bearing + e.height);
    }
  }
  out.x_bearing = left, out.y_bearing = top;
  out.width = right - left, out.height = bottom - top;
}

// cairo's own glyphs of a whole text (as cairo_show_text draws it from the origin) in the face
// selected on `cr`; none where it is not UTF-8.
GlyphRun cairos_glyphs(cairo_t* cr, const LaidOutText& text) {
  GlyphRun run;
  run.face = built_in_index(cairo_get_font_face(cr)).value_or(0);
  run.font_face = text.font_face;
  cairo_glyph_t* glyphs = nullptr;
  cairo_text_cluster_t* clusters = nullptr;
  int count = 0, cluster_count = 0;
  cairo_text_cluster_flags_t flags{};
  if (cairo_scaled_font_text_to_glyphs(cairo_get_scaled_font(cr), 0, 0, text.utf8.data(),
                                       static_cast<int>(text.utf8.size()), &glyphs, &count,
                                       &clusters, &cluster_count, &flags) != CAIRO_STATUS_SUCCESS)
    return run;
  std::size_t byte = 0;
  int g = 0;
  for (int c = 0; c < cluster_count; ++c) {
    for (int k = 0; k < clusters[c].num_glyphs && g < count; ++k, ++g)
      run.glyphs.push_back({glyphs[g].index, glyphs[g].x, glyphs[g].y, byte});
    byte += static_cast<std::size_t>(clusters[c].num_bytes);
  }
  cairo_glyph_free(glyphs);
  cairo_text_cluster_free(clusters);
  return run;
}

// `utf8` laid out in the font selected on `cr`; its extents measured where `measure`.
LaidOutText lay_out(cairo_t* cr, const char* utf8, bool measure) {
  LaidOutText text;
  if (utf8 != nullptr) text.utf8 = utf8;
  text.font_face = std::shared_ptr<cairo_font_face_t>(
      cairo_font_face_reference(cairo_get_font_face(cr)), cairo_font_face_destroy);
  cairo_get_font_matrix(cr, &text.font_matrix);
  cairo_font_options_t* options = cairo_font_options_create();
  cairo_get_font_options(cr, options);
  text.font_options = std::shared_ptr<cairo_font_options_t>(options, cairo_font_options_destroy);
  auto layout = itemize(cr, utf8);
  if (!layout) {
    text.whole = true;
    if (!measure) return text;
    cairo_text_extents(cr, utf8, &text.extents);
    if (cairo_status(cr) == CAIRO_STATUS_SUCCESS) text.runs.push_back(cairos_glyphs(cr, text));
    return text;
  }
  cairo_save(cr);
  const double advance = place(cr, utf8, layout->first, layout->second, text.runs);
  if (measure) ink_extents(cr, text.runs, text.extents);
  cairo_restore(cr);
  text.extents.x_advance = advance;
  text.extents.y_advance = 0;
  return text;
}

// Draws `text` from the current point (or the origin), by `whole` (cairo's own call) where it
// needs no layout, else each run's glyphs in its face by `glyphs`, in the font it was laid out
// in; the current point then at the text's end.
void draw(cairo_t* cr, const LaidOutText& text, void (*whole)(cairo_t*, const char*),
          void (*glyphs)(cairo_t*, const cairo_glyph_t*, int)) {
  cairo_save(cr);
  cairo_set_font_face(cr, text.font_face.get());
  cairo_set_font_matrix(cr, &text.font_matrix);
  if (text.whole) {
    whole(cr, text.utf8.c_str());
    cairo_restore(cr);
    return;
  }
  double x = 0, y = 0;
  if (cairo_has_current_point(cr)) cairo_get_current_point(cr, &x, &y);
  for (const GlyphRun& run : text.runs) {
    cairo_set_font_face(cr, built_in_face(run.face));
    const std::vector<cairo_glyph_t> placed = cairo_glyphs(run, x, y);
    glyphs(cr, placed.data(), static_cast<int>(placed.size()));
  }
  cairo_restore(cr);
  cairo_move_to(cr, x + text.extents.x_advance, y);
}

}  // namespace

LaidOutText lay_out_text(cairo_t* cr, const char* utf8) { return lay_out(cr, utf8, true); }

std::vector<LaidOutText> lay_out_texts(cairo_t* cr, const std::vector<TextRequest>& requests) {
  std::vector<LaidOutText> laid;
  laid.reserve(requests.size());
  cairo_save(cr);
  for (const TextRequest& request : requests) {
    cairo_save(cr);
    if (request.angle != 0) cairo_rotate(cr, request.angle);
    select(cr, request.face, request.size);
    LaidOutText text = lay_out(cr, request.utf8.c_str(), true);
    const double advance = text.extents.x_advance;
    if (request.max_advance > 0 && advance > request.max_advance) {
      select(cr, request.face, request.size * request.max_advance / advance);
      text = lay_out(cr, request.utf8.c_str(), true);
    }
    laid.push_back(std::move(text));
    cairo_restore(cr);
  }
  cairo_restore(cr);
  return laid;
}

void show_laid_out(cairo_t* cr, const LaidOutText& text) {
  draw(cr, text, cairo_show_text, cairo_show_glyphs);
}

void show_placed(cairo_t* cr, const std::vector<PlacedText>& texts) {
  for (const PlacedText& placed : texts) {
    cairo_save(cr);
    if (placed.angle != 0 || placed.x != 0 || placed.y != 0) {
      cairo_translate(cr, placed.x, placed.y);
      cairo_rotate(cr, placed.angle);
    }
    cairo_set_source_rgb(cr, placed.r, placed.g, placed.b);
    cairo_move_to(cr, placed.origin_x, placed.origin_y);
    show_laid_out(cr, *placed.text);
    cairo_restore(cr);
  }
}

void show_text(cairo_t* cr, const char* utf8) {
  draw(cr, lay_out(cr, utf8, false), cairo_show_text, cairo_show_glyphs);
}

void text_extents(cairo_t* cr, const char* utf8, cairo_text_extents_t* extents) {
  *extents = lay_out(cr, utf8, true).extents;
}

void text_path(cairo_t* cr, const char* utf8) {
  draw(cr, lay_out(cr, utf8, false), cairo_text_path, cairo_glyph_path);
}

}  // namespace bookspin::typeface
