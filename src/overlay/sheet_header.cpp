#include "overlay/sheet_header.hpp"

#include <string>
#include <vector>

#include "overlay/cairo_canvas.hpp"
#include "typeface/text_layout.hpp"

namespace bookspin::overlay {

std::vector<std::string> wrap_sheet_header(cairo_t* cr, const std::vector<std::string>& header,
                                           double font, double width) {
  std::vector<std::string> lines;
  const double room = width - 2.0 * font;
  const auto advance = [cr](const std::string& text) {
    cairo_text_extents_t e;
    typeface::text_extents(cr, text.c_str(), &e);
    return e.x_advance;
  };
  // The bold title as long as it fits, its remaining words the next line's start (a sweep's
  // "T-handle: first flip against the perturbation …" ran past the sheet's right edge).
  std::vector<std::string> given = header;
  select_overlay_font(cr, true, font);
  if (!given.empty() && advance(given[0]) > room) {
    std::string fits, rest = given[0];
    for (std::size_t space = rest.find(' '); space != std::string::npos;
         space = given[0].find(' ', space + 1)) {
      if (advance(given[0].substr(0, space)) > room) break;
      fits = given[0].substr(0, space);
      rest = given[0].substr(space + 1);
    }
    if (!fits.empty()) {
      given[0] = fits;
      given.insert(given.begin() + 1, rest);
    }
  }
  select_overlay_font(cr, false, 0.8 * font);
  for (std::size_t i = 0; i < given.size(); ++i) {
    if (i == 0 || advance(given[i]) <= room) {
      lines.push_back(given[i]);
      continue;
    }
    // A list ("a · b · c", a comparison's tiles) is broken between its items, anything else
    // between words.
    const std::string dot = " \u00b7 ";
    const std::string gap = given[i].find(dot) != std::string::npos ? dot : " ";
    std::string line;
    std::size_t start = 0;
    while (start <= given[i].size()) {
      std::size_t end = given[i].find(gap, start);
      if (end == std::string::npos) end = given[i].size();
      const std::string word = given[i].substr(start, end - start);
      const std::string longer = line.empty() ? word : line + gap + word;
      if (!line.empty() && advance(gap == dot ? longer + " \u00b7" : longer) > room) {
        lines.push_back(gap == dot ? line + " \u00b7" : line);
        line = word;
      } else {
        line = longer;
      }
      start = end + gap.size();
    }
    if (!line.empty()) lines.push_back(line);
  }
  return lines;
}

double draw_sheet_header(cairo_t* cr, const std::vector<std::string>& header, double font) {
  double y = 0.4 * font;
  for (std::size_t i = 0; i < header.size(); ++i) {
    select_overlay_font(cr, i == 0, i == 0 ? font : 0.8 * font);
    y += 1.35 * (i == 0 ? font : 0.8 * font);
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    cairo_move_to(cr, font, y);
    typeface::show_text(cr, header[i].c_str());
  }
  return y;
}

SheetHeader lay_out_sheet_header(cairo_t* cr, const std::vector<std::string>& header, double font,
                                 double width) {
  const std::vector<std::string> wrapped = wrap_sheet_header(cr, header, font, width);
  std::vector<typeface::TextRequest> requests;
  for (std::size_t i = 0; i < wrapped.size(); ++i)
    requests.push_back({wrapped[i], i == 0 ? typeface::Face::sans_bold : typeface::Face::sans,
                        i == 0 ? font : 0.8 * font, 0});
  SheetHeader laid{typeface::lay_out_texts(cr, requests), {}, font, 0.4 * font};
  for (std::size_t i = 0; i < wrapped.size(); ++i) {
    laid.bottom += 1.35 * (i == 0 ? font : 0.8 * font);
    laid.baselines.push_back(laid.bottom);
  }
  return laid;
}

}  // namespace bookspin::overlay
