#include "mp4_probe.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/pixdesc.h>
#include <libswscale/swscale.h>
}

#include <cstdint>
#include <fstream>
#include <memory>
#include <stdexcept>

#include "video/libav_support.hpp"

namespace bookspin::video::testing {
namespace {

struct InputCloser {
  void operator()(AVFormatContext* c) const { avformat_close_input(&c); }
};
using libav::CodecContextDeleter;
using libav::FrameDeleter;
using libav::PacketDeleter;
using libav::SwsDeleter;

void check(int rc, const char* what) {
  if (rc < 0) {
    char text[AV_ERROR_MAX_STRING_SIZE] = {};
    av_strerror(rc, text, sizeof text);
    throw std::runtime_error(std::string(what) + ": " + text);
  }
}

// Converts like a player would: honour the stream's matrix and range tags.
RgbaImage to_rgba(const AVFrame* frame) {
  std::unique_ptr<SwsContext, SwsDeleter> sws(sws_getContext(
      frame->width, frame->height, static_cast<AVPixelFormat>(frame->format), frame->width,
      frame->height, AV_PIX_FMT_RGBA, SWS_BICUBIC | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INT, nullptr,
      nullptr, nullptr));
  if (!sws) throw std::runtime_error("sws_getContext failed");
  const int matrix = frame->colorspace == AVCOL_SPC_BT709 ? SWS_CS_ITU709 : SWS_CS_DEFAULT;
  const int* table = sws_getCoefficients(matrix);
  const int full_range = frame->color_range == AVCOL_RANGE_JPEG ? 1 : 0;
  sws_setColorspaceDetails(sws.get(), table, full_range, table, 1, 0, 1 << 16, 1 << 16);
  RgbaImage image(frame->width, frame->height);
  std::uint8_t* dst[4] = {image.pixels.data(), nullptr, nullptr, nullptr};  // sws reads 4
  const int dst_stride[4] = {image.width * 4, 0, 0, 0};
  sws_scale(sws.get(), frame->data, frame->linesize, 0, frame->height, dst, dst_stride);
  return image;
}

void receive_all(AVCodecContext* codec, AVFrame* frame, Mp4Probe& probe) {
  for (;;) {
    const int rc = avcodec_receive_frame(codec, frame);
    if (rc == AVERROR(EAGAIN) || rc == AVERROR_EOF) return;
    check(rc, "avcodec_receive_frame");
    probe.frames.push_back(to_rgba(frame));
    av_frame_unref(frame);
  }
}

}  // namespace

Mp4Probe probe_mp4(const std::filesystem::path& path) {
  AVFormatContext* raw = nullptr;
  check(avformat_open_input(&raw, path.c_str(), nullptr, nullptr), "avformat_open_input");
  std::unique_ptr<AVFormatContext, InputCloser> input(raw);
  check(avformat_find_stream_info(input.get(), nullptr), "avformat_find_stream_info");

  Mp4Probe probe;
  probe.format_name = input->iformat->name;
  const int index = av_find_best_stream(input.get(), AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
  check(index, "av_find_best_stream");
  for (unsigned i = 0; i < input->nb_streams; ++i) {
    probe.video_streams += input->streams[i]->codecpar->codec_type == AVMEDIA_TYPE_VIDEO;
  }
  const AVStream* stream = input->streams[index];
  const AVCodecParameters* par = stream->codecpar;
  probe.codec = avcodec_get_name(par->codec_id);
  const char* pix = av_get_pix_fmt_name(static_cast<AVPixelFormat>(par->format));
  probe.pix_fmt = pix ? pix : "?";
  probe.color_space = av_color_space_name(par->color_space);
  probe.width = par->width;
  probe.height = par->height;
  probe.r_frame_rate_num = stream->r_frame_rate.num;
  probe.r_frame_rate_den = stream->r_frame_rate.den;
  probe.avg_frame_rate_num = stream->avg_frame_rate.num;
  probe.avg_frame_rate_den = stream->avg_frame_rate.den;
  probe.nb_frames = stream->nb_frames;

  const AVCodec* decoder = avcodec_find_decoder(par->codec_id);
  if (decoder == nullptr) throw std::runtime_error("no decoder for " + probe.codec);
  std::unique_ptr<AVCodecContext, CodecContextDeleter> codec(avcodec_alloc_context3(decoder));
  check(avcodec_parameters_to_context(codec.get(), par), "avcodec_parameters_to_context");
  check(avcodec_open2(codec.get(), decoder, nullptr), "avcodec_open2");

  std::unique_ptr<AVPacket, PacketDeleter> packet(av_packet_alloc());
  std::unique_ptr<AVFrame, FrameDeleter> frame(av_frame_alloc());
  while (av_read_frame(input.get(), packet.get()) >= 0) {
    if (packet->stream_index == index) {
      check(avcodec_send_packet(codec.get(), packet.get()), "avcodec_send_packet");
      receive_all(codec.get(), frame.get(), probe);
    }
    av_packet_unref(packet.get());
  }
  check(avcodec_send_packet(codec.get(), nullptr), "flush");
  receive_all(codec.get(), frame.get(), probe);
  return probe;
}

std::vector<std::string> top_level_boxes(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw std::runtime_error("cannot open " + path.string());
  const auto file_size = static_cast<std::uint64_t>(std::filesystem::file_size(path));
  std::vector<std::string> types;
  std::uint64_t offset = 0;
  while (offset + 8 <= file_size) {
    unsigned char header[16] = {};
    file.seekg(static_cast<std::streamoff>(offset));
    file.read(reinterpret_cast<char*>(header), 8);
    std::uint64_t size = 0;
    for (int i = 0; i < 4; ++i) size = size << 8 | header[i];
    types.emplace_back(reinterpret_cast<char*>(header + 4), 4);
    if (size == 1) {  // 64-bit "largesize" follows the type
      file.read(reinterpret_cast<char*>(header + 8), 8);
      size = 0;
      for (int i = 8; i < 16; ++i) size = size << 8 | header[i];
    } else if (size == 0) {  // box runs to the end of the file
      size = file_size - offset;
    }
    if (size < 8) throw std::runtime_error("corrupt box size in " + path.string());
    offset += size;
  }
  return types;
}

}  // namespace bookspin::video::testing
