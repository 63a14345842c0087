#pragma once
// The sinks of one clip, fed frame by frame: each video (MP4, WebM, GIF) on its own encoder
// thread, PNG frames on a small worker pool, the diagnostics CSVs (one, or a comparison's one
// per tile) on the caller's thread. Every
// output is written under a temporary name; finish() completes them and adds them to the
// run's OutputSet, whose commit() puts them in place together (docs/outputs.md).
#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include "clip/bounded_queue.hpp"
#include "common/rgba_image.hpp"
#include "common/stop.hpp"
#include "output/atomic_output.hpp"
#include "output/diagnostics_csv.hpp"
#include "physics/simulator.hpp"
#include "video/video.hpp"

namespace bookspin::clip {

/// Where a clip's outputs go (the clip product names them: products/clip.hpp). Only the
/// videos of SinkOptions::formats are written; the frames only with SinkOptions::write_png.
struct ClipPaths {
  std::filesystem::path mp4;         ///< the H.264 video
  std::filesystem::path webm;        ///< the VP9 video
  std::filesystem::path gif;         ///< the GIF
  std::filesystem::path frames_dir;  ///< the PNG frames, frame_file_name(i) each
  std::filesystem::path csv;         ///< the diagnostics CSV (a comparison's first tile's)
};

/// The file name of frame `index` (from 0) in ClipPaths::frames_dir: "frame_00042.png".
std::string frame_file_name(int index);

struct SinkOptions {
  bool write_png = true;
  int png_compression = 1;  ///< deflate level 0–9 (output::write_png)
  int png_workers = 1;      ///< threads compressing PNGs
  video::EncoderSettings encoder;
  /// Videos to write, each of "mp4", "webm", "gif" at most once (scene::kVideoFormats);
  /// every one gets the same frames.
  std::vector<std::string> formats{"mp4"};
  int webm_crf = 32;    ///< video::WebmSettings::crf
  int gif_width = 640;  ///< video::GifSettings::width
  int gif_fps = 15;     ///< video::GifSettings::gif_fps
  /// Polled by finish() while the encoders finish their long passes (the MP4's and WebM's
  /// flushes, the GIF's palette pass): a signal throws Interrupted (common/stop.hpp).
  StopPoll stop;
};

class ClipSinks {
 public:
  /// Opens all outputs (temporaries). `tile_csvs`: a comparison's diagnostics CSVs of its
  /// tiles after the first (whose CSV is paths.csv), in tile order. Throws OutputError,
  /// video::EncoderError, std::invalid_argument.
  ClipSinks(const ClipPaths& paths, const SinkOptions& options,
            const std::vector<std::filesystem::path>& tile_csvs = {});
  /// Without finish(): stops the workers and removes every temporary. Never throws.
  ~ClipSinks();
  ClipSinks(const ClipSinks&) = delete;
  ClipSinks& operator=(const ClipSinks&) = delete;

  /// Queues frame `index` (blocks while the queues are full, so memory stays bounded) and
  /// writes its CSV rows: rows[0] to ClipPaths::csv, rows[1 + i] to tile_csvs[i]
  /// (std::invalid_argument unless there is one row per CSV). Rethrows the first error of a
  /// worker.
  void add(int index, RgbaImage image, std::span<const physics::Diagnostics> rows);
  /// Same for a clip with one CSV.
  void add(int index, RgbaImage image, const physics::Diagnostics& diagnostics) {
    add(index, std::move(image), std::span(&diagnostics, 1));
  }
  /// Drains the queues and completes every output under its temporary name, adding each to
  /// `set` (videos in the order of SinkOptions::formats, then the frames, then the CSVs);
  /// nothing is in place until set.commit(), which must come before these sinks are
  /// destroyed. Rethrows the first error of a worker. Throws Interrupted when
  /// SinkOptions::stop answers a signal while an encoder finishes (nothing put in place).
  void finish(output::OutputSet& set);
  /// A frame buffer the sinks are done with, to render the next frame into instead of
  /// allocating (and page-faulting) a new one; std::nullopt if none is free now.
  std::optional<RgbaImage> spare_frame();
  /// Non-empty when the MP4 encoder fell back to libx264: one line on why.
  const std::string& encoder_message() const;
  /// The H.264 encoder making the MP4 ("libx264", "h264_nvenc"); empty without an MP4.
  const std::string& mp4_encoder() const;

 private:
  using Frame = std::shared_ptr<const RgbaImage>;
  /// One video file and the queue of frames its thread encodes.
  struct Video {
    std::function<void(const RgbaImage&)> add_frame;
    std::function<void(output::OutputSet&)> finish;
    BoundedQueue<Frame> queue{4};
  };
  void encode_loop(Video& video);
  void png_loop();
  void record_error();
  void rethrow_if_failed();
  void stop_workers();
  void recycle(const RgbaImage* image);

  ClipPaths paths_;
  SinkOptions options_;
  std::optional<video::Mp4Encoder> mp4_;
  std::optional<video::WebmEncoder> webm_;
  std::optional<video::GifEncoder> gif_;
  std::optional<output::AtomicDirectory> frames_;
  output::DiagnosticsCsvFile csv_;
  std::vector<std::unique_ptr<output::DiagnosticsCsvFile>> tile_csvs_;
  // Before the queues: frames left in them at destruction come back here.
  std::mutex spare_mutex_;
  std::vector<RgbaImage> spares_;
  std::vector<std::unique_ptr<Video>> videos_;
  BoundedQueue<std::pair<int, Frame>> png_queue_;
  std::mutex error_mutex_;
  std::exception_ptr error_;
  std::vector<std::thread> workers_;
};

}  // namespace bookspin::clip
