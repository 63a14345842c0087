// `bookspin render` end to end: outputs, frame counts, and failures that leave nothing
// behind (issues 3 and 8).
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "support/cli_runner.hpp"

namespace bookspin::cli {
namespace {

using namespace bookspin::test;  // the shared runner (tests/support)

namespace fs = std::filesystem;

const std::string kSmall =
    " --set render.width=128 --set render.height=96 --set render.preset='\"ultrafast\"'";

int count_files(const fs::path& dir) {
  int n = 0;
  if (fs::exists(dir))
    for (const auto& e : fs::recursive_directory_iterator(dir)) n += e.is_regular_file();
  return n;
}

int count_lines(const fs::path& file) {
  const std::string text = read_file(file);
  return static_cast<int>(std::count(text.begin(), text.end(), '\n'));
}

TEST(RenderCommand, WritesMp4FramesAndCsvWithMatchingCounts) {
  const fs::path out = fresh_dir("render_outputs");
  const CliResult r = run_bookspin("render " + scene_path("fig09-matrix-unstable-x") + kSmall +
                                   " --frames 9 -o " + out.string());
  ASSERT_EQ(r.status, 0) << r.output;
  const std::string name = "fig09-matrix-unstable-x";
  EXPECT_GT(fs::file_size(out / (name + ".mp4")), 1000u);
  EXPECT_EQ(count_files(out / name / "frames"), 9);
  EXPECT_TRUE(fs::exists(out / name / "frames" / "frame_00008.png"));
  EXPECT_EQ(count_lines(out / name / "diagnostics.csv"), 10);  // header + 9 rows
  const CliResult probe = [&] {
    CliResult p;
    FILE* pipe = popen(("ffprobe -v error -count_frames -select_streams v:0 -show_entries "
                        "stream=codec_name,pix_fmt,width,height,r_frame_rate,nb_read_frames "
                        "-of csv=p=0 " +
                        (out / (name + ".mp4")).string())
                           .c_str(),
                       "r");
    char line[256];
    while (pipe && fgets(line, sizeof line, pipe)) p.output += line;
    p.status = pipe ? pclose(pipe) : -1;
    return p;
  }();
  if (probe.status == 0) {
    EXPECT_EQ(probe.output, "h264,128,96,yuv420p,30/1,9\n");
  }
}

/// ffprobe's "codec,width,height,frames" of the first video stream of `file`, decoding every
/// frame (an independent reader: FFmpeg's command-line tool, not bookspin's code).
std::string ffprobe_stream(const fs::path& file) {
  std::string out;
  run_shell(
      "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
      "stream=codec_name,width,height,nb_read_frames -of csv=p=0 " +
          file.string(),
      out);
  return out;
}

TEST(RenderCommand, FormatsWriteMp4WebmAndGifFromOneRenderAndListThemInTheManifest) {
  const fs::path out = fresh_dir("render_formats");
  const std::string name = "fig09-matrix-unstable-x";
  const CliResult r = run_bookspin("render " + scene_path(name) + kSmall +
                                   " --set render.gif_width=64 --frames 9 --no-png "
                                   "--format mp4,webm,gif -o " +
                                   out.string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(ffprobe_stream(out / (name + ".mp4")), "h264,128,96,9\n");
  EXPECT_EQ(ffprobe_stream(out / (name + ".webm")), "vp9,128,96,9\n");
  // 30 frames/s → every 2nd frame at the default 15 frames/s: frames 0, 2, 4, 6, 8.
  EXPECT_EQ(ffprobe_stream(out / (name + ".gif")), "gif,64,48,5\n");
  const std::string manifest = read_file(out / name / "manifest.json");
  for (const char* ext : {".mp4", ".webm", ".gif"})
    EXPECT_NE(manifest.find("\"" + name + ext + "\""), std::string::npos) << ext << manifest;
  // Up to date with the same formats; another list is another render.
  EXPECT_NE(run_bookspin("render " + scene_path(name) + kSmall +
                         " --set render.gif_width=64 --frames 9 --no-png "
                         "--format mp4,webm,gif -o " +
                         out.string())
                .output.find("up to date"),
            std::string::npos);

  // The scene key alone, without the MP4.
  const fs::path only = fresh_dir("render_formats_webm");
  ASSERT_EQ(
      run_bookspin("render " + scene_path(name) + kSmall +
                   " --frames 3 --no-png --set 'render.formats=[\"webm\"]' -o " + only.string())
          .status,
      0);
  EXPECT_EQ(ffprobe_stream(only / (name + ".webm")), "vp9,128,96,3\n");
  EXPECT_FALSE(fs::exists(only / (name + ".mp4")));
  EXPECT_FALSE(fs::exists(only / (name + ".gif")));
}

TEST(RenderCommand, NoPngSkipsTheFrames) {
  const fs::path out = fresh_dir("render_no_png");
  ASSERT_EQ(run_bookspin("render " + scene_path("fig03-particle-stable-z") + kSmall +
                         " --frames 3 --no-png -o " + out.string())
                .status,
            0);
  EXPECT_TRUE(fs::exists(out / "fig03-particle-stable-z.mp4"));
  EXPECT_FALSE(fs::exists(out / "fig03-particle-stable-z" / "frames"));
}

// The clip's rows are the simulation's, frame for frame: the rows of the frames still in the
// render pipeline are those of the pose each frame shows, not of the simulation ahead of it.
TEST(RenderCommand, CsvIsByteForByteWhatSimulateWrites) {
  const fs::path out = fresh_dir("render_csv_is_simulate");
  const CliResult r = run_bookspin("render " + scene_path("fig09-matrix-unstable-x") + kSmall +
                                   " --no-png --frames 6 -o " + out.string());
  ASSERT_EQ(r.status, 0) << r.output;
  const fs::path csv = out / "simulated.csv";
  ASSERT_EQ(run_bookspin("simulate " + scene_path("fig09-matrix-unstable-x") +
                         " --set time.frames=6 --csv " + csv.string())
                .status,
            0);
  EXPECT_EQ(read_file(out / "fig09-matrix-unstable-x/diagnostics.csv"), read_file(csv));
}

TEST(RenderCommand, DivergedSceneRendersToTheEndAndWarns) {
  const fs::path out = fresh_dir("render_diverged");
  const CliResult r =
      run_bookspin("render " + scene_path("fig08-particle-neither") + kSmall +
                   " --set time.steps_per_frame=300 --frames 12 -o " + out.string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("warning: fig08-particle-neither: simulation diverged at t = "),
            std::string::npos)
      << r.output;
  EXPECT_EQ(count_files(out / "fig08-particle-neither" / "frames"), 12);
}

/// The lines of `text` that start with `prefix`.
std::vector<std::string> lines_starting(const std::string& text, const std::string& prefix) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (line.rfind(prefix, 0) == 0) lines.push_back(line);
  return lines;
}

// render.codec = "h264_nvenc" with the scene's default preset ("faster", x264's name, which
// NVENC gets as its own p2). Without an NVIDIA GPU (CI), h264_nvenc is in Debian's FFmpeg but
// cannot open, and the render falls back to libx264: one warning gives the reason `bookspin
// info` gives (the driver's), not a preset NVENC refused, and the manifest records libx264 as
// the MP4's encoder beside the render.codec asked for; found up to date, it says so again.
TEST(RenderCommand, NvencFallbackWarnsWithTheRealReasonAndTheManifestNamesLibx264) {
  const std::string info = run_bookspin("info").output;
  const std::string line = "H.264 encoder h264_nvenc: ";
  const auto at = info.find(line);
  if (at == std::string::npos) GTEST_SKIP() << "this FFmpeg has no h264_nvenc";
  const std::string status = info.substr(at + line.size(), info.find('\n', at) - at - line.size());
  const std::string name = "fig09-matrix-unstable-x";
  const fs::path out = fresh_dir("render_nvenc_fallback");
  const std::string args = "render " + scene_path(name) +
                           " --set render.width=256 --set render.height=144"
                           " --set render.codec='\"h264_nvenc\"' --frames 3 --no-png -o " +
                           out.string();
  const SplitResult r = run_bookspin_split(args);
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string manifest = read_file(out / name / "manifest.json");
  EXPECT_NE(manifest.find("\"render.codec\": \"h264_nvenc\""), std::string::npos) << manifest;
  EXPECT_NE(manifest.find("\"render.preset\": \"faster\""), std::string::npos) << manifest;
  const std::vector<std::string> warnings = lines_starting(r.err, "bookspin: warning: ");
  if (status == "usable") {  // a GPU with NVENC: it made the MP4
    EXPECT_NE(manifest.find("\"mp4_encoder\": \"h264_nvenc\""), std::string::npos) << manifest;
    EXPECT_TRUE(warnings.empty()) << r.err;
    return;
  }
  ASSERT_EQ(warnings.size(), 1u) << r.err;
  const std::string prefix =
      "bookspin: warning: " + name + ": encoder \"h264_nvenc\" failed to open: ";
  EXPECT_EQ(warnings[0].rfind(prefix, 0), 0u) << warnings[0];
  EXPECT_EQ(warnings[0].find("preset"), std::string::npos) << warnings[0];
  EXPECT_TRUE(warnings[0].ends_with("; using libx264")) << warnings[0];
  // "unusable (REASON)": the reason the encoder gives when asked with no preset at all.
  ASSERT_EQ(status.rfind("unusable (", 0), 0u) << status;
  const std::string reason = status.substr(10, status.size() - 11);
  EXPECT_NE(warnings[0].find(": " + reason + "; using libx264"), std::string::npos)
      << warnings[0] << "\nbookspin info: " << reason;
  EXPECT_NE(manifest.find("\"mp4_encoder\": \"libx264\""), std::string::npos) << manifest;
  // x264 signs its stream (an SEI message "x264 - core N …"): libx264 made the file.
  EXPECT_NE(read_file(out / (name + ".mp4")).find("x264 - core"), std::string::npos);

  const SplitResult again = run_bookspin_split(args);
  ASSERT_EQ(again.status, 0) << again.err;
  EXPECT_NE(again.out.find("up to date: " + name), std::string::npos) << again.out;
  EXPECT_EQ(lines_starting(again.err, "bookspin: warning: "),
            std::vector<std::string>{warnings[0] + " (when it was rendered)"})
      << again.err;
}

TEST(RenderCommand, UnwritableOutputDirectoryIsOneLineAndNothingIsWritten) {
  const fs::path out = fresh_dir("render_unwritable");
  const fs::path blocker = out / "a-file";
  { std::ofstream(blocker) << "x"; }
  const CliResult r = run_bookspin("render " + scene_path("fig09-matrix-unstable-x") + kSmall +
                                   " --frames 2 -o " + (blocker / "sub").string());
  EXPECT_NE(r.status, 0);
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  EXPECT_NE(r.output.find("cannot create output directory"), std::string::npos) << r.output;
  EXPECT_EQ(count_files(out), 1);
}

TEST(RenderCommand, NoUsableEglDisplayIsOneLineAndNothingIsWritten) {
  const fs::path out = fresh_dir("render_no_egl");
  // glvnd finds no EGL vendor at all: every platform fails to give a display.
  const CliResult r = run_bookspin_env("__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent.json",
                                       "render " + scene_path("fig09-matrix-unstable-x") + kSmall +
                                           " --frames 2 -o " + out.string());
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  EXPECT_NE(r.output.find("EGL"), std::string::npos) << r.output;
  EXPECT_EQ(count_files(out), 0);
}

TEST(RenderCommand, OddSizeIsRejectedBeforeAnyOutput) {
  const fs::path out = fresh_dir("render_odd");
  const CliResult r = run_bookspin("render " + scene_path("fig09-matrix-unstable-x") +
                                   " --set render.width=129 -o " + out.string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.output.find("4:2:0 video needs even sizes"), std::string::npos) << r.output;
  EXPECT_EQ(count_files(out), 0);
}

TEST(RenderOptions, PngCompressionOverridesTheSceneAndIsRangeChecked) {
  const auto dir = fresh_dir("render-png-compression");
  const std::string common = "render " + scene_path("fig09-matrix-unstable-x") +
                             " --frames 2 --set render.width=64 --set render.height=36 -o ";
  ASSERT_EQ(run_bookspin(common + (dir / "stored").string() + " --png-compression 0").status, 0);
  ASSERT_EQ(run_bookspin(common + (dir / "deflated").string() + " --png-compression 9").status, 0);
  const auto frame =
      std::filesystem::path("fig09-matrix-unstable-x") / "frames" / "frame_00001.png";
  // Level 0 stores the pixels uncompressed: bigger than level 9's file.
  EXPECT_GT(std::filesystem::file_size(dir / "stored" / frame),
            std::filesystem::file_size(dir / "deflated" / frame));
  EXPECT_EQ(run_bookspin(common + dir.string() + " --png-compression 10").status, 2);
}

}  // namespace
}  // namespace bookspin::cli
