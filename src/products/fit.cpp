#include "products/fit.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>

#include "cache/make_cached.hpp"
#include "charts/toss_plots.hpp"
#include "clip/clip.hpp"
#include "output/atomic_output.hpp"
#include "output/manifest.hpp"
#include "output/output_dir.hpp"
#include "output/png_writer.hpp"
#include "output/sha256.hpp"
#include "output/staged_files.hpp"
#include "products/explorer.hpp"
#include "products/fit_scene.hpp"
#include "scene/canonical.hpp"

namespace bookspin::products {
namespace {

/// Renders every toss's clip (fit_clip.hpp) into a scratch folder of the run, which the clip
/// loop puts its complete videos in, and stages them into `files` under the layout's names:
/// they go in place with the tables and charts or not at all. The scratch folder (a hidden
/// temporary beside the manifest, with the tiles' diagnostics CSVs) is removed either way.
void render_toss_clips(const FitJob& job, const scene::Scene& base,
                       const fit::GyroRecording& recording, const fit::FitResult& fit,
                       const FitLayout& layout, output::StagedFiles& files) {
  const output::AtomicDirectory scratch(layout.manifest.parent_path() / "render");
  const std::filesystem::path& folder = scratch.temp_path();
  const std::vector<std::string>& formats = base.render.formats;
  for (std::size_t k = 0; k < fit.tosses.size(); ++k) {
    const int toss = static_cast<int>(k);
    clip::ClipRequest request;
    request.scene = toss_clip_scene(base, recording.name, fit, toss, job.render->slow_motion);
    const std::string name = "toss" + std::to_string(k + 1);
    request.paths = {folder / (name + ".mp4"), folder / (name + ".webm"), folder / (name + ".gif"),
                     folder / (name + "-frames"), folder / (name + "-measured.csv")};
    request.tile_csvs = {folder / (name + "-exact-fit.csv")};
    request.tile_models = toss_tile_models(recording, fit, toss, request.scene.body);
    request.write_png = false;
    request.stop_signal = job.stop_signal;
    clip::render_clip(request);
    for (std::size_t f = 0; f < formats.size(); ++f)
      files.adopt(layout.videos[k * formats.size() + f], folder / (name + "." + formats[f]));
  }
}

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
    layout.measured.push_back(out_dir / (toss + "-measured.csv"));
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

cache::Outcome make_fit(const FitJob& job, std::vector<std::string>* summary) {
  // The recording is read before the manifest check: its name names the outputs, and its
  // samples are what the outputs depend on.
  const fit::GyroRecording recording = fit::read_recording(job.recording);
  JsonArray tosses;
  for (const auto& [a, b] : job.tosses)
    tosses.push_back({JsonArray{{JsonNumber{a, NumberStyle::digits17}},
                                {JsonNumber{b, NumberStyle::digits17}}}});
  JsonArray moments;
  if (job.moments)
    for (int i = 0; i < 3; ++i)
      moments.push_back({JsonNumber{(*job.moments)[i], NumberStyle::digits17}});
  // The samples' exact bits (and the pauses'): a changed sample or pause remakes the fit.
  std::string samples;
  const auto append = [&](double value) {
    samples.append(reinterpret_cast<const char*>(&value), sizeof value);
  };
  for (std::size_t i = 0; i < recording.t.size(); ++i) {
    append(recording.t[i]);
    for (int c = 0; c < 3; ++c) append(recording.omega[i][c]);
  }
  for (double pause : recording.pauses) append(pause);
  // The program first, as every scene product's head has it: a rebuilt bookspin fits again.
  JsonObject members{{"bookspin",
                      {JsonObject{{"version", {output::program_version()}},
                                  {"build_id", {"sha256:" + output::program_build_id()}}}}},
                     {"recording", {output::sha256_text(samples)}},
                     {"tosses", {std::move(tosses)}},
                     {"moments", {std::move(moments)}},
                     {"width", {std::int64_t{job.width}}},
                     {"height", {std::int64_t{job.height}}},
                     {"drag", {std::string(physics::to_string(job.drag))}}};
  // --render: the clips' scene (before anything is made: a bad scene writes nothing), its
  // resolved keys and the files it reads in the head.
  const std::optional<scene::Scene> clip_scene =
      job.render ? std::optional(fit_clip_scene(*job.render)) : std::nullopt;
  std::vector<std::filesystem::path> input_files;
  if (clip_scene) {
    const JsonObject render{{"slow_motion", {JsonNumber{job.render->slow_motion}}},
                            {"scene", {scene::canonical_scene(*clip_scene), true}}};
    // First: a head that only added members after the plain fit's would begin with the plain
    // head, which manifest_stale() matches as a prefix.
    members.insert(members.begin(), {"render", {render, true}});
    const scene::RenderOptions& r = clip_scene->render;
    for (const std::string& file :
         {r.texture_front, r.texture_back, r.texture_spine, r.texture_pages, clip_scene->body_mesh})
      if (!file.empty()) input_files.emplace_back(file);
  }
  const std::filesystem::path manifest = job.out_dir / recording.name / "fit-manifest.json";
  const cache::CachedOutputs cached{
      recording.name + "-fit", manifest,   "fit", members, job.out_dir, nullptr,
      /*all_or_nothing=*/true, input_files};
  const cache::Outcome outcome = cache::make_cached(cached, job.freshness, [&] {
    // The stops: before the flights are sought and fitted, before each chart, and before the
    // files go in place (docs/outputs.md, "Signals").
    stop_if_asked(job.stop_signal, "fit flights");
    const fit::FlightSearch search = job.tosses.empty() ? fit::find_flights(recording)
                                                        : fit::hand_flights(recording, job.tosses);
    fit::FitSettings settings;
    settings.moments = job.moments;
    settings.drag = job.drag;
    const fit::FitResult result = fit::fit_recording(recording, search, settings);
    if (clip_scene && !result.body.moments_determined && !result.body.moments_fixed)
      throw InputError(recording.source +
                       ": --render: every toss is stable (no flip), so the fit cannot tell the "
                       "moments apart and has no motion to show; give --moments");
    const bool scenes = toss_book(result.body).has_value();
    const FitLayout layout =
        fit_layout(job.out_dir, recording.name, static_cast<int>(result.tosses.size()), scenes,
                   clip_scene ? clip_scene->render.formats : std::vector<std::string>{});
    std::vector<RgbaImage> charts;
    for (std::size_t k = 0; k < result.tosses.size(); ++k) {
      stop_if_asked(job.stop_signal, "fit charts");
      charts.push_back(
          charts::toss_image(recording, result, static_cast<int>(k), job.width, job.height));
    }
    output::prepare_output_dir(layout.csv.parent_path());
    output::StagedFiles files;  // the tables and every chart together, or none
    files.text(layout.csv, csv_text(fit::fit_toss_csv(result), "fit CSV"));
    files.text(layout.body_csv, csv_text(fit::fit_body_csv(result), "fit body CSV"));
    for (std::size_t k = 0; k < charts.size(); ++k) files.png(layout.pngs[k], charts[k]);
    for (std::size_t k = 0; k < layout.scenes.size(); ++k) {
      const int toss = static_cast<int>(k);
      files.text(layout.measured[k],
                 csv_text(toss_measured_csv(recording, result, toss), "fit measured CSV"));
      files.text(layout.scenes[k], toss_scene_text(result, toss, recording.name,
                                                   layout.measured[k].filename().string()));
    }
    if (clip_scene) render_toss_clips(job, *clip_scene, recording, result, layout, files);
    stop_if_asked(job.stop_signal, "fit files");
    files.commit();
    if (summary) {
      *summary = fit::fit_summary(result);
      summary->push_back("wrote " + layout.csv.string() + ", " + layout.body_csv.string() +
                         " and " + std::to_string(layout.pngs.size()) + " chart(s)" +
                         (layout.videos.empty()
                              ? std::string()
                              : ", " + std::to_string(layout.videos.size()) + " video(s)"));
      if (scenes) {
        summary->push_back(explore_line(job.out_dir, recording.name));
      } else {
        summary->push_back(
            "no scene of the tosses: the fitted moments break the triangle inequality "
            "(I1 + I2 > I3) or make a body too flat for a scene: no rigid body has them");
      }
    }
    return cache::Made{layout.outputs()};
  });
  // Up to date: the tosses' scenes are there, and how to open them is said again.
  if (outcome == cache::Outcome::up_to_date && summary &&
      std::filesystem::exists(job.out_dir / (recording.name + "-toss1.toml")))
    summary->push_back(explore_line(job.out_dir, recording.name));
  return outcome;
}

}  // namespace bookspin::products
