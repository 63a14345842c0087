// `bookspin gallery`: OUT/index.html over the clips, frames and plots already under OUT.
#include <algorithm>
#include <fstream>
#include <iostream>

#include "cli/commands.hpp"
#include "cli/gallery_page.hpp"
#include "output/atomic_output.hpp"
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
  if (exists(out, scene.name + ".mp4")) e.video = scene.name + ".mp4";
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

}  // namespace

int gallery_command(const GalleryOptions& options) {
  const fs::path out(options.out_dir);
  std::vector<GalleryEntry> entries;
  // Every scene is parsed first, so a bad one fails before anything is written.
  for (const auto& path : options.scene_paths)
    entries.push_back(entry_for(out, scene::parse_scene(path)));
  std::error_code ec;
  fs::create_directories(out, ec);
  if (ec) throw_output_error("cannot create output directory", out, ec.value());
  write_page(out / "index.html", gallery_html(entries));
  std::cout << "wrote " << (out / "index.html").string() << " (" << entries.size() << " clips)\n";
  return kExitOk;
}

}  // namespace bookspin::cli
