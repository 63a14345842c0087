#pragma once
// The sinks of one clip, fed frame by frame: MP4 on an encoder thread, PNG frames on a small
// worker pool, the diagnostics CSV on the caller's thread. Every output is written under a
// temporary name and appears under its final name only in finish().
#include <exception>
#include <filesystem>
#include <fstream>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "common/rgba_image.hpp"
#include "output/atomic_output.hpp"
#include "output/bounded_queue.hpp"
#include "output/diagnostics_csv.hpp"
#include "output/mp4_encoder.hpp"
#include "physics/simulator.hpp"

namespace bookspin::output {

struct ClipPaths {
  std::filesystem::path mp4;         ///< out/<scene>.mp4
  std::filesystem::path frames_dir;  ///< out/<scene>/frames
  std::filesystem::path csv;         ///< out/<scene>/diagnostics.csv
};

struct SinkOptions {
  bool write_png = true;
  int png_compression = 1;  ///< zlib level 0–9
  int png_workers = 1;      ///< threads compressing PNGs
  output::EncoderSettings encoder;
};

class ClipSinks {
 public:
  /// Opens all outputs (temporaries). Throws OutputError, EncoderError, std::invalid_argument.
  ClipSinks(const ClipPaths& paths, const SinkOptions& options);
  /// Without finish(): stops the workers and removes every temporary. Never throws.
  ~ClipSinks();
  ClipSinks(const ClipSinks&) = delete;
  ClipSinks& operator=(const ClipSinks&) = delete;

  /// Queues frame `index` (blocks while the queues are full, so memory stays bounded) and
  /// writes its CSV row. Rethrows the first error of a worker.
  void add(int index, RgbaImage image, const physics::Diagnostics& diagnostics);
  /// Drains the queues, then renames every output into place.
  void finish();
  /// A frame buffer the sinks are done with, to render the next frame into instead of
  /// allocating (and page-faulting) a new one; std::nullopt if none is free now.
  std::optional<RgbaImage> spare_frame();
  /// Non-empty when the encoder fell back to libx264.
  const std::string& encoder_message() const { return encoder_.fallback_message(); }

 private:
  using Frame = std::shared_ptr<const RgbaImage>;
  void encode_loop();
  void png_loop();
  void record_error();
  void rethrow_if_failed();
  void stop_workers();
  void recycle(const RgbaImage* image);

  ClipPaths paths_;
  SinkOptions options_;
  output::Mp4Encoder encoder_;
  std::optional<output::AtomicDirectory> frames_;
  DiagnosticsCsvFile csv_;
  // Before the queues: frames left in them at destruction come back here.
  std::mutex spare_mutex_;
  std::vector<RgbaImage> spares_;
  output::BoundedQueue<Frame> encode_queue_;
  output::BoundedQueue<std::pair<int, Frame>> png_queue_;
  std::mutex error_mutex_;
  std::exception_ptr error_;
  std::vector<std::thread> workers_;
};

}  // namespace bookspin::output
