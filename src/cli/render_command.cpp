#include <algorithm>
#include <iostream>

#include "cache/freshness.hpp"
#include "cli/commands.hpp"
#include "cli/interrupt.hpp"
#include "cli/progress.hpp"
#include "common/errors.hpp"
#include "jobs/lattice_note.hpp"
#include "products/clip.hpp"
#include "scene/scene.hpp"

namespace bookspin::cli {

void remake_note(const std::string& name, const std::string& reason) {
  std::cerr << "bookspin: note: " << name << ": making it again: " << reason << '\n';
}

std::vector<std::string> parse_format_list(const std::string& list) {
  std::vector<std::string> formats;
  std::size_t start = 0;
  while (!list.empty() && start <= list.size()) {
    const std::size_t comma = std::min(list.find(',', start), list.size());
    std::string name = list.substr(start, comma - start);
    const auto first = name.find_first_not_of(" \t");
    name = first == std::string::npos
               ? ""
               : name.substr(first, name.find_last_not_of(" \t") + 1 - first);
    formats.push_back(name);
    start = comma + 1;
  }
  if (formats.size() == 1 && formats[0].empty()) formats.clear();
  if (const std::string problem = scene::video_formats_problem(formats); !problem.empty())
    throw InputError("--format: " + problem);
  return formats;
}

int render_command(const RenderArgs& args) {
  install_interrupt_handlers();
  std::optional<std::vector<std::string>> formats;
  if (args.formats) formats = parse_format_list(*args.formats);
  products::ClipJob job;
  job.scene = scene::parse_scene(args.scene_path, args.overrides);
  if (formats) job.scene.render.formats = *formats;
  for (const std::string& warning : job.scene.warnings)
    std::cerr << "bookspin: warning: " << warning << '\n';
  if (const std::string note = jobs::lattice_note(job.scene); !note.empty())
    std::cerr << "bookspin: " << note << '\n';
  const std::string name = job.scene.name;
  Progress progress(name, job.scene.frames);
  job.out_dir = args.out_dir;
  job.write_png = !args.no_png;
  job.png_compression = args.png_compression;
  job.jobs = args.jobs;
  job.freshness = {args.force, args.verify, remake_note};
  job.on_note = [](const std::string& note) { std::cerr << "bookspin: note: " << note << '\n'; };
  job.on_progress = [&progress](int done) { progress.update(done); };
  job.stop_signal = stop_poll();
  const products::ClipOutcome done = products::make_clip(job);
  if (done.outcome == cache::Outcome::up_to_date) {
    std::cout << "up to date: " << name << std::endl;
    for (const auto& warning : done.warnings)
      std::cerr << "bookspin: warning: " << warning << " (when it was rendered)\n";
    return kExitOk;
  }
  progress.finish(done.result.frames);
  for (const auto& warning : done.warnings) std::cerr << "bookspin: warning: " << warning << '\n';
  std::cout << "rendered: " << name << " (" << done.result.frames << " frames)" << std::endl;
  return kExitOk;
}

}  // namespace bookspin::cli
