#include "products/gallery_page.hpp"

#include <cctype>
#include <sstream>

namespace bookspin::products {

namespace {

constexpr const char* kStyle = R"(
body { font-family: "DejaVu Sans", sans-serif; margin: 2rem auto; max-width: 1400px; padding: 0 1rem;
       background: #f4f4f1; color: #1c1c1c; }
h1 { font-size: 1.6rem; }
.clip { background: #fff; border-radius: 8px; box-shadow: 0 1px 4px rgba(0,0,0,.15);
        margin: 1.5rem 0; padding: 1rem; }
.clip h2 { font-size: 1.2rem; margin: 0 0 .3rem; }
.clip p { margin: .2rem 0 .8rem; }
.media { display: grid; grid-template-columns: minmax(0, 1fr); gap: 1rem; justify-items: start; }
.media video, .media img { max-width: 100%; height: auto; background: #111; border-radius: 4px; }
.media video:not([width]) { width: 100%; aspect-ratio: 16 / 9; }
.media img.plot { background: #fff; border: 1px solid #ddd; }
.missing { color: #a33; }
.files { font-size: .9rem; }
.about { color: #444; max-width: 60rem; }
.made { color: #666; font-size: .85rem; }
nav.contents { background: #fff; border-radius: 8px; padding: .6rem 1rem; margin: 1rem 0;
               box-shadow: 0 1px 4px rgba(0,0,0,.15); }
nav.contents h2 { font-size: 1.1rem; margin: .2rem 0 .4rem; }
nav.contents > ol { columns: 22rem; column-gap: 2rem; margin: 0; padding-left: 1.4rem; }
nav.contents li { break-inside: avoid; margin: .15rem 0; }
nav.contents ol ol { padding-left: 1.2rem; }
/* A clip's still (its poster frame, which its player shows before play) is printed in its
   player's place: a player prints as an empty box ("0:00 / 0:01"). */
img.still { display: none; }
/* On paper (docs/outputs.md, "The gallery on paper"): dark text on white, each clip's still
   beside its chart on one page, no picture split between pages, the contents' links and the
   players left out (a toss's player's poster is its chart, printed beside it already). */
@media print {
  body { background: #fff; color: #000; margin: 0; max-width: none; padding: 0; }
  .clip { box-shadow: none; border: 1px solid #bbb; border-radius: 0; margin: 0 0 .8rem; padding: .5rem; }
  nav.contents, video { display: none; }
  img.still { display: block; }
  .media { gap: .5rem; }
  .media > * { break-inside: avoid; }
  .media:has(> img.still) { grid-template-columns: repeat(2, minmax(0, 1fr)); break-inside: avoid; }
  .media:has(> img.still) img { width: 100%; }
  .media img { max-width: 100%; height: auto; }
  .clip h2, .clip h3 { break-after: avoid; }
  a { color: #000; text-decoration: none; }
  .about, .made, .files, .missing { color: #222; }
}
/* A phone: the page's margins narrower, a clip's files wrapping at any point. */
@media (max-width: 599px) {
  body { margin: 1rem auto; padding: 0 .5rem; }
  .clip { padding: .7rem; }
  .files { overflow-wrap: anywhere; }
}
)";

/// A path inside an attribute: names are [A-Za-z0-9._-] and '/', escaped anyway. (Built with
/// append: GCC 12 warns falsely, -Wrestrict, on "literal" + std::string.)
std::string attr(const std::string& path) {
  std::string quoted(1, '"');
  quoted.append(html_escape(path)).append(1, '"');
  return quoted;
}

using ImageSizes = std::map<std::string, ImageSize>;

/// ` width="W" height="H"` of the image at `path` where its size is known; else nothing.
std::string size_attrs(const ImageSizes& sizes, const std::string& path) {
  const auto it = sizes.find(path);
  if (it == sizes.end()) return {};
  return " width=\"" + std::to_string(it->second.width) + "\" height=\"" +
         std::to_string(it->second.height) + "\"";
}

/// A chart: its image, lazily loaded, on a row of its own at most the size it was drawn at (its
/// text at the size it was drawn for), linking the PNG itself. A clip and its poster likewise.
void write_chart(std::ostream& out, const ImageSizes& sizes, const std::string& path,
                 const std::string& alt) {
  out << "<a class=\"plot\" href=" << attr(path)
      << "><img class=\"plot\" loading=\"lazy\" src=" << attr(path) << size_attrs(sizes, path)
      << " alt=\"" << html_escape(alt) << "\"></a>\n";
}

void write_media(std::ostream& out, const GalleryEntry& e, const ImageSizes& sizes) {
  out << "<div class=\"media\">\n";
  if (!e.video.empty()) {
    out << "<video controls preload=\"metadata\" src=" << attr(e.video);
    if (!e.poster.empty()) out << " poster=" << attr(e.poster) << size_attrs(sizes, e.poster);
    out << "></video>\n";
    // The same frame as an image, shown only on paper (kStyle, img.still).
    if (!e.poster.empty())
      out << "<img class=\"still\" src=" << attr(e.poster) << size_attrs(sizes, e.poster)
          << " alt=\"frame of " << html_escape(e.title) << "\">\n";
  } else if (!e.poster.empty()) {
    out << "<img src=" << attr(e.poster) << size_attrs(sizes, e.poster) << " alt=\"frame of "
        << html_escape(e.title) << "\">\n";
  } else if (e.sweep.empty() && e.report_charts.empty()) {
    out << "<p class=\"missing\">not rendered yet (no " << html_escape(e.name) << ".mp4)</p>\n";
  }
  if (!e.plot.empty()) write_chart(out, sizes, e.plot, "diagnostics of " + e.title);
  if (!e.sweep.empty()) write_chart(out, sizes, e.sweep, "parameter sweep of " + e.title);
  for (const auto& chart : e.report_charts)
    write_chart(out, sizes, chart, "accuracy report of " + e.title);
  out << "</div>\n";
}

void write_entry(std::ostream& out, const GalleryEntry& e, const ImageSizes& sizes) {
  out << "<section class=\"clip\" id=" << attr(e.name) << ">\n<h2>" << html_escape(e.title)
      << "</h2>\n";
  if (!e.description.empty()) out << "<p>" << html_escape(e.description) << "</p>\n";
  write_media(out, e, sizes);
  out << "<p class=\"files\">" << html_escape(e.name);
  if (!e.mp4.empty()) out << " · <a href=" << attr(e.mp4) << ">MP4</a>";
  if (!e.webm.empty()) out << " · <a href=" << attr(e.webm) << ">WebM</a>";
  if (!e.gif.empty()) out << " · <a href=" << attr(e.gif) << ">GIF</a>";
  if (!e.glb.empty()) out << " · <a href=" << attr(e.glb) << ">glTF</a>";
  if (!e.explorer.empty()) out << " · <a href=" << attr(e.explorer) << ">open in the explorer</a>";
  if (!e.sweep_csv.empty())
    out << " · <a href=" << attr(e.sweep_csv) << ">" << html_escape(e.sweep_csv) << "</a>";
  for (const auto& csv : e.report_csvs)
    out << " · <a href=" << attr(csv) << ">" << html_escape(csv) << "</a>";
  for (const auto& csv : e.csvs) {
    const std::string file = csv.substr(csv.rfind('/') + 1);  // npos + 1 = 0: the whole path
    out << " · <a href=" << attr(csv) << ">" << html_escape(file) << "</a>";
  }
  out << "</p>\n</section>\n";
}

/// The phone-toss lab's section (id "phone-lab"): the explorer page's lab panel where there is
/// one (`lab_page`), then per fitted recording its two tables, then per toss its chart and clip
/// side by side and a line of links.
void write_fits(std::ostream& out, const std::vector<GalleryFit>& fits, const std::string& lab_page,
                const ImageSizes& sizes) {
  out << "<section class=\"clip\" id=\"phone-lab\">\n<h2>Phone-toss lab: a measured toss beside "
         "the exact motion</h2>\n<p>A phone's gyroscope recording of tosses (phyphox), each "
         "free flight fitted with the exact torque-free motion (<code>bookspin fit</code>, "
         "docs/phone-lab.md): per toss the measured &omega; (dots) against the fitted exact "
         "&omega; (lines) with the momentum sphere, and the body turning as the phone turned "
         "beside the fitted exact motion.";
  if (!lab_page.empty())
    out << " Your own recording fitted in the page, nothing installed: <a href=" << attr(lab_page)
        << ">the Phone-toss lab</a>.";
  out << "</p>\n";
  for (const GalleryFit& fit : fits) {
    out << "<h3>" << html_escape(fit.recording) << "</h3>\n<p class=\"files\">"
        << html_escape(fit.recording);
    for (const std::string* csv : {&fit.csv, &fit.body_csv})
      if (!csv->empty()) out << " · <a href=" << attr(*csv) << ">" << html_escape(*csv) << "</a>";
    out << "</p>\n";
    for (const GalleryToss& toss : fit.tosses) {
      const std::string what = fit.recording + ", toss " + std::to_string(toss.number);
      out << "<div class=\"media\">\n";
      if (!toss.chart.empty())
        write_chart(out, sizes, toss.chart, "measured and fitted omega of " + what);
      // The clip's poster is the toss's chart (measured and fitted ω over the whole flight):
      // its first frame has drawn nothing yet, empty panels over the first milliseconds.
      if (!toss.video.empty()) {
        out << "<video controls preload=\"metadata\" src=" << attr(toss.video);
        if (!toss.chart.empty()) out << " poster=" << attr(toss.chart);
        out << "></video>\n";
      }
      out << "</div>\n<p class=\"files\">toss " << toss.number;
      if (!toss.chart.empty()) out << " · <a href=" << attr(toss.chart) << ">chart</a>";
      if (!toss.video.empty()) out << " · <a href=" << attr(toss.video) << ">clip</a>";
      if (!toss.explorer.empty())
        out << " · <a href=" << attr(toss.explorer) << ">open in the explorer</a>";
      out << "</p>\n";
    }
  }
  out << "</section>\n";
}

/// The intro's words for the sections before the clips, in page order, ending "then " (none:
/// "first "), so that the intro states the order the page has.
std::string first_sections(const GalleryHeader& header) {
  std::vector<std::string> parts;
  if (!header.flipcheck_league.empty()) parts.emplace_back("the conformance kit's league table");
  if (!header.fits.empty()) parts.emplace_back("the phone-toss lab's fitted tosses");
  if (parts.empty()) return "first ";
  std::string text = "first " + parts[0];
  if (parts.size() > 1) text += " and " + parts[1];
  return text + ", then ";
}

/// The name of a group's heading in the contents.
const char* group_name(GalleryGroup group) {
  switch (group) {
    case GalleryGroup::paper_figure:
      return "The paper's figures";
    case GalleryGroup::exact:
      return "The exact motion";
    case GalleryGroup::comparison:
      return "Comparisons of models and methods";
    case GalleryGroup::other:
      return "Other bodies";
    case GalleryGroup::sweep:
      return "Sweeps";
  }
  return "";
}

/// The page's contents (id "contents"): a link to each section in page order, the clips under
/// their group's name.
void write_contents(std::ostream& out, const std::vector<GalleryEntry>& entries,
                    const GalleryHeader& header) {
  if (entries.empty() && header.flipcheck_league.empty() && header.fits.empty()) return;
  out << "<nav class=\"contents\" id=\"contents\">\n<h2>Contents</h2>\n<ol>\n";
  if (!header.flipcheck_league.empty())
    out << "<li><a href=\"#flipcheck-league\">Does an engine get the flip right?</a></li>\n";
  if (!header.fits.empty())
    out << "<li><a href=\"#phone-lab\">Phone-toss lab: a measured toss beside the exact "
           "motion</a></li>\n";
  for (std::size_t i = 0; i < entries.size(); ++i) {
    if (i == 0 || entries[i].group != entries[i - 1].group)
      out << "<li>" << group_name(entries[i].group) << "\n<ol>\n";
    out << "<li><a href=\"#" << html_escape(entries[i].name) << "\">"
        << html_escape(entries[i].title.empty() ? entries[i].name : entries[i].title)
        << "</a></li>\n";
    if (i + 1 == entries.size() || entries[i + 1].group != entries[i].group) out << "</ol></li>\n";
  }
  out << "</ol>\n</nav>\n";
}

}  // namespace

std::string html_escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

bool GalleryRank::operator<(const GalleryRank& o) const {
  if (group != o.group) return group < o.group;
  if (figure != o.figure) return figure < o.figure;
  return name < o.name;
}

GalleryRank gallery_rank(const std::string& name, bool is_comparison, bool is_exact,
                         bool is_sweep) {
  GalleryRank rank;
  rank.name = name;
  const auto starts = [&name](std::string_view prefix) { return name.rfind(prefix, 0) == 0; };
  std::size_t digits = 0;
  while (3 + digits < name.size() && std::isdigit(static_cast<unsigned char>(name[3 + digits])))
    ++digits;
  if (starts("fig") && digits > 0 && digits <= 4) {
    rank.group = GalleryGroup::paper_figure;
    rank.figure = std::stoi(name.substr(3, digits));
  } else if (is_sweep || starts("sweep-")) {
    rank.group = GalleryGroup::sweep;
  } else if (is_comparison || starts("compare-")) {
    rank.group = GalleryGroup::comparison;
  } else if (is_exact || starts("exact-")) {
    rank.group = GalleryGroup::exact;
  }
  return rank;
}

std::string gallery_html(const std::vector<GalleryEntry>& entries, const GalleryHeader& header) {
  std::ostringstream out;
  out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
      << "<link rel=\"icon\" href=\"data:,\">\n"  // no favicon request, so no console error
      << "<title>bookspin: the spinning book, figure by figure</title>\n<style>"
      << kStyle
      // Every part of the page in one main landmark (docs/explorer.md, "For every person").
      << "</style>\n</head>\n<body>\n<main>\n<h1>bookspin: the spinning book, figure by "
         "figure</h1>\n"
      << "<p class=\"about\">The clips of bookspin, a simulation of a freely spinning book (the "
         "tennis-racket or Dzhanibekov effect): "
      << first_sections(header)
      << "the paper's figures 3–12, the exact "
         "motion, the comparisons of models and methods, other bodies and sweeps. Each clip "
         "comes with a plot of its diagnostics over the whole run (body-frame &omega;, energy "
         "drift, shape error) and its CSV files.</p>\n"
      << "<p class=\"made\">Made with bookspin " << html_escape(header.version) << " (build "
      << html_escape(header.build_id.substr(0, 12)) << ")";
  if (!header.date.empty()) out << ", " << html_escape(header.date);
  if (!header.machine.empty()) out << ", on " << html_escape(header.machine);
  out << ".</p>\n";
  write_contents(out, entries, header);
  if (!header.flipcheck_league.empty()) {
    out << "<section class=\"kit\" id=\"flipcheck-league\">\n<h2>Does an engine get the flip "
           "right?</h2>\n<p>The conformance kit (<code>bookspin flipcheck</code>): every model "
           "and engine bookspin runs, and the JavaScript engines of the explorer, judged against "
           "the exact motion in the kit's scenarios: <a href="
        << attr(header.flipcheck_league) << ">the league table</a>";
    if (!header.flipcheck_league_csv.empty())
      out << " · <a href=" << attr(header.flipcheck_league_csv) << ">its CSV</a>";
    out << ".";
    if (!header.flipcheck_judge_page.empty())
      out << " Your engine's motion judged in the page, nothing installed: <a href="
          << attr(header.flipcheck_judge_page) << ">judge a motion</a>.";
    out << "</p>\n</section>\n";
  }
  if (!header.fits.empty()) write_fits(out, header.fits, header.phone_lab_page, header.image_sizes);
  for (const auto& e : entries) write_entry(out, e, header.image_sizes);
  out << "</main>\n</body>\n</html>\n";
  return out.str();
}

}  // namespace bookspin::products
