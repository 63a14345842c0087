#include "products/fit.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <sstream>

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

std::string fixed(double value, int digits) {
  std::ostringstream text;
  text.precision(digits);
  text << std::fixed << value;
  return text.str();
}

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

CsvTable fit_toss_csv(const fit::FitResult& fit) {
  CsvTable table{
      {"toss", "t_start", "t_end", "omega0_x", "omega0_y", "omega0_z", "half_period_measured",
       "half_period_fitted", "half_period_predicted", "residual_rms", "L_decay", "drag_rate",
       "drag_rate_sigma", "stable", "poor_fit", "flag"},
      {}};
  for (std::size_t k = 0; k < fit.tosses.size(); ++k) {
    const fit::TossFit& t = fit.tosses[k];
    table.rows.push_back(
        {std::to_string(k + 1), shortest_cell(t.flight.t_start), shortest_cell(t.flight.t_end),
         shortest_cell(t.omega0[0]), shortest_cell(t.omega0[1]), shortest_cell(t.omega0[2]),
         shortest_cell(t.half_period_measured), shortest_cell(t.half_period_fitted),
         shortest_cell(t.half_period_predicted), shortest_cell(t.residual_rms),
         shortest_cell(t.L_decay), shortest_cell(t.drag_rate), shortest_cell(t.drag_rate_sigma),
         std::string(t.stable ? "yes" : "no"), std::string(t.poor_fit ? "yes" : "no"), t.flag});
  }
  return table;
}

CsvTable fit_body_csv(const fit::FitResult& fit) {
  const fit::BodyEstimate& b = fit.body;
  CsvTable table{{"I1_over_I3",      "I2_over_I3",      "I3_over_I3", "I1_sigma", "I2_sigma",
                  "axis1_x",         "axis1_y",         "axis1_z",    "axis2_x",  "axis2_y",
                  "axis2_z",         "axis3_x",         "axis3_y",    "axis3_z",  "axis1_sigma_deg",
                  "axis2_sigma_deg", "axis3_sigma_deg", "moments",    "tosses",   "drag"},
                 {}};
  std::vector<CsvCell> row{shortest_cell(b.ratios[0]), shortest_cell(b.ratios[1]),
                           shortest_cell(b.ratios[2])};
  for (int i = 0; i < 2; ++i)
    row.push_back(
        shortest_cell(b.ratio_sigma ? std::optional<double>((*b.ratio_sigma)[i]) : std::nullopt));
  for (int a = 0; a < 3; ++a)
    for (int c = 0; c < 3; ++c) row.push_back(shortest_cell(b.axes(c, a)));
  for (int a = 0; a < 3; ++a)
    row.push_back(shortest_cell(b.axis_sigma_deg ? std::optional<double>((*b.axis_sigma_deg)[a])
                                                 : std::nullopt));
  row.push_back(std::string(b.moments_fixed        ? "given"
                            : b.moments_determined ? "fitted"
                                                   : "poorly determined"));
  row.push_back(std::to_string(fit.tosses.size()));
  row.push_back(std::string(physics::to_string(fit.drag)));
  table.rows.push_back(std::move(row));
  return table;
}

/// The command that opens every toss scene of `name` in OUT in the explorer: a shell glob, not
/// one word per toss.
std::string explore_line(const std::filesystem::path& out_dir, const std::string& name) {
  return "to play the tosses beside the measurement: bookspin explore " +
         shell_word(out_dir / (name + "-toss")) + "*.toml -o " + shell_word(out_dir) +
         ", then open " + explorer_page_path(out_dir).string();
}

std::vector<std::string> fit_summary(const fit::FitResult& fit) {
  std::vector<std::string> lines;
  const Eigen::Vector3d& bias = fit.search.bias;
  lines.push_back(fit.search.rest_samples > 0
                      ? "bias (rad/s, from " + std::to_string(fit.search.rest_samples) +
                            " samples at rest): " + fixed(bias[0], 4) + ", " + fixed(bias[1], 4) +
                            ", " + fixed(bias[2], 4)
                      : "no rest in the recording: the gyroscope's bias is not removed");
  for (std::size_t k = 0; k < fit.tosses.size(); ++k) {
    const fit::TossFit& t = fit.tosses[k];
    std::string drag;
    if (fit.drag != physics::DragLaw::none)
      drag = ", drag " + fixed(t.drag_rate, 3) +
             (t.drag_rate_sigma ? " ± " + fixed(*t.drag_rate_sigma, 3) : std::string()) + " /s";
    lines.push_back("kept toss " + std::to_string(k + 1) + ": " + fixed(t.flight.t_start, 3) + "–" +
                    fixed(t.flight.t_end, 3) + " s" + drag +
                    (t.stable ? " (stable: no flip)" : "") + (t.poor_fit ? " (flagged)" : ""));
  }
  for (const fit::DroppedStretch& d : fit.search.dropped)
    lines.push_back("dropped " + fixed(d.t_start, 3) + "–" + fixed(d.t_end, 3) + " s: " + d.reason);
  const fit::BodyEstimate& b = fit.body;
  std::string sigma;
  if (b.ratio_sigma && !b.moments_fixed)
    sigma = " (± " + fixed((*b.ratio_sigma)[0], 4) + ", ± " + fixed((*b.ratio_sigma)[1], 4) + ")";
  lines.push_back("moments I1 : I2 : I3 = " + fixed(b.ratios[0], 4) + " : " +
                  fixed(b.ratios[1], 4) + " : 1" + (b.moments_fixed ? " (given)" : sigma) +
                  (fit.drag == physics::DragLaw::none
                       ? ", no drag"
                       : ", " + std::string(physics::to_string(fit.drag)) + " drag"));
  for (const std::string& note : b.notes) lines.push_back("note: " + note);
  return lines;
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
    files.text(layout.csv, csv_text(fit_toss_csv(result), "fit CSV"));
    files.text(layout.body_csv, csv_text(fit_body_csv(result), "fit body CSV"));
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
      *summary = fit_summary(result);
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
