#pragma once
// MP4 (H.264, yuv420p) clips encoded in-process with FFmpeg's libraries.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>

#include "common/rgba_image.hpp"
#include "common/stop.hpp"

namespace bookspin::output {
class OutputSet;
}  // namespace bookspin::output

namespace bookspin::video {

/// libav refused something (encoder missing or failing, bad frame). File
/// system failures are reported as OutputError instead.
class EncoderError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// How to encode. Sizes in pixels, both even (4:2:0 chroma is subsampled 2×2).
struct EncoderSettings {
  int width = 0;
  int height = 0;
  int fps = 30;                   ///< frames per second, 1…1000; also the time base 1/fps
  std::string codec = "libx264";  ///< any H.264 encoder name; falls back to libx264
  int crf = 18;                   ///< constant-quality factor 0 (lossless) … 51 (worst);
                                  ///< sent as "crf", or "cq" to encoders without crf
  /// Encoder speed preset: one of x264's, "ultrafast" … "placebo", which an NVENC encoder gets
  /// as its own preset of the same intent ("faster" → "p2"; docs/outputs.md), or a name the
  /// encoder itself knows ("p4"), handed on as it is.
  std::string preset = "medium";
  /// Encoder threads; 0 = the encoder's choice for all cores (x264: 1.5 × cores frame threads +
  /// lookahead).
  int threads = 0;
};

/// Encodes RGBA frames into an MP4 with one H.264 yuv420p stream, constant
/// frame rate fps/1, moov atom first (+faststart). The file is written under a
/// temporary name next to `path` and appears under `path` only when finish()
/// succeeds; destroying the encoder earlier (exception, interrupt) removes it.
///
/// Not thread-safe per object, but holds no thread affinity: add_frame and
/// finish may be called from any one thread at a time (e.g. a writer thread
/// draining a clip::BoundedQueue, as the clip sinks do).
class Mp4Encoder {
 public:
  /// Opens the encoder and the temporary output file, writes the header.
  /// If settings.codec is absent from this FFmpeg or fails to open (h264_nvenc
  /// without a GPU), libx264 is used instead and fallback_message() says why.
  /// Throws std::invalid_argument for odd or non-positive sizes ("… 4:2:0 video
  /// needs even sizes"), fps outside 1…1000, crf outside 0…51, a codec that is
  /// not an H.264 encoder, or an unknown x264 preset when libx264 was asked
  /// for; EncoderError if libx264 is needed but missing or fails to open;
  /// OutputError (naming `path`) if the file cannot be created or written.
  Mp4Encoder(std::filesystem::path path, const EncoderSettings& settings);
  /// Without a successful finish(): discards the temporary file. Never throws.
  ~Mp4Encoder();
  Mp4Encoder(const Mp4Encoder&) = delete;
  Mp4Encoder& operator=(const Mp4Encoder&) = delete;
  Mp4Encoder(Mp4Encoder&&) noexcept;
  Mp4Encoder& operator=(Mp4Encoder&&) noexcept;

  /// Converts `frame` (RGBA, top row first, exactly width×height) to yuv420p,
  /// encodes it as the next frame (pts = frame_count() in units of 1/fps) and
  /// muxes whatever packets are ready. Throws std::invalid_argument on a size
  /// mismatch, std::logic_error after finish(), EncoderError or OutputError on
  /// failure.
  void add_frame(const RgbaImage& frame);

  /// Drains the encoder, writes the trailer (moving moov to the front), closes
  /// the file and renames it onto the final path; with `set`, the complete file is
  /// added to it instead and put in place by set->commit() with the run's other
  /// outputs (the encoder must live until then). Throws EncoderError if no
  /// frame was added, OutputError on write/rename failure (no file is left
  /// then), std::logic_error if called twice. `stop` is polled for each packet of the
  /// drain ("mp4 flush"): when it answers a signal, finish() throws Interrupted and the
  /// temporary is left for the destructor to remove (nothing put in place).
  void finish(output::OutputSet* set = nullptr, const StopPoll& stop = {});

  /// Frames accepted by add_frame so far.
  std::int64_t frame_count() const;
  /// The encoder actually in use, e.g. "libx264".
  const std::string& codec_name() const;
  /// Empty if settings.codec was used; otherwise one line on why libx264 was used.
  const std::string& fallback_message() const;
  const std::filesystem::path& path() const;
  /// CPU seconds spent so far converting RGBA frames to yuv420p (swscale, on the threads
  /// that called add_frame), for bookspin-bench's split of a frame's cost.
  double conversion_seconds() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace bookspin::video
