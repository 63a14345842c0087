#include "typeface/typeface.hpp"

#include <cairo-ft.h>
#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_MODULE_H
#include FT_SFNT_NAMES_H
#include FT_TRUETYPE_IDS_H

#include <array>
#include <cstdlib>
#include <optional>
#include <string_view>

#include "common/errors.hpp"
#include "typeface/built_in.hpp"
#include "typeface/embedded_fonts.hpp"

namespace bookspin::typeface {

namespace {

// The six faces of Face, then the fallbacks (built_in.hpp): Droid Sans Fallback (CJK), Symbola
// (emoji and symbols).
constexpr std::array<std::string_view, kBuiltInFaces> kFiles{"DejaVuSans.ttf",
                                                             "DejaVuSans-Bold.ttf",
                                                             "DejaVuSansMono.ttf",
                                                             "DejaVuSerif.ttf",
                                                             "DejaVuSerif-Bold.ttf",
                                                             "DejaVuSerif-Italic.ttf",
                                                             "DroidSansFallbackFull.ttf",
                                                             "Symbola_hint.ttf"};
static_assert(kFirstFallback == 6, "the fallbacks follow the six faces of Face");

// FreeType's memory hooks: the library is made with FT_New_Library and FT_Add_Default_Modules
// rather than FT_Init_FreeType, which would also read the FREETYPE_PROPERTIES variable.
void* ft_alloc(FT_Memory, long size) { return std::malloc(static_cast<std::size_t>(size)); }
void ft_free(FT_Memory, void* block) { std::free(block); }
void* ft_realloc(FT_Memory, long, long new_size, void* block) {
  return std::realloc(block, static_cast<std::size_t>(new_size));
}
FT_MemoryRec_ ft_memory{nullptr, ft_alloc, ft_free, ft_realloc};

// The options of every text (docs/architecture.md, the typeface stage): greyscale
// antialiasing, FreeType's light hinting (the vertical axis only) with metrics rounded to
// whole pixels, as Debian 12's default configuration draws DejaVu: the goldens were drawn so.
constexpr cairo_antialias_t kAntialias = CAIRO_ANTIALIAS_GRAY;
constexpr cairo_hint_style_t kHintStyle = CAIRO_HINT_STYLE_SLIGHT;
constexpr cairo_hint_metrics_t kHintMetrics = CAIRO_HINT_METRICS_ON;
constexpr cairo_subpixel_order_t kSubpixelOrder = CAIRO_SUBPIXEL_ORDER_DEFAULT;
constexpr int kLoadFlags = FT_LOAD_DEFAULT;  // no autohinter forced, no bitmaps asked

struct Faces {
  FT_Library library = nullptr;
  std::array<FT_Face, kBuiltInFaces> ft{};
  std::array<cairo_font_face_t*, kBuiltInFaces> cairo{};
  std::array<const EmbeddedFont*, kBuiltInFaces> file{};
  cairo_font_options_t* options = nullptr;
};

// Made once and kept for the process's life (cairo holds the FreeType faces by pointer).
const Faces& the_faces() {
  static const Faces faces = [] {
    Faces f;
    if (FT_New_Library(&ft_memory, &f.library) != 0)
      throw InternalError("the typeface: FreeType's library could not be made");
    FT_Add_Default_Modules(f.library);
    const auto& fonts = embedded_fonts();
    for (std::size_t i = 0; i < kFiles.size(); ++i) {
      for (const auto& font : fonts)
        if (kFiles[i] == font.file) f.file[i] = &font;
      if (f.file[i] == nullptr)
        throw InternalError("the typeface: " + std::string(kFiles[i]) + " is not built in");
      if (FT_New_Memory_Face(f.library, f.file[i]->data, static_cast<FT_Long>(f.file[i]->size), 0,
                             &f.ft[i]) != 0)
        throw InternalError("the typeface: FreeType cannot read the built-in " +
                            std::string(kFiles[i]));
      f.cairo[i] = cairo_ft_font_face_create_for_ft_face(f.ft[i], kLoadFlags);
      if (cairo_font_face_status(f.cairo[i]) != CAIRO_STATUS_SUCCESS)
        throw InternalError("the typeface: cairo cannot use " + std::string(kFiles[i]));
    }
    f.options = cairo_font_options_create();
    cairo_font_options_set_antialias(f.options, kAntialias);
    cairo_font_options_set_hint_style(f.options, kHintStyle);
    cairo_font_options_set_hint_metrics(f.options, kHintMetrics);
    cairo_font_options_set_subpixel_order(f.options, kSubpixelOrder);
    return f;
  }();
  return faces;
}

// The font's version as its name table states it ("Version 2.37"), or "" where it has none.
std::string name_entry(FT_Face face, FT_UShort name_id) {
  const FT_UInt count = FT_Get_Sfnt_Name_Count(face);
  for (FT_UInt i = 0; i < count; ++i) {
    FT_SfntName name;
    if (FT_Get_Sfnt_Name(face, i, &name) != 0 || name.name_id != name_id) continue;
    // The Macintosh Roman entry is one byte a character; Windows' is UTF-16BE.
    if (name.platform_id == TT_PLATFORM_MACINTOSH)
      return std::string(reinterpret_cast<const char*>(name.string), name.string_len);
    if (name.platform_id == TT_PLATFORM_MICROSOFT) {
      std::string text;
      for (FT_UInt k = 1; k < name.string_len; k += 2)
        if (name.string[k - 1] == 0 && name.string[k] < 0x80)
          text += static_cast<char>(name.string[k]);
      return text;
    }
  }
  return {};
}

}  // namespace

cairo_font_face_t* built_in_face(std::size_t index) { return the_faces().cairo.at(index); }

const EmbeddedFont& built_in_file(std::size_t index) { return *the_faces().file.at(index); }

std::optional<std::size_t> built_in_index(cairo_font_face_t* face) {
  const Faces& f = the_faces();
  for (std::size_t i = 0; i < f.cairo.size(); ++i)
    if (f.cairo[i] == face) return i;
  return std::nullopt;
}

const cairo_font_options_t* built_in_options() { return the_faces().options; }

void select(cairo_t* cr, Face face, double size) {
  const Faces& f = the_faces();
  cairo_set_font_face(cr, f.cairo[static_cast<std::size_t>(face)]);
  cairo_set_font_options(cr, f.options);
  cairo_set_font_size(cr, size);
}

std::vector<FaceInfo> faces() {
  const Faces& f = the_faces();
  std::vector<FaceInfo> out;
  for (std::size_t i = 0; i < kFiles.size(); ++i) {
    const FT_Face face = f.ft[i];
    std::string name = face->family_name != nullptr ? face->family_name : "";
    if (face->style_name != nullptr && std::string_view(face->style_name) != "Book" &&
        std::string_view(face->style_name) != "Regular")
      name += std::string(" ") + face->style_name;
    out.push_back({name, name_entry(face, TT_NAME_ID_VERSION_STRING), f.file[i]->file,
                   f.file[i]->sha256, f.file[i]->source_path});
  }
  return out;
}

std::string text_options() {
  FT_Int major = 0, minor = 0, patch = 0;
  FT_Library_Version(the_faces().library, &major, &minor, &patch);
  return "antialias gray, hint style slight, hint metrics on, subpixel order default; "
         "FreeType " +
         std::to_string(major) + "." + std::to_string(minor) + "." + std::to_string(patch) +
         ", its default load flags, no autohinter forced, FREETYPE_PROPERTIES not read; "
         "no fontconfig";
}

std::vector<std::string> info_lines() {
  std::vector<std::string> lines;
  for (const FaceInfo& face : faces())
    lines.push_back("text face: " + face.name + " (" + face.version + "), built in from " +
                    face.source_path + ", SHA-256 " + face.sha256);
  lines.push_back("text options: " + text_options());
  return lines;
}

}  // namespace bookspin::typeface
