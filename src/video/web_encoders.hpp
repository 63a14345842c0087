#pragma once
// WebM (VP9) and GIF clips for web pages and slides, encoded in-process with FFmpeg's
// libraries from the same RGBA frames as the MP4 (docs/outputs.md, "Video formats").
#include <cstdint>
#include <filesystem>
#include <memory>

#include "common/rgba_image.hpp"
#include "common/stop.hpp"
#include "video/mp4_encoder.hpp"

namespace bookspin::video {

/// A WebM clip: one VP9 stream (libvpx-vp9), yuv420p BT.709 limited range, constant frame
/// rate fps/1, at the frames' own size.
struct WebmSettings {
  int width = 0;    ///< pixels, even
  int height = 0;   ///< pixels, even
  int fps = 30;     ///< frames per second, 1…1000
  int crf = 32;     ///< VP9 constant quality, 0 (best) … 63
  int threads = 0;  ///< encoder threads; 0 = one per core
};

/// The fastest a GIF plays, in frames per second: a GIF stores each frame's delay in whole
/// centiseconds, and browsers show a delay under 2 cs as 10 cs, so 2 cs is the shortest
/// (docs/outputs.md, "Video formats"). FFmpeg's GIF muxer counts in centiseconds too: a faster
/// rate would give frames of equal timestamps, which it refuses.
inline constexpr int kGifMaxFps = 50;

/// A GIF clip with one global 256-colour palette computed over the whole clip (FFmpeg's
/// palettegen, then paletteuse with ordered dithering), scaled to `width` pixels wide.
/// Every `step`-th frame is kept (step = max(1, round(fps / gif_fps))), so the GIF plays at
/// fps/step frames per second (at most kGifMaxFps) for the clip's own duration; it loops
/// forever. Frame k of the GIF starts at k·step/fps s, rounded to the centisecond by the
/// muxer, so delays alternate between the two nearest whole centiseconds and the total
/// stays the clip's.
struct GifSettings {
  int source_width = 0;  ///< pixels of the frames handed to add_frame
  int source_height = 0;
  int fps = 30;      ///< frame rate of the frames handed to add_frame, 1…1000
  int width = 640;   ///< GIF width in pixels, 16 … source_width
  int gif_fps = 15;  ///< target GIF frame rate, 1 … fps
};

/// The GIF's height for `settings`: the source aspect kept, rounded to an even number.
int gif_height(const GifSettings& settings);
/// Frames of the source kept per GIF frame: max(1, round(fps / gif_fps)).
int gif_step(const GifSettings& settings);
/// Frames in a GIF made from `source_frames` frames: ceil(source_frames / gif_step).
std::int64_t gif_frame_count(const GifSettings& settings, std::int64_t source_frames);

/// Both encoders write under a temporary name next to `path`, which appears only when
/// finish() succeeds (with an OutputSet: when the set commits; the encoder must live until
/// then); destroying the encoder earlier removes it. Not thread-safe per object,
/// but free of thread affinity (one thread at a time). Errors as Mp4Encoder: bad settings →
/// std::invalid_argument, libav refusing → EncoderError, file system → OutputError naming
/// the path; add_frame on a size mismatch → std::invalid_argument; finish() with no frame
/// → EncoderError. finish(stop) polls `stop` between the units of its long passes (the
/// WebM's flush: "webm flush", each packet; the GIF: "gif finish" as it starts, "gif palette
/// pass" once the palette is made, then "gif palette frames" for each frame of the pass): a
/// signal throws Interrupted and the temporary goes with the encoder (nothing put in place).
class WebmEncoder {
 public:
  WebmEncoder(std::filesystem::path path, const WebmSettings& settings);
  ~WebmEncoder();
  WebmEncoder(const WebmEncoder&) = delete;
  WebmEncoder& operator=(const WebmEncoder&) = delete;
  /// `frame`: RGBA, top row first, exactly width×height.
  void add_frame(const RgbaImage& frame);
  void finish(output::OutputSet* set = nullptr, const StopPoll& stop = {});
  std::int64_t frame_count() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// See GifSettings. The palette needs every frame, so the GIF is made in two passes: each kept
/// frame is scaled, counted into the palette and stored deflated in a file of no name beside
/// `path` (disk, not memory: what the encoder holds does not grow with the clip); finish()
/// applies the palette to the stored frames one at a time. A frame store that cannot be
/// created or written → OutputError naming `path`.
class GifEncoder {
 public:
  GifEncoder(std::filesystem::path path, const GifSettings& settings);
  ~GifEncoder();
  GifEncoder(const GifEncoder&) = delete;
  GifEncoder& operator=(const GifEncoder&) = delete;
  /// `frame`: RGBA, top row first, exactly source_width×source_height; only every step-th
  /// call (the first included) reaches the GIF.
  void add_frame(const RgbaImage& frame);
  void finish(output::OutputSet* set = nullptr, const StopPoll& stop = {});
  /// Frames written to the GIF so far (after finish(): all of them).
  std::int64_t frame_count() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace bookspin::video
