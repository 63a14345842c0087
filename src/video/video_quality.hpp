#pragma once
// How close a lossy clip is to the frames it was made from: a video file decoded back to RGB
// frames, and SSIM and PSNR of a decoded frame against its original (bookspin-bench's
// `presets` section chooses the default x264 preset and CRF with them, docs/performance-video.md).
#include <cstdint>
#include <filesystem>
#include <functional>

#include "common/rgba_image.hpp"

namespace bookspin::video {

/// Decodes every video frame of the first video stream of `path` (any container and codec
/// FFmpeg reads) and hands each, in display order, to `on_frame` as RGBA (alpha 255), top
/// row first, at the stream's own size. YUV is taken as BT.709 limited range, the tags
/// Mp4Encoder writes. Returns the number of frames decoded. Throws EncoderError when the
/// file cannot be opened or decoded.
std::int64_t decode_video(const std::filesystem::path& path,
                          const std::function<void(const RgbaImage& frame)>& on_frame);

/// SSIM and the squared error of one frame against its original.
struct FrameQuality {
  double ssim = 1.0;         ///< mean SSIM of the luma, 1 = identical
  double squared_error = 0;  ///< sum over every pixel and R, G, B of (a − b)², in levels²
  std::int64_t samples = 0;  ///< pixels × 3: squared_error / samples is the MSE
};

/// SSIM (Wang, Bovik, Sheikh, Simoncelli 2004, eq. 13, with K1 = 0.01, K2 = 0.03, L = 255) of
/// the luma Y = 0.2126 R + 0.7152 G + 0.0722 B (BT.709) of `decoded` against `original`,
/// over 8×8 windows stepped by 4 pixels, unweighted, averaged over the windows (the
/// windowing of x264's and libavfilter's ssim); and the squared error over R, G, B. Both
/// images the same size, at least 8×8, else std::invalid_argument.
FrameQuality frame_quality(const RgbaImage& original, const RgbaImage& decoded);

/// PSNR in dB, 10 log10(255² / MSE), of `squared_error` over `samples` samples; an MSE of 0
/// (identical) gives kPsnrIdentical, so the number stays finite.
double psnr_db(double squared_error, std::int64_t samples);
inline constexpr double kPsnrIdentical = 100.0;

}  // namespace bookspin::video
