// `bookspin gallery`: OUT/index.html over the clips, frames and plots already under OUT.
#include <sys/utsname.h>

#include <algorithm>
#include <ctime>
#include <fstream>
#include <iostream>
#include <thread>

#include "cache/manifests.hpp"
#include "cli/commands.hpp"
#include "cli/gallery_page.hpp"
#include "output/atomic_output.hpp"
#include "output/manifest.hpp"
#include "output/output_dir.hpp"
#include "output/sha256.hpp"
#include "scene/scene.hpp"

namespace bookspin::cli {

namespace {

namespace fs = std::filesystem;

bool exists(const fs::path& out, const std::string& relative) {
  std::error_code ec;
  return fs::is_regular_file(out / relative, ec);
}

/// Files under OUT/<dir> whose names start with `prefix` and end with `suffix`, sorted,
/// as paths relative to OUT.
std::vector<std::string> files_in(const fs::path& out, const std::string& dir,
                                  const std::string& prefix, const std::string& suffix) {
  std::vector<std::string> found;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(out / dir, ec)) {
    const std::string name = e.path().filename().string();
    const bool match = name.size() >= prefix.size() + suffix.size() && name.rfind(prefix, 0) == 0 &&
                       name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
    if (match && e.is_regular_file(ec)) found.push_back(dir + "/" + name);
  }
  std::sort(found.begin(), found.end());
  return found;
}

/// OUT/<name>/poster.png if there is one, else the middle frame of OUT/<name>/frames/.
std::string poster_for(const fs::path& out, const std::string& name) {
  if (exists(out, name + "/poster.png")) return name + "/poster.png";
  const auto frames = files_in(out, name + "/frames", "frame_", ".png");
  return frames.empty() ? "" : frames[frames.size() / 2];
}

GalleryEntry entry_for(const fs::path& out, const scene::Scene& scene) {
  GalleryEntry e;
  e.name = scene.name;
  e.title = scene.title;
  e.description = scene.description;
  if (exists(out, scene.name + ".mp4")) e.mp4 = scene.name + ".mp4";
  if (exists(out, scene.name + ".webm")) e.webm = scene.name + ".webm";
  if (exists(out, scene.name + ".gif")) e.gif = scene.name + ".gif";
  if (exists(out, scene.name + ".glb")) e.glb = scene.name + ".glb";
  if (exists(out, "explorer.html")) e.explorer = "explorer.html?scene=" + scene.name;
  e.video = e.mp4.empty() ? e.webm : e.mp4;
  e.poster = poster_for(out, scene.name);
  if (exists(out, scene.name + "-plot.png")) e.plot = scene.name + "-plot.png";
  if (exists(out, scene.name + "-sweep.png")) e.sweep = scene.name + "-sweep.png";
  if (exists(out, scene.name + "-sweep.csv")) e.sweep_csv = scene.name + "-sweep.csv";
  e.csvs = files_in(out, scene.name, "diagnostics", ".csv");
  return e;
}

void write_page(const fs::path& path, const std::string& html) {
  output::AtomicFile file(path);
  std::ofstream page(file.temp_path(), std::ios::binary);
  if (!page) throw_output_error("cannot create", path, errno);
  page << html;
  page.close();
  if (!page) throw_output_error("cannot write", path, errno);
  file.commit();
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

}  // namespace

int gallery_command(const GalleryOptions& options) {
  const fs::path out(options.out_dir);
  std::vector<std::pair<GalleryRank, GalleryEntry>> ranked;
  // Every scene is parsed first, so a bad one fails before anything is written.
  for (const auto& path : options.scene_paths) {
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
  for (auto& [rank, entry] : ranked) entries.push_back(std::move(entry));

  GalleryHeader header{output::program_version(), output::program_build_id(), "", machine()};
  // Up to date: the same page but for its date (output/manifest.hpp).
  const std::string head =
      "  \"manifest\": 1,\n  \"command\": \"gallery\",\n  \"page_sha256\": \"" +
      output::sha256_text(gallery_html(entries, header)) + "\",\n";
  const cache::CacheOutcome outcome =
      run_cached({out / "gallery-manifest.json", head, out, options.force, false,
                  [&]() -> std::optional<cache::JobOutputs> {
                    std::error_code ec;
                    output::make_directories(out, ec);
                    if (ec) throw_output_error("cannot create output directory", out, ec.value());
                    header.date = utc_now();
                    write_page(out / "index.html", gallery_html(entries, header));
                    return cache::JobOutputs{"", {"index.html"}};
                  }},
                 "index.html");
  if (outcome == cache::CacheOutcome::up_to_date) return kExitOk;
  std::cout << "wrote " << (out / "index.html").string() << " (" << entries.size() << " clips)\n";
  return kExitOk;
}

}  // namespace bookspin::cli
