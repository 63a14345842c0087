#include <algorithm>
#include <fstream>
#include <iostream>
#include <sstream>

#include "cache/manifests.hpp"
#include "cli/commands.hpp"
#include "cli/interrupt.hpp"
#include "cli/progress.hpp"
#include "clip/clip.hpp"
#include "common/errors.hpp"
#include "jobs/lattice_note.hpp"
#include "output/manifest.hpp"
#include "scene/canonical.hpp"

namespace bookspin::cli {

namespace {

clip::ClipRequest clip_request(const RenderArgs& args, scene::Scene scene, Progress& progress) {
  clip::ClipRequest request;
  request.scene = std::move(scene);
  request.out_dir = args.out_dir;
  request.write_png = !args.no_png;
  request.png_compression = args.png_compression;
  request.jobs = args.jobs;
  request.on_note = [](const std::string& note) {
    std::cerr << "bookspin: note: " << note << '\n';
  };
  request.on_progress = [&progress](int done) { progress.update(done); };
  request.stop_signal = interrupt_signal;
  return request;
}

/// The divergence warnings of a clip, without the "bookspin: warning: " prefix.
std::vector<std::string> divergence_warnings(const std::string& name,
                                             const clip::ClipResult& result) {
  std::vector<std::string> warnings;
  if (result.diverged_at) {
    std::ostringstream w;
    w << name << ": simulation diverged at t = " << *result.diverged_at
      << divergence_because(result.divergence_reason) << "; the clip holds the last finite frame";
    warnings.push_back(w.str());
  }
  for (const auto& tile : result.diverged_tiles) {
    std::ostringstream w;
    w << name << ": panel '" << tile.label << "' diverged at t = " << tile.t
      << "; its tile holds the last finite frame";
    warnings.push_back(w.str());
  }
  return warnings;
}

/// The manifest's "warnings" member (in its note: recorded, not compared), so that a run
/// that finds the clip up to date repeats them.
std::string warnings_json(const std::vector<std::string>& warnings) {
  std::string json = "  \"warnings\": [";
  for (std::size_t i = 0; i < warnings.size(); ++i)
    json.append(i == 0 ? "" : ", ").append(scene::json_string(warnings[i]));
  return json.append("],\n");
}

/// The warnings recorded in a manifest by warnings_json(), unescaped (only \" and \\ occur
/// in them in practice; anything else is kept as written).
std::vector<std::string> recorded_warnings(const std::filesystem::path& manifest) {
  std::ifstream in(manifest);
  std::vector<std::string> warnings;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("  \"warnings\": [", 0) != 0) continue;
    std::string current;
    bool inside = false;
    for (std::size_t i = line.find('[') + 1; i < line.size(); ++i) {
      const char c = line[i];
      if (!inside) {
        inside = c == '"';
      } else if (c == '\\' && i + 1 < line.size()) {
        current += line[++i];
      } else if (c == '"') {
        warnings.push_back(current);
        current.clear();
        inside = false;
      } else {
        current += c;
      }
    }
  }
  return warnings;
}

}  // namespace

std::string divergence_because(const std::string& reason) {
  return reason.empty() ? "" : "; " + reason;
}

cache::CacheOutcome run_cached(const cache::CachedJob& job, const std::string& name) {
  const cache::CacheOutcome outcome = cache::run_cached(job, [&name](const std::string& reason) {
    std::cerr << "bookspin: note: " << name << ": making it again: " << reason << '\n';
  });
  if (outcome == cache::CacheOutcome::up_to_date) std::cout << "up to date: " << name << std::endl;
  return outcome;
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
  scene::Scene scene = scene::parse_scene(args.scene_path, args.overrides);
  if (formats) scene.render.formats = *formats;
  for (const std::string& warning : scene.warnings)
    std::cerr << "bookspin: warning: " << warning << '\n';
  if (const std::string note = jobs::lattice_note(scene); !note.empty())
    std::cerr << "bookspin: " << note << '\n';
  if (args.frames > 0) scene.frames = args.frames;
  const std::string name = scene.name;
  Progress progress(name, scene.frames);
  const clip::ClipRequest request = clip_request(args, std::move(scene), progress);
  const auto manifest = cache::clip_manifest_path(args.out_dir, name);
  // An interrupted render puts no output in place, so the old manifest stays true.
  clip::ClipResult result;
  std::vector<std::string> warnings;
  const cache::CacheOutcome outcome = run_cached(
      {manifest, cache::clip_manifest_head(request), args.out_dir, args.force, args.verify,
       [&]() -> std::optional<cache::JobOutputs> {
         result = clip::render_clip(request);
         if (result.signal != 0) return std::nullopt;
         warnings = divergence_warnings(name, result);
         return cache::JobOutputs{cache::manifest_note(request.scene) + warnings_json(warnings),
                                  cache::clip_outputs(request)};
       }},
      name);
  if (outcome == cache::CacheOutcome::up_to_date) {
    for (const auto& warning : recorded_warnings(manifest))
      std::cerr << "bookspin: warning: " << warning << " (when it was rendered)\n";
    return kExitOk;
  }
  if (outcome == cache::CacheOutcome::interrupted) {
    std::cerr << "\nbookspin: interrupted; removed the unfinished outputs of " << name << '\n';
    return 128 + result.signal;
  }
  progress.finish(result.frames);
  for (const auto& warning : warnings) std::cerr << "bookspin: warning: " << warning << '\n';
  std::cout << "rendered: " << name << " (" << result.frames << " frames)" << std::endl;
  return kExitOk;
}

}  // namespace bookspin::cli
