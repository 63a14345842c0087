#pragma once
// The typeface of every picture's text (the overlays', the charts' and the generated book
// covers'): DejaVu, built into the program from Debian's font files, drawn through cairo's
// FreeType backend with every option set here. No fontconfig configuration, locale, home
// folder or FREETYPE_PROPERTIES of the machine reaches a frame (docs/architecture.md, the
// typeface stage).
#include <cairo.h>

#include <string>
#include <vector>

#include "typeface/face.hpp"

namespace bookspin::typeface {

/// Sets `face` on `cr`, `size` pixels to the em (cairo's font size, in the context's user
/// units), with the fixed options of text_options(). Thread-safe: the faces are made once.
void select(cairo_t* cr, Face face, double size);

/// One face built in: its name ("DejaVu Sans Bold"), the version its file states ("Version
/// 2.37"), the file's name, SHA-256 and the path the build read it from.
struct FaceInfo {
  std::string name;
  std::string version;
  std::string file;
  std::string sha256;
  std::string source_path;
};

/// Every face, in the order of Face.
std::vector<FaceInfo> faces();

/// The options every text is drawn with, in words: antialiasing, hint style, hint metrics,
/// subpixel order, FreeType's load flags and version.
std::string text_options();

/// What `bookspin info` says of the text: a line per face, then the options.
std::vector<std::string> info_lines();

}  // namespace bookspin::typeface
