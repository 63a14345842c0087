#include "products/fit.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <memory>

#include "cache/make_cached.hpp"
#include "charts/toss_plots.hpp"
#include "clip/clip.hpp"
#include "common/sha256.hpp"
#include "output/atomic_output.hpp"
#include "output/manifest.hpp"
#include "output/output_dir.hpp"
#include "output/png_writer.hpp"
#include "output/staged_files.hpp"
#include "products/explorer.hpp"
#include "scene/limits.hpp"

namespace bookspin::products {

// The toss scenes' constants are the scene's own (fit/toss_scene.hpp): a scene file plays at
// the default frame rate, and its book is no smaller than a scene allows.
static_assert(fit::kTossSceneFramesPerSecond == *scene::limit("render.fps").fallback);
static_assert(fit::kMinTossBookSide == scene::limit("book.size").min);

namespace {

/// `path` as one word of a shell's command line: as it is when it holds nothing a shell reads
/// specially, else in single quotes.
std::string shell_word(const std::filesystem::path& path) {
  const std::string text = path.string();
  const bool plain = !text.empty() && std::all_of(text.begin(), text.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || (c != 0 && std::strchr("._/-+,:@%=", c));
  });
  if (plain) return text;
  std::string quoted = "'";
  for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

}  // namespace

std::vector<std::filesystem::path> FitLayout::outputs() const {
  std::vector<std::filesystem::path> all{csv, body_csv};
  all.insert(all.end(), pngs.begin(), pngs.end());
  all.insert(all.end(), scenes.begin(), scenes.end());
  all.insert(all.end(), measured.begin(), measured.end());
  all.insert(all.end(), videos.begin(), videos.end());
  return all;
}

FitLayout fit_layout(const std::filesystem::path& out_dir, const std::string& name, int tosses,
                     bool scenes, const std::vector<std::string>& video_formats) {
  FitLayout layout{out_dir / (name + "-fit.csv"),
                   out_dir / (name + "-fit-body.csv"),
                   {},
                   out_dir / name / "fit-manifest.json",
                   {},
                   {},
                   {}};
  for (int k = 1; k <= tosses; ++k) {
    const std::string toss = name + "-toss" + std::to_string(k);
    layout.pngs.push_back(out_dir / (toss + ".png"));
    for (const std::string& format : video_formats)
      layout.videos.push_back(out_dir / (toss + "." + format));
    if (!scenes) continue;
    layout.scenes.push_back(out_dir / (toss + ".toml"));
    layout.measured.push_back(out_dir / fit::toss_measured_file(name, k - 1));
  }
  return layout;
}

/// The command that opens every toss scene of `name` in OUT in the explorer: a shell glob, not
/// one word per toss.
std::string explore_line(const std::filesystem::path& out_dir, const std::string& name) {
  return "to play the tosses beside the measurement: bookspin explore " +
         shell_word(out_dir / (name + "-toss")) + "*.toml -o " + shell_word(out_dir) +
         ", then open " + explorer_page_path(out_dir).string();
}

namespace {

/// The fit's manifest head: with --render the clips' resolved scene, then the program, the
/// recording's samples (their exact bits, and the pauses': a changed sample remakes the fit)
/// and what was asked.
JsonObject fit_head(const FitJob& job) {
  // With --render, the clips' resolved scene first (a head that only added members after the
  // plain fit's would begin with the plain head, which manifest_stale() matches as a prefix).
  JsonObject members;
  if (job.clips) members.push_back({"render", {job.clips->head, true}});
  const fit::GyroRecording& recording = job.recording;
  JsonArray tosses;
  for (const auto& [a, b] : job.request.tosses)
    tosses.push_back({JsonArray{{JsonNumber{a, NumberStyle::digits17}},
                                {JsonNumber{b, NumberStyle::digits17}}}});
  JsonArray moments;
  if (job.request.settings.moments)
    for (int i = 0; i < 3; ++i)
      moments.push_back({JsonNumber{(*job.request.settings.moments)[i], NumberStyle::digits17}});
  std::string samples;
  const auto append = [&](double value) {
    samples.append(reinterpret_cast<const char*>(&value), sizeof value);
  };
  for (std::size_t i = 0; i < recording.t.size(); ++i) {
    append(recording.t[i]);
    for (int c = 0; c < 3; ++c) append(recording.omega[i][c]);
  }
  for (double pause : recording.pauses) append(pause);
  // Several pooled: the recordings' names too (they name each toss's recording in the tables).
  if (recording.parts.size() >= 2)
    for (const fit::RecordingPart& part : recording.parts) samples += part.name + '\n';
  // The program next, as every scene product's head has it: a rebuilt bookspin fits again.
  members.insert(members.end(),
                 {{"bookspin",
                   {JsonObject{{"version", {output::program_version()}},
                               {"build_id", {"sha256:" + output::program_build_id()}}}}},
                  {"recording", {sha256_text(samples)}},
                  {"tosses", {std::move(tosses)}},
                  {"moments", {std::move(moments)}},
                  {"width", {std::int64_t{job.width}}},
                  {"height", {std::int64_t{job.height}}},
                  {"drag", {std::string(physics::to_string(job.request.settings.drag))}}});
  return members;
}

/// Every file of a made fit, in memory or in a scratch folder, before any is put in place.
struct FitFiles {
  FitLayout layout;
  std::vector<std::string> summary;  ///< the report's lines, what was written, what next
  /// Each toss's clips, rendered into the scratch folder (fit_clip.hpp), each path under
  /// `layout.videos`' name; the folder, a hidden temporary beside the manifest, goes with it.
  std::unique_ptr<output::AtomicDirectory> scratch;
  std::vector<std::filesystem::path> videos;
  std::vector<RgbaImage> charts;  ///< one per toss (charts::toss_image)
  /// The tables, and each toss's measured ω and scene file where the fit has them.
  std::vector<std::pair<std::filesystem::path, std::string>> texts;
};

/// Renders each toss's clips into `files.scratch` (clip::render_clip, which puts its complete
/// videos there), in render.formats' order.
void render_toss_clips(const FitJob& job, const fit::FitReport& report, FitFiles& files) {
  const std::filesystem::path& folder = files.scratch->temp_path();
  for (std::size_t k = 0; k < report.tosses.size(); ++k) {
    clip::ClipRequest request;
    request.scene = toss_clip_scene(job.clips->scene, report.recording, report.result,
                                    static_cast<int>(k), job.clips->slow_motion);
    request.tile_models =
        toss_tile_models(report.result, report.tosses[k].chart, request.scene.body);
    const std::string name = "toss" + std::to_string(k + 1);
    request.paths = {folder / (name + ".mp4"), folder / (name + ".webm"), folder / (name + ".gif"),
                     folder / (name + "-frames"), folder / (name + "-measured.csv")};
    request.tile_csvs = {folder / (name + "-exact-fit.csv")};
    request.write_png = false;
    request.stop_signal = job.stop_signal;
    clip::render_clip(request);
    for (const std::string& format : request.scene.render.formats)
      files.videos.push_back(folder / (name + "." + format));
  }
}

/// Every file of `report`'s fit made (fit_layout names them): with --render each toss's clips
/// first, then each toss's chart, then the texts: the tables, each toss's measured ω and scene.
FitFiles fit_files(const FitJob& job, const fit::FitReport& report) {
  FitFiles files;
  files.layout = fit_layout(
      job.out_dir, report.recording, static_cast<int>(report.tosses.size()), report.has_scenes,
      job.clips ? job.clips->scene.render.formats : std::vector<std::string>{});
  const FitLayout& layout = files.layout;
  files.summary = report.summary;
  if (job.verbose)
    files.summary.insert(files.summary.end(), report.dropped.begin(), report.dropped.end());
  files.summary.push_back("wrote " + layout.csv.string() + ", " + layout.body_csv.string() +
                          " and " + std::to_string(layout.pngs.size()) + " chart(s)" +
                          (layout.videos.empty()
                               ? std::string()
                               : ", " + std::to_string(layout.videos.size()) + " video(s)"));
  // Without scenes, the report's summary has said why (fit::kNoSceneLine).
  if (report.has_scenes) files.summary.push_back(explore_line(job.out_dir, report.recording));
  if (job.clips) {
    files.scratch =
        std::make_unique<output::AtomicDirectory>(layout.manifest.parent_path() / "render");
    render_toss_clips(job, report, files);
  }
  for (const fit::TossReport& toss : report.tosses) {
    stop_if_asked(job.stop_signal, "fit charts");
    files.charts.push_back(charts::toss_image(toss.chart, job.width, job.height));
  }
  files.texts = {{layout.csv, report.toss_csv}, {layout.body_csv, report.body_csv}};
  for (std::size_t k = 0; k < layout.scenes.size(); ++k) {
    files.texts.emplace_back(layout.measured[k], report.tosses[k].measured_csv);
    files.texts.emplace_back(layout.scenes[k], report.tosses[k].scene_text);
  }
  return files;
}

}  // namespace

cache::Outcome make_fit(const FitJob& job, std::vector<std::string>* summary) {
  const std::string& name = job.recording.name;
  const std::string explore = explore_line(job.out_dir, name);
  JsonObject head = fit_head(job);
  const cache::CachedOutputs cached{
      name + "-fit",
      job.out_dir / name / "fit-manifest.json",
      "fit",
      std::move(head),
      job.out_dir,
      nullptr,
      /*all_or_nothing=*/true,
      job.clips ? job.clips->inputs : std::vector<std::filesystem::path>{}};
  const cache::Outcome outcome = cache::make_cached(cached, job.freshness, [&] {
    // The stops: before the flights are sought and fitted, before each toss's values, clip
    // frame and chart, and before the files go in place (docs/outputs.md, "Signals").
    const fit::FitReport report = fit::fit_report(job.recording, job.request, job.stop_signal);
    const fit::BodyEstimate& body = report.result.body;
    if (job.clips && !body.moments_determined && !body.moments_fixed)
      throw InputError(report.source +
                       ": --render: every toss is stable (no flip), so the fit cannot tell the "
                       "moments apart and has no motion to show; give --moments");
    const FitFiles files = fit_files(job, report);
    output::prepare_output_dir(job.out_dir);
    output::StagedFiles staged;  // every file put in place together, or none
    for (const auto& [path, text] : files.texts) staged.text(path, text);
    for (std::size_t k = 0; k < files.charts.size(); ++k)
      staged.png(files.layout.pngs[k], files.charts[k]);
    for (std::size_t k = 0; k < files.videos.size(); ++k)
      staged.adopt(files.layout.videos[k], files.videos[k]);
    stop_if_asked(job.stop_signal, "fit files");
    staged.commit();
    if (summary) *summary = files.summary;
    return cache::Made{files.layout.outputs()};
  });
  // Up to date: the tosses' scenes are there, and how to open them is said again.
  if (outcome == cache::Outcome::up_to_date && summary &&
      std::filesystem::exists(job.out_dir / (name + "-toss1.toml")))
    summary->push_back(explore);
  return outcome;
}

}  // namespace bookspin::products
