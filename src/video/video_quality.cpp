#include "video/video_quality.hpp"

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "video/libav_support.hpp"
#include "video/mp4_encoder.hpp"

namespace bookspin::video {
namespace {

struct InputFormatDeleter {
  void operator()(AVFormatContext* context) const { avformat_close_input(&context); }
};
using InputFormatPtr = std::unique_ptr<AVFormatContext, InputFormatDeleter>;

/// Converts decoded frames of any pixel format to RGBA; YUV as BT.709 limited range.
class ToRgba {
 public:
  const RgbaImage& convert(const AVFrame& frame) {
    const auto format = static_cast<AVPixelFormat>(frame.format);
    scaler_.reset(sws_getContext(
        frame.width, frame.height, format, frame.width, frame.height, AV_PIX_FMT_RGBA,
        SWS_BICUBIC | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INT, nullptr, nullptr, nullptr));
    if (!scaler_) throw EncoderError("swscale cannot convert the decoded frames to RGBA");
    const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
    // Only YUV sources take the matrix; for RGB and palette ones swscale ignores it.
    sws_setColorspaceDetails(scaler_.get(), bt709, 0, bt709, 1, 0, 1 << 16, 1 << 16);
    if (image_.width != frame.width || image_.height != frame.height)
      image_ = RgbaImage(frame.width, frame.height);
    std::uint8_t* target[4] = {image_.pixels.data(), nullptr, nullptr, nullptr};
    const int stride[4] = {image_.width * 4, 0, 0, 0};
    sws_scale(scaler_.get(), frame.data, frame.linesize, 0, frame.height, target, stride);
    return image_;
  }

 private:
  libav::SwsPtr scaler_;
  RgbaImage image_;
};

}  // namespace

std::int64_t decode_video(const std::filesystem::path& path,
                          const std::function<void(const RgbaImage& frame)>& on_frame) {
  libav::configure_logging();
  const std::string name = path.string();
  const auto fail = [&name](const std::string& what, int rc) {
    throw EncoderError("cannot decode \"" + name + "\": " + what + ": " + libav::error_text(rc));
  };
  AVFormatContext* raw = nullptr;
  int rc = avformat_open_input(&raw, name.c_str(), nullptr, nullptr);
  if (rc < 0) fail("open", rc);
  InputFormatPtr input(raw);
  rc = avformat_find_stream_info(input.get(), nullptr);
  if (rc < 0) fail("stream info", rc);
  const AVCodec* decoder = nullptr;
  const int stream = av_find_best_stream(input.get(), AVMEDIA_TYPE_VIDEO, -1, -1, &decoder, 0);
  if (stream < 0 || decoder == nullptr) fail("no video stream", stream);
  libav::CodecContextPtr codec(avcodec_alloc_context3(decoder));
  libav::PacketPtr packet(av_packet_alloc());
  libav::FramePtr frame(av_frame_alloc());
  if (!codec || !packet || !frame) throw EncoderError("out of memory decoding \"" + name + "\"");
  rc = avcodec_parameters_to_context(codec.get(), input->streams[stream]->codecpar);
  if (rc < 0) fail("codec parameters", rc);
  rc = avcodec_open2(codec.get(), decoder, nullptr);
  if (rc < 0) fail("open the decoder", rc);
  ToRgba to_rgba;
  std::int64_t frames = 0;
  const auto drain = [&] {
    for (;;) {
      const int got = avcodec_receive_frame(codec.get(), frame.get());
      if (got == AVERROR(EAGAIN) || got == AVERROR_EOF) return;
      if (got < 0) fail("decode", got);
      on_frame(to_rgba.convert(*frame));
      ++frames;
      av_frame_unref(frame.get());
    }
  };
  while ((rc = av_read_frame(input.get(), packet.get())) >= 0) {
    if (packet->stream_index == stream) {
      const int sent = avcodec_send_packet(codec.get(), packet.get());
      av_packet_unref(packet.get());
      if (sent < 0) fail("decode", sent);
      drain();
    } else {
      av_packet_unref(packet.get());
    }
  }
  if (rc != AVERROR_EOF) fail("read", rc);
  rc = avcodec_send_packet(codec.get(), nullptr);  // flush
  if (rc < 0) fail("decode", rc);
  drain();
  return frames;
}

namespace {

/// Sums of one 4×4 block of two luma images: Σx, Σy, Σx², Σy², Σxy.
using BlockSums = std::array<double, 5>;

double luma(const std::uint8_t* rgba) {
  return 0.2126 * rgba[0] + 0.7152 * rgba[1] + 0.0722 * rgba[2];
}

}  // namespace

FrameQuality frame_quality(const RgbaImage& original, const RgbaImage& decoded) {
  if (original.width != decoded.width || original.height != decoded.height || original.width < 8 ||
      original.height < 8) {
    throw std::invalid_argument("frame_quality: sizes " + std::to_string(original.width) + "x" +
                                std::to_string(original.height) + " and " +
                                std::to_string(decoded.width) + "x" +
                                std::to_string(decoded.height) + " differ or are smaller than 8x8");
  }
  const int w = original.width, h = original.height, bw = w / 4, bh = h / 4;
  FrameQuality q;
  std::int64_t squared = 0;
  std::vector<BlockSums> blocks(static_cast<std::size_t>(bw) * bh, BlockSums{});
  for (int y = 0; y < h; ++y) {
    const std::uint8_t* a = original.row(y);
    const std::uint8_t* b = decoded.row(y);
    for (int x = 0; x < w; ++x) {
      for (int c = 0; c < 3; ++c) {
        const int d = a[4 * x + c] - b[4 * x + c];
        squared += d * d;
      }
      if (x / 4 >= bw || y / 4 >= bh) continue;
      const double ya = luma(a + 4 * x), yb = luma(b + 4 * x);
      BlockSums& s = blocks[static_cast<std::size_t>(y / 4) * bw + x / 4];
      s[0] += ya;
      s[1] += yb;
      s[2] += ya * ya;
      s[3] += yb * yb;
      s[4] += ya * yb;
    }
  }
  q.squared_error = static_cast<double>(squared);
  q.samples = static_cast<std::int64_t>(w) * h * 3;
  constexpr double kC1 = (0.01 * 255) * (0.01 * 255), kC2 = (0.03 * 255) * (0.03 * 255);
  constexpr double kN = 64.0;  // pixels of an 8×8 window
  double total = 0;
  for (int by = 0; by + 1 < bh; ++by) {
    for (int bx = 0; bx + 1 < bw; ++bx) {
      BlockSums s{};
      for (int dy = 0; dy < 2; ++dy)
        for (int dx = 0; dx < 2; ++dx)
          for (int k = 0; k < 5; ++k)
            s[k] += blocks[static_cast<std::size_t>(by + dy) * bw + bx + dx][k];
      const double mx = s[0] / kN, my = s[1] / kN;
      const double vx = s[2] / kN - mx * mx, vy = s[3] / kN - my * my, cxy = s[4] / kN - mx * my;
      total +=
          (2 * mx * my + kC1) * (2 * cxy + kC2) / ((mx * mx + my * my + kC1) * (vx + vy + kC2));
    }
  }
  q.ssim = total / (static_cast<double>(bw - 1) * (bh - 1));
  return q;
}

double psnr_db(double squared_error, std::int64_t samples) {
  if (samples <= 0) throw std::invalid_argument("psnr_db: no samples");
  const double mse = squared_error / static_cast<double>(samples);
  if (mse <= 0) return kPsnrIdentical;
  return std::min(kPsnrIdentical, 10.0 * std::log10(255.0 * 255.0 / mse));
}

}  // namespace bookspin::video
