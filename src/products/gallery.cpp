#include "products/gallery.hpp"

#include <sys/utsname.h>

#include <algorithm>
#include <ctime>
#include <fstream>
#include <map>
#include <stdexcept>
#include <thread>

#include "cache/make_cached.hpp"
#include "common/sha256.hpp"
#include "output/atomic_output.hpp"
#include "output/manifest.hpp"
#include "output/output_dir.hpp"
#include "output/png_writer.hpp"
#include "products/accuracy.hpp"
#include "products/clip.hpp"
#include "products/explorer.hpp"
#include "products/fit.hpp"
#include "products/flipcheck.hpp"
#include "products/gallery_page.hpp"
#include "products/gltf.hpp"
#include "products/plot.hpp"
#include "products/sweep.hpp"
#include "scene/scene.hpp"

namespace bookspin::products {

namespace {

namespace fs = std::filesystem;

bool exists(const fs::path& out, const std::string& relative) {
  std::error_code ec;
  return fs::is_regular_file(out / relative, ec);
}

std::string path_in_out(const fs::path& out, const fs::path& path) {
  return path.lexically_relative(out).generic_string();
}

/// The path relative to OUT of `path` if that file exists, else "".
std::string if_there(const fs::path& out, const fs::path& path) {
  std::error_code ec;
  return fs::is_regular_file(path, ec) ? path_in_out(out, path) : "";
}

/// The outputs of the last run of a product, as its manifest lists them: only these are
/// linked, so a file left from an earlier run (another render.formats) never is.
class Listed {
 public:
  Listed(const fs::path& out, const fs::path& manifest)
      : out_(out), paths_(output::read_manifest(manifest).outputs) {}
  /// The path relative to OUT of `path` if the manifest lists it and it exists, else "".
  std::string operator()(const fs::path& path) const {
    const std::string relative = path_in_out(out_, path);
    return std::find(paths_.begin(), paths_.end(), relative) != paths_.end() ? if_there(out_, path)
                                                                             : "";
  }
  /// The listed files in `folder` (relative to OUT) ending in `suffix`, in the manifest's order.
  std::vector<std::string> in_folder(const fs::path& folder, const std::string& suffix) const {
    const std::string prefix = path_in_out(out_, folder) + "/";
    std::vector<std::string> found;
    for (const std::string& p : paths_) {
      if (p.rfind(prefix, 0) == 0 && p.size() > prefix.size() + suffix.size() &&
          p.compare(p.size() - suffix.size(), suffix.size(), suffix) == 0 &&
          p.find('/', prefix.size()) == std::string::npos && exists(out_, p))
        found.push_back(p);
    }
    return found;
  }

 private:
  fs::path out_;
  std::vector<std::string> paths_;
};

/// OUT/<name>/poster.png if there is one, else the middle one of the clip's frames that its
/// manifest lists.
std::string poster_for(const fs::path& out, const Listed& clip_outputs, const ClipLayout& clip,
                       const std::string& name) {
  if (exists(out, name + "/poster.png")) return name + "/poster.png";
  const auto frames = clip_outputs.in_folder(clip.frames_dir, ".png");
  return frames.empty() ? "" : frames[frames.size() / 2];
}

GalleryEntry entry_for(const fs::path& out, const scene::Scene& scene) {
  GalleryEntry e;
  e.name = scene.name;
  e.title = scene.title;
  e.description = scene.description;
  // Every video format, whichever the scene names (a render's --format may differ).
  scene::Scene every_format = scene;
  every_format.render.formats = {"mp4", "webm", "gif"};
  const ClipLayout clip = clip_layout(out, every_format);
  // The clip's files only as its last render made them (docs/outputs.md).
  const Listed rendered(out, clip.manifest);
  e.mp4 = rendered(clip.videos[0]);
  e.webm = rendered(clip.videos[1]);
  e.gif = rendered(clip.videos[2]);
  const GltfLayout gltf = gltf_layout(out, scene);
  e.glb = Listed(out, gltf.manifest)(gltf.glb);
  if (const std::string page = if_there(out, explorer_page_path(out)); !page.empty())
    e.explorer = page + "?scene=" + scene.name;
  e.video = e.mp4.empty() ? e.webm : e.mp4;
  e.poster = poster_for(out, rendered, clip, scene.name);
  const PlotLayout plot = plot_layout(out, scene);
  e.plot = Listed(out, plot.manifest)(plot.png);
  const SweepPaths sweep = sweep_paths(out, scene.name);
  e.sweep = if_there(out, sweep.png);
  e.sweep_csv = if_there(out, sweep.csv);
  const AccuracyLayout accuracy = accuracy_layout(out, scene);
  const Listed reported(out, accuracy.manifest);
  for (const fs::path& file : accuracy.outputs()) {
    const std::string there = reported(file);
    if (there.empty()) continue;
    (file.extension() == ".png" ? e.report_charts : e.report_csvs).push_back(there);
  }
  for (const fs::path& csv : clip.csvs) {
    if (const std::string there = rendered(csv); !there.empty()) e.csvs.push_back(there);
  }
  return e;
}

/// "HOST, CPU MODEL, N cores" from uname(2) and /proc/cpuinfo (parts it cannot read left out).
std::string machine() {
  std::string text;
  struct utsname u {};
  if (uname(&u) == 0) text = u.nodename;
  std::ifstream cpuinfo("/proc/cpuinfo");
  for (std::string line; std::getline(cpuinfo, line);) {
    if (line.rfind("model name", 0) == 0 && line.find(':') != std::string::npos) {
      text += (text.empty() ? "" : ", ") + line.substr(line.find(':') + 2);
      break;
    }
  }
  if (const unsigned cores = std::thread::hardware_concurrency(); cores > 0)
    text += (text.empty() ? "" : ", ") + std::to_string(cores) + " cores";
  return text;
}

std::string utc_now() {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&now, &tm);
  char buffer[32];
  std::strftime(buffer, sizeof buffer, "%Y-%m-%d %H:%M UTC", &tm);
  return buffer;
}

/// Every fit in OUT (OUT/<recording>/fit-manifest.json, by recording name), each file as its
/// manifest lists it: the tables, and per toss its chart, its clip and its scene (linked into
/// the explorer page where OUT/explorer.html is there).
std::vector<GalleryFit> fits_in(const fs::path& out) {
  std::vector<std::string> names;
  std::error_code ec;
  for (fs::directory_iterator it(out, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (exists(out, path_in_out(out, fit_layout(out, name, 0).manifest))) names.push_back(name);
  }
  std::sort(names.begin(), names.end());
  const std::string page = if_there(out, explorer_page_path(out));
  std::vector<GalleryFit> fits;
  for (const std::string& name : names) {
    const FitLayout bare = fit_layout(out, name, 0);
    const Listed listed(out, bare.manifest);
    GalleryFit fit{name, listed(bare.csv), listed(bare.body_csv), {}};
    // The tosses: N = 1, 2, … while the manifest lists the chart of toss N.
    for (int n = 1;; ++n) {
      const FitLayout layout = fit_layout(out, name, n, true, {"mp4", "webm"});
      GalleryToss toss{n, listed(layout.pngs.back()), listed(layout.videos[2 * (n - 1)]), ""};
      if (toss.chart.empty()) break;
      if (toss.video.empty()) toss.video = listed(layout.videos[2 * (n - 1) + 1]);
      if (!page.empty() && !listed(layout.scenes.back()).empty())
        toss.explorer = page + "?scene=" + layout.scenes.back().stem().string();
      fit.tosses.push_back(std::move(toss));
    }
    if (!fit.csv.empty() || !fit.tosses.empty()) fits.push_back(std::move(fit));
  }
  return fits;
}

}  // namespace

GalleryLayout gallery_layout(const fs::path& out_dir) {
  return {out_dir / "index.html", out_dir / "gallery-manifest.json"};
}

namespace {

/// The size of every image the page shows (GalleryHeader::image_sizes), read from each PNG's
/// header; a PNG that cannot be read is left out (the page shows it as wide as its column).
std::map<std::string, ImageSize> image_sizes(const fs::path& out,
                                             const std::vector<GalleryEntry>& entries,
                                             const std::vector<GalleryFit>& fits) {
  std::vector<std::string> images;
  for (const GalleryEntry& e : entries) {
    for (const std::string* p : {&e.poster, &e.plot, &e.sweep}) images.push_back(*p);
    images.insert(images.end(), e.report_charts.begin(), e.report_charts.end());
  }
  for (const GalleryFit& fit : fits)
    for (const GalleryToss& toss : fit.tosses) images.push_back(toss.chart);
  std::map<std::string, ImageSize> sizes;
  for (const std::string& image : images) {
    if (image.empty() || sizes.count(image)) continue;
    try {
      const output::PngSize size = output::read_png_size(out / image);
      sizes[image] = {size.width, size.height};
    } catch (const std::runtime_error&) {
    }
  }
  return sizes;
}

}  // namespace

GalleryOutcome make_gallery(const GalleryJob& job) {
  const fs::path& out = job.out_dir;
  const GalleryLayout layout = gallery_layout(out);
  std::vector<std::pair<GalleryRank, GalleryEntry>> ranked;
  // Every scene is parsed first, so a bad one fails before anything is written.
  for (const auto& path : job.scene_paths) {
    stop_if_asked(job.stop_signal, "gallery scenes");
    const scene::Scene scene = scene::parse_scene(path);
    // The exact motion of the book; other bodies' exact runs go with the other bodies.
    const bool exact = scene.compare.empty() && scene.model.kind == physics::ModelKind::exact &&
                       scene.body.shape == physics::BodyShape::book;
    GalleryEntry entry = entry_for(out, scene);
    const bool sweep = !entry.sweep.empty() || !entry.sweep_csv.empty() ||
                       fs::path(path).parent_path().filename() == "sweeps";
    ranked.emplace_back(gallery_rank(scene.name, !scene.compare.empty(), exact, sweep),
                        std::move(entry));
  }
  std::stable_sort(ranked.begin(), ranked.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<GalleryEntry> entries;
  for (auto& [rank, entry] : ranked) {
    entry.group = rank.group;
    entries.push_back(std::move(entry));
  }

  GalleryHeader header{
      output::program_version(), output::program_build_id(), "", machine(), "", "", "", "", {}, {}};
  const FlipcheckLeagueLayout league = flipcheck_league_layout(out);
  if (exists(out, path_in_out(out, league.manifest))) {
    const Listed tabled(out, league.manifest);
    header.flipcheck_league = tabled(league.html);
    header.flipcheck_league_csv = tabled(league.csv);
    if (const std::string page = if_there(out, explorer_page_path(out)); !page.empty())
      header.flipcheck_judge_page = page + "#judge";
  }
  if (const std::string page = if_there(out, explorer_page_path(out)); !page.empty())
    header.phone_lab_page = page + "#lab";
  header.fits = fits_in(out);
  header.image_sizes = image_sizes(out, entries, header.fits);
  // Up to date: the same page but for its date (output/manifest.hpp).
  GalleryOutcome done;
  done.entries = entries.size();
  const cache::CachedOutputs cached{
      layout.page.filename().string(),
      layout.manifest,
      "gallery",
      {{"page_sha256", {sha256_text(gallery_html(entries, header))}}},
      out,
      nullptr,
      /*all_or_nothing=*/true};  // one page, whole or not at all (output::write_text_file)
  done.outcome = cache::make_cached(cached, job.freshness, [&] {
    stop_if_asked(job.stop_signal, "gallery write");
    // The page made first, then its folder and the file (output::write_text_file: through a
    // temporary, put in place whole).
    header.date = utc_now();
    const std::string html = gallery_html(entries, header);
    std::error_code ec;
    output::make_directories(out, ec);
    if (ec) throw_output_error("cannot create output directory", out, ec.value());
    output::write_text_file(layout.page, html);
    return cache::Made{{layout.page}};
  });
  return done;
}

}  // namespace bookspin::products
