// `bookspin render` run after run: the outputs of one run are put in place together or not at
// all, a folder holds the outputs of one run only, and every video format plays for as long
// as the clip (docs/outputs.md, "One run's outputs, all or nothing" and "Video formats").
// Videos are read back with FFmpeg's command-line ffprobe, not bookspin's code.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <vector>

#include "support/cli_runner.hpp"

namespace bookspin::cli {
namespace {

using namespace bookspin::test;  // the shared runner (tests/support)

namespace fs = std::filesystem;

const std::string kScene = "fig09-matrix-unstable-x";
const std::string kSmall =
    " --set render.width=128 --set render.height=96 --set render.preset='\"ultrafast\"'"
    " --set render.gif_width=64";

std::vector<std::string> names(const std::map<std::string, std::string>& files) {
  std::vector<std::string> list;
  for (const auto& [name, bytes] : files) list.push_back(name);
  return list;
}

CliResult render(const fs::path& out, const std::string& options) {
  return run_bookspin("render " + scene_path(kScene) + kSmall + " " + options + " -o " +
                      out.string());
}

// A rerun that fails after the videos were encoded (the GIF's path is taken by a folder, so
// it cannot be put in place after the MP4 and WebM were finished) or before anything is
// encoded (a GIF rate no GIF can play: exit 2) leaves every earlier output and the manifest
// byte for byte, and nothing of its own (no temporary).
TEST(RenderRuns, AFailedRerunLeavesTheEarlierOutputsAndManifestByteForByte) {
  const fs::path out = fresh_dir("render_runs_failed");
  ASSERT_EQ(render(out, "--frames 6 --format mp4,webm").status, 0);
  fs::create_directories(out / (kScene + ".gif"));
  std::ofstream(out / (kScene + ".gif") / "notes.txt") << "someone else's";
  const auto before = tree_of(out);
  ASSERT_EQ(before.count(kScene + "/manifest.json"), 1u) << testing::PrintToString(names(before));
  ASSERT_EQ(before.count(kScene + "/frames/frame_00005.png"), 1u);

  // Another scene (crf 20), all three formats: the GIF fails last.
  const CliResult failed = render(out, "--frames 6 --set render.crf=20 --format mp4,webm,gif");
  EXPECT_EQ(failed.status, 1) << failed.output;
  EXPECT_NE(failed.output.find("bookspin: error: cannot "), std::string::npos) << failed.output;
  EXPECT_NE(failed.output.find(kScene + ".gif"), std::string::npos) << failed.output;
  EXPECT_EQ(failed.output.find(" @ 0x"), std::string::npos) << failed.output;  // no FFmpeg line
  EXPECT_EQ(tree_of(out), before) << testing::PrintToString(names(tree_of(out)));

  // Bad input: refused before anything is written.
  const CliResult bad = render(out,
                               "--frames 48 --set render.fps=120 --set render.gif_fps=50 "
                               "--format mp4,webm,gif");
  EXPECT_EQ(bad.status, 2) << bad.output;
  EXPECT_NE(bad.output.find("render.gif_fps: "), std::string::npos) << bad.output;
  EXPECT_EQ(tree_of(out), before);

  // Still up to date: the manifest tells the truth about the earlier run.
  EXPECT_NE(render(out, "--frames 6 --format mp4,webm").output.find("up to date"),
            std::string::npos);
}

/// Every src=, poster= and href= value of the gallery page (the files it links).
std::vector<std::string> linked(const fs::path& out) {
  const std::string html = read_file(out / "index.html");
  std::vector<std::string> files;
  for (const std::string attribute : {"src=\"", "poster=\"", "href=\""}) {
    for (std::size_t at = html.find(attribute); at != std::string::npos;
         at = html.find(attribute, at + 1)) {
      const std::size_t begin = at + attribute.size();
      files.push_back(html.substr(begin, html.find('"', begin) - begin));
    }
  }
  return files;
}

bool links(const std::vector<std::string>& files, const std::string& file) {
  return std::find(files.begin(), files.end(), file) != files.end();
}

// After `--format mp4,gif`, a scene change and `--format mp4` with `--no-png`, the GIF and
// the frames of the first run are gone, the manifest lists the MP4 and CSV alone, and the
// gallery links neither the GIF nor a frame, even when a GIF is put back by hand.
TEST(RenderRuns, ARerunHoldsTheOutputsOfOneRunOnlyAndTheGalleryLinksOnlyThose) {
  const fs::path out = fresh_dir("render_runs_one_run");
  const std::string gif = kScene + ".gif";
  ASSERT_EQ(render(out, "--frames 4 --format mp4,gif").status, 0);
  ASSERT_EQ(run_bookspin("gallery " + out.string() + " " + scene_path(kScene)).status, 0);
  EXPECT_TRUE(links(linked(out), gif));
  EXPECT_TRUE(links(linked(out), kScene + "/frames/frame_00002.png"));  // the poster

  const CliResult rerun = render(out, "--frames 5 --no-png --format mp4");
  ASSERT_EQ(rerun.status, 0) << rerun.output;
  EXPECT_EQ(
      names(tree_of(out)),  // sorted: '.' comes before '/'
      (std::vector<std::string>{kScene, kScene + ".mp4", kScene + "/diagnostics.csv",
                                kScene + "/manifest.json", "gallery-manifest.json", "index.html"}));
  const std::string manifest = read_file(out / kScene / "manifest.json");
  EXPECT_EQ(manifest.find(gif + "\""), std::string::npos) << manifest;
  EXPECT_EQ(manifest.find("frames/"), std::string::npos) << manifest;

  fs::copy_file(out / (kScene + ".mp4"), out / gif,
                fs::copy_options::overwrite_existing);  // a file the last run did not make
  fs::create_directories(out / kScene / "frames");
  fs::copy_file(out / (kScene + ".mp4"), out / kScene / "frames" / "frame_00000.png");
  ASSERT_EQ(run_bookspin("gallery " + out.string() + " " + scene_path(kScene)).status, 0);
  const std::vector<std::string> files = linked(out);
  EXPECT_TRUE(links(files, kScene + ".mp4")) << testing::PrintToString(files);
  EXPECT_TRUE(links(files, kScene + "/diagnostics.csv")) << testing::PrintToString(files);
  EXPECT_FALSE(links(files, gif)) << testing::PrintToString(files);
  EXPECT_FALSE(links(files, kScene + "/frames/frame_00000.png")) << testing::PrintToString(files);
}

/// What ffprobe reads from the first video stream of `file`: the frames it decodes and the
/// time from the first packet's start to the last one's end, in seconds.
struct Played {
  int frames = -1;
  double seconds = -1.0;
};

Played ffprobe_played(const fs::path& file) {
  Played played;
  std::string count;
  run_shell(
      "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
      "stream=nb_read_frames -of csv=p=0 " +
          file.string(),
      count);
  played.frames = std::atoi(count.c_str());
  std::string packets;
  run_shell(
      "ffprobe -v error -select_streams v:0 -show_entries packet=pts_time,duration_time "
      "-of csv=p=0 " +
          file.string(),
      packets);
  std::istringstream lines(packets);
  double first = INFINITY, last = -INFINITY;
  for (std::string line; std::getline(lines, line);) {
    const auto comma = line.find(',');
    if (comma == std::string::npos) continue;
    const double pts = std::atof(line.c_str()), duration = std::atof(line.c_str() + comma + 1);
    first = std::min(first, pts);
    last = std::max(last, pts + duration);
  }
  if (std::isfinite(first)) played.seconds = last - first;
  return played;
}

// Each format of a real render, decoded: the MP4 and WebM hold every frame and last
// frames / fps; the GIF keeps every step-th frame (step = round(fps / gif_fps), worked out
// here by hand) and lasts as long as the clip, to the centisecond its delays are counted in.
// At the default GIF rate, a reduced one, and the fastest frame rates of the limits table.
TEST(RenderRuns, EveryFormatDecodesToTheClipsFrameCountAndDuration) {
  struct Case {
    int frames, fps, gif_fps, step;
  };
  // 30/15 (the default) → every 2nd; 30/5 → every 6th; 120/15 → every 8th; 240/50 → every 5th.
  for (const Case& c :
       {Case{12, 30, 15, 2}, Case{12, 30, 5, 6}, Case{48, 120, 15, 8}, Case{50, 240, 50, 5}}) {
    SCOPED_TRACE(std::to_string(c.fps) + " frames/s, GIF " + std::to_string(c.gif_fps));
    const fs::path out = fresh_dir("render_runs_timing");
    const CliResult r = render(out, "--frames " + std::to_string(c.frames) + " --no-png" +
                                        " --set render.fps=" + std::to_string(c.fps) +
                                        " --set render.gif_fps=" + std::to_string(c.gif_fps) +
                                        " --format mp4,webm,gif");
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_EQ(r.output.find("[gif @"), std::string::npos) << r.output;  // no raw FFmpeg line
    const double clip_seconds = static_cast<double>(c.frames) / c.fps;
    for (const char* ext : {".mp4", ".webm"}) {
      const Played p = ffprobe_played(out / (kScene + ext));
      EXPECT_EQ(p.frames, c.frames) << ext;
      EXPECT_NEAR(p.seconds, clip_seconds, 0.0011) << ext;  // WebM counts milliseconds
    }
    ASSERT_EQ(c.frames % c.step, 0);  // so the GIF's last kept frame ends the clip exactly
    const Played gif = ffprobe_played(out / (kScene + ".gif"));
    EXPECT_EQ(gif.frames, c.frames / c.step);
    // Each start is rounded to the centisecond and the last frame repeats the delay before it.
    EXPECT_NEAR(gif.seconds, clip_seconds, 0.0151);
  }
}

}  // namespace
}  // namespace bookspin::cli
