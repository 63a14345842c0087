// Bench section `presets`: which x264 preset and CRF give medium/CRF 18's picture for less
// encoding. Real clips' frames are rendered once, encoded with every preset from ultrafast
// to medium over a CRF range, decoded back to RGB and compared with the frames
// (video/video_quality.hpp: SSIM of the luma and PSNR over R, G, B, our own code). The rule
// (docs/performance-video.md): the fastest pair whose SSIM and PSNR are within 0.0005 and 0.1 dB
// of medium/CRF 18's on every clip, at no more than 1.25× its file size.
#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "bench/clip_runs.hpp"
#include "bench/sections.hpp"
#include "clip/clip.hpp"
#include "output/atomic_output.hpp"
#include "output/png_writer.hpp"
#include "products/clip.hpp"
#include "scene/scene.hpp"
#include "video/video.hpp"

namespace bookspin::bench {

namespace {

constexpr const char* kReferencePreset = "medium";
constexpr int kReferenceCrf = 18;
constexpr double kSsimSlack = 0.0005, kPsnrSlackDb = 0.1, kSizeLimit = 1.25;
const std::vector<std::string> kPresets = {"ultrafast", "superfast", "veryfast",
                                           "faster",    "fast",      "medium"};

/// One clip's frames as `bookspin render` writes them (PNG, lossless), and its frame rate.
struct RawClip {
  std::string name;
  int fps = 30;
  std::vector<RgbaImage> frames;
};

/// One encoding of one clip, decoded back and compared with the raw frames.
struct Encoding {
  double ssim = 0, psnr = 0, bytes = 0, cpu = 0;
};

/// The first `frames` frames of `scene_path` rendered once with PNG frames, read back.
RawClip render_raw(const BenchContext& c, const std::string& scene_path, int frames) {
  products::ClipJob job;
  job.scene = scene::parse_scene(scene_path, {});
  job.scene.frames = std::min(frames, job.scene.frames);
  job.out_dir = c.scratch / "presets-raw";
  job.write_png = true;
  job.png_compression = 1;
  job.jobs = c.options.jobs;
  const clip::ClipRequest request = products::clip_request(job);
  clip::render_clip(request);
  RawClip raw{job.scene.name, job.scene.render.fps, {}};
  for (int i = 0; i < job.scene.frames; ++i)
    raw.frames.push_back(output::read_png(request.paths.frames_dir / clip::frame_file_name(i)));
  std::filesystem::remove_all(job.out_dir);
  return raw;
}

Encoding encode_and_compare(const BenchContext& c, const RawClip& raw, const std::string& preset,
                            int crf) {
  const auto file = c.scratch / "presets.mp4";
  video::EncoderSettings settings;
  settings.width = raw.frames.front().width;
  settings.height = raw.frames.front().height;
  settings.fps = raw.fps;
  settings.crf = crf;
  settings.preset = preset;
  settings.threads = c.options.jobs;
  Encoding e;
  {
    const Stopwatch stopwatch;
    video::Mp4Encoder encoder(file, settings);
    for (const RgbaImage& frame : raw.frames) encoder.add_frame(frame);
    encoder.finish();
    e.cpu = stopwatch.elapsed().cpu;
  }
  e.bytes = static_cast<double>(std::filesystem::file_size(file));
  double ssim = 0, squared = 0;
  std::int64_t samples = 0;
  std::size_t index = 0;
  video::decode_video(file, [&](const RgbaImage& decoded) {
    if (index >= raw.frames.size())
      throw std::runtime_error("bench: more frames decoded than encoded");
    const video::FrameQuality q = video::frame_quality(raw.frames[index++], decoded);
    ssim += q.ssim;
    squared += q.squared_error;
    samples += q.samples;
  });
  if (index != raw.frames.size()) throw std::runtime_error("bench: decoded frames are missing");
  e.ssim = ssim / static_cast<double>(index);
  e.psnr = video::psnr_db(squared, samples);
  std::filesystem::remove(file);
  return e;
}

std::string pair_text(const std::string& preset, int crf) {
  return preset + " crf " + std::to_string(crf);
}

/// What one preset × CRF did over every clip, against medium/CRF 18.
struct PairVerdict {
  double cpu = 0;              ///< encoding CPU seconds summed over the clips
  double ssim_margin = 1e300;  ///< smallest SSIM − reference SSIM over the clips
  double psnr_margin = 1e300;  ///< smallest PSNR − reference PSNR (dB)
  double size_ratio = 0;       ///< largest file size / reference size
  bool qualifies() const {
    return ssim_margin >= -kSsimSlack && psnr_margin >= -kPsnrSlackDb && size_ratio <= kSizeLimit;
  }
};

/// The pairs from the fastest preset to medium, each over the CRFs in order.
std::vector<std::pair<std::pair<std::string, int>, PairVerdict>> ordered(
    const std::map<std::pair<std::string, int>, PairVerdict>& verdicts,
    const std::vector<int>& crfs) {
  std::vector<std::pair<std::pair<std::string, int>, PairVerdict>> pairs;
  for (const std::string& preset : kPresets)
    for (int crf : crfs) pairs.emplace_back(std::pair{preset, crf}, verdicts.at({preset, crf}));
  return pairs;
}

}  // namespace

void bench_presets(const BenchContext& c) {
  const BenchOptions& o = c.options;
  std::vector<int> crfs = o.preset_crfs;
  if (std::find(crfs.begin(), crfs.end(), kReferenceCrf) == crfs.end())
    crfs.push_back(kReferenceCrf);
  std::sort(crfs.begin(), crfs.end());
  using Key = std::pair<std::string, int>;
  std::map<Key, PairVerdict> verdicts;
  std::string csv =
      "clip,frames,width,height,preset,crf,ssim,psnr_db,bytes,encode_cpu_s,ssim_minus_reference,"
      "psnr_minus_reference_db,size_over_reference,cpu_over_reference,within_rule\n";
  for (const std::string& scene_path : o.preset_scenes) {
    const RawClip raw = render_raw(c, scene_path, o.preset_frames);
    std::map<Key, Encoding> results;
    for (const std::string& preset : kPresets)
      for (int crf : crfs) results[{preset, crf}] = encode_and_compare(c, raw, preset, crf);
    const Encoding& ref = results.at({kReferencePreset, kReferenceCrf});
    for (const auto& [key, e] : results) {
      PairVerdict& v = verdicts[key];
      v.cpu += e.cpu;
      v.ssim_margin = std::min(v.ssim_margin, e.ssim - ref.ssim);
      v.psnr_margin = std::min(v.psnr_margin, e.psnr - ref.psnr);
      v.size_ratio = std::max(v.size_ratio, e.bytes / ref.bytes);
      const bool within = e.ssim - ref.ssim >= -kSsimSlack && e.psnr - ref.psnr >= -kPsnrSlackDb &&
                          e.bytes / ref.bytes <= kSizeLimit;
      char line[512];
      std::snprintf(
          line, sizeof line, "%s,%zu,%d,%d,%s,%d,%.6f,%.4f,%.0f,%.4f,%.6f,%.4f,%.4f,%.4f,%s\n",
          raw.name.c_str(), raw.frames.size(), raw.frames.front().width, raw.frames.front().height,
          key.first.c_str(), key.second, e.ssim, e.psnr, e.bytes, e.cpu, e.ssim - ref.ssim,
          e.psnr - ref.psnr, e.bytes / ref.bytes, e.cpu / ref.cpu, within ? "yes" : "no");
      csv += line;
    }
    c.report->remark("presets: " + raw.name + ", " + std::to_string(raw.frames.size()) +
                     " frames encoded " + std::to_string(results.size()) + " times");
  }
  const PairVerdict& ref = verdicts.at({kReferencePreset, kReferenceCrf});
  Key chosen{kReferencePreset, kReferenceCrf};
  for (const auto& [key, v] : ordered(verdicts, crfs)) {
    char note[160];
    std::snprintf(note, sizeof note,
                  "worst clip: SSIM %+.5f, PSNR %+.3f dB, size %.3fx of medium crf 18; %s",
                  v.ssim_margin, v.psnr_margin, v.size_ratio,
                  v.qualifies() ? "within the rule" : "outside the rule");
    c.report->add({"presets", pair_text(key.first, key.second) + ": encoding CPU / medium crf 18",
                   v.cpu / ref.cpu, "x", note});
    if (v.qualifies() && v.cpu < verdicts.at(chosen).cpu) chosen = key;
  }
  c.report->add(
      {"presets", "the rule's pick: " + pair_text(chosen.first, chosen.second),
       verdicts.at(chosen).cpu / ref.cpu, "x",
       "encoding CPU of the fastest pair within SSIM -0.0005, PSNR -0.1 dB, size 1.25x on "
       "every clip"});
  if (!o.out_dir.empty()) {
    const auto path = std::filesystem::path(o.out_dir) / "presets.csv";
    output::AtomicFile file(path);
    std::ofstream out(file.temp_path(), std::ios::binary);
    out << csv;
    out.close();
    if (!out) throw_output_error("cannot write", path, errno);
    file.commit();
    c.report->remark("wrote " + path.string());
  }
  // The whole render with the old default and the pick, alternated, best of each.
  const int w = 1280, h = 720, frames = o.frames, rounds = std::max(1, o.rounds);
  Timing old_default, pick;
  for (int round = 0; round < rounds; ++round) {
    old_default.keep_best(
        timed_render(clip_request(c, "old-default", w, h, frames, false,
                                  {"render.preset=\"" + std::string(kReferencePreset) + "\"",
                                   "render.crf=" + std::to_string(kReferenceCrf)})));
    pick.keep_best(timed_render(clip_request(c, "pick", w, h, frames, false,
                                             {"render.preset=\"" + chosen.first + "\"",
                                              "render.crf=" + std::to_string(chosen.second)})));
  }
  const std::string what = ", render --no-png " + std::to_string(frames) + " frames 1280x720";
  const std::string of = "best of " + std::to_string(rounds) + " alternated runs";
  c.report->add({"presets", "medium crf 18" + what, old_default.wall, "s", of});
  c.report->add({"presets", pair_text(chosen.first, chosen.second) + what, pick.wall, "s", of});
  c.report->add({"presets", "pick / medium crf 18, wall time", pick.wall / old_default.wall, "x",
                 "the same runs"});
  c.report->add({"presets", "pick / medium crf 18, CPU time", pick.cpu / old_default.cpu, "x",
                 "the same runs, all threads"});
}

}  // namespace bookspin::bench
