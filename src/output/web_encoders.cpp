#include "output/web_encoders.hpp"

extern "C" {
#include <libavfilter/avfilter.h>
#include <libavfilter/buffersink.h>
#include <libavfilter/buffersrc.h>
#include <libavutil/imgutils.h>
#include <libavutil/opt.h>
}

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

#include "output/atomic_output.hpp"
#include "output/libav_support.hpp"

namespace bookspin::output {
namespace {

std::string size_text(int width, int height) {
  return std::to_string(width) + "x" + std::to_string(height);
}

void check_frame(const RgbaImage& image, int width, int height, const char* what) {
  if (image.width != width || image.height != height ||
      image.pixels.size() != static_cast<std::size_t>(image.width) * image.height * 4) {
    throw std::invalid_argument("frame " + size_text(image.width, image.height) +
                                " does not match " + what + " size " + size_text(width, height));
  }
}

struct FilterGraphDeleter {
  void operator()(AVFilterGraph* graph) const { avfilter_graph_free(&graph); }
};
using FilterGraphPtr = std::unique_ptr<AVFilterGraph, FilterGraphDeleter>;

/// One video stream muxed into a file written atomically: the container and codec opened,
/// packets moved from the encoder to the muxer. `label` ("WebM", "GIF") names it in errors.
/// Member order: the libav objects (and the file, via `format`) go before `output`.
struct StreamFile {
  const char* label;
  AtomicFile output;
  libav::OutputFormatPtr format;
  libav::CodecContextPtr codec;
  AVStream* stream = nullptr;  // owned by `format`
  libav::PacketPtr packet;
  std::int64_t frames = 0;
  bool closed = false;

  StreamFile(const char* label_, std::filesystem::path path)
      : label(label_), output(std::move(path)) {}

  [[noreturn]] void throw_io(const std::string& action, int rc) const {
    throw_output_error(action, output.final_path(), libav::error_text(rc));
  }

  /// Opens muxer `muxer` on the temporary and allocates encoder `encoder` (not opened yet).
  AVCodecContext* open(const char* muxer, const char* encoder) {
    libav::configure_logging();
    const std::string url = "file:" + output.temp_path().string();
    AVFormatContext* raw = nullptr;
    const int rc = avformat_alloc_output_context2(&raw, nullptr, muxer, url.c_str());
    if (rc < 0 || raw == nullptr)
      throw EncoderError(std::string(muxer) + " muxer: " + libav::error_text(rc));
    format.reset(raw);
    const AVCodec* found = avcodec_find_encoder_by_name(encoder);
    if (found == nullptr) {
      throw EncoderError(std::string(label) + ": encoder \"" + encoder +
                         "\" is not in this FFmpeg build");
    }
    codec.reset(avcodec_alloc_context3(found));
    packet.reset(av_packet_alloc());
    if (!codec || !packet) throw EncoderError("out of memory opening the " + std::string(label));
    if ((format->oformat->flags & AVFMT_GLOBALHEADER) != 0)
      codec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    return codec.get();
  }

  /// Opens the encoder with `options`, adds the stream, writes the header.
  void start(AVDictionary* options) {
    {
      libav::LogCapture capture;
      const int rc = avcodec_open2(codec.get(), codec->codec, &options);
      av_dict_free(&options);
      if (rc < 0) {
        std::string why = libav::error_text(rc);
        if (!capture.text().empty()) why = capture.text() + " (" + why + ")";
        throw EncoderError(std::string(label) + " encoder " + codec->codec->name +
                           " failed to open: " + why);
      }
    }
    stream = avformat_new_stream(format.get(), nullptr);
    if (stream == nullptr) throw EncoderError(std::string("cannot add a stream to the ") + label);
    stream->time_base = codec->time_base;
    stream->avg_frame_rate = codec->framerate;
    stream->r_frame_rate = codec->framerate;
    int rc = avcodec_parameters_from_context(stream->codecpar, codec.get());
    if (rc < 0) throw EncoderError("codec parameters: " + libav::error_text(rc));
    rc = avio_open(&format->pb, format->url, AVIO_FLAG_WRITE);
    if (rc < 0) throw_io(std::string("cannot create ") + label, rc);
    rc = avformat_write_header(format.get(), nullptr);
    if (rc < 0) throw_io(std::string("cannot write the header of ") + label, rc);
  }

  /// Encodes `frame` (null: flush) and muxes the packets that are ready.
  void encode(const AVFrame* frame) {
    int rc = avcodec_send_frame(codec.get(), frame);
    if (rc < 0) {
      throw EncoderError(std::string(codec->codec->name) +
                         " rejected a frame: " + libav::error_text(rc));
    }
    if (frame != nullptr) ++frames;
    for (;;) {
      rc = avcodec_receive_packet(codec.get(), packet.get());
      if (rc == AVERROR_EOF || (frame != nullptr && rc == AVERROR(EAGAIN))) return;
      if (rc < 0) {
        throw EncoderError(std::string(codec->codec->name) + " failed: " + libav::error_text(rc));
      }
      if (packet->duration == 0) packet->duration = 1;  // one frame of the time base
      av_packet_rescale_ts(packet.get(), codec->time_base, stream->time_base);
      packet->stream_index = stream->index;
      rc = av_interleaved_write_frame(format.get(), packet.get());
      if (rc < 0) throw_io(std::string("cannot write ") + label, rc);
    }
  }

  /// Flushes the encoder, writes the trailer, closes and renames the file into place.
  void finish() {
    if (closed) throw std::logic_error(std::string(label) + " finish called twice");
    closed = true;
    if (frames == 0)
      throw EncoderError(std::string(label) + " \"" + output.final_path().string() +
                         "\" has no frames");
    encode(nullptr);
    int rc = av_write_trailer(format.get());
    if (rc < 0) throw_io(std::string("cannot finish ") + label, rc);
    rc = avio_closep(&format->pb);
    if (rc < 0) throw_io(std::string("cannot finish ") + label, rc);
    output.commit();
  }
};

libav::FramePtr make_frame(AVPixelFormat pixel_format, int width, int height) {
  libav::FramePtr frame(av_frame_alloc());
  if (!frame) throw EncoderError("out of memory allocating a frame");
  frame->format = pixel_format;
  frame->width = width;
  frame->height = height;
  const int rc = av_frame_get_buffer(frame.get(), 0);
  if (rc < 0) throw EncoderError("frame buffer: " + libav::error_text(rc));
  return frame;
}

}  // namespace

// ---------------------------------------------------------------------------------- WebM

struct WebmEncoder::Impl {
  WebmSettings settings;
  StreamFile file;
  libav::SwsPtr scaler;
  libav::FramePtr frame;
  Impl(std::filesystem::path path, const WebmSettings& s)
      : settings(s), file("WebM", std::move(path)) {}
};

WebmEncoder::WebmEncoder(std::filesystem::path path, const WebmSettings& s) {
  const std::string size = size_text(s.width, s.height);
  if (s.width <= 0 || s.height <= 0 || s.width % 2 != 0 || s.height % 2 != 0)
    throw std::invalid_argument("WebM size " + size + " must be positive and even (4:2:0)");
  if (s.fps < 1 || s.fps > 1000)
    throw std::invalid_argument("WebM fps " + std::to_string(s.fps) + " is outside 1…1000");
  if (s.crf < 0 || s.crf > 63)
    throw std::invalid_argument("WebM crf " + std::to_string(s.crf) + " is outside 0…63");
  impl_ = std::make_unique<Impl>(std::move(path), s);
  StreamFile& f = impl_->file;
  AVCodecContext* c = f.open("webm", "libvpx-vp9");
  c->width = s.width;
  c->height = s.height;
  c->pix_fmt = AV_PIX_FMT_YUV420P;
  c->time_base = AVRational{1, s.fps};
  c->framerate = AVRational{s.fps, 1};
  c->bit_rate = 0;  // with crf: constant quality
  c->thread_count = std::max(0, s.threads);
  c->gop_size = 4 * s.fps;
  c->colorspace = AVCOL_SPC_BT709;
  c->color_primaries = AVCOL_PRI_BT709;
  c->color_trc = AVCOL_TRC_BT709;
  c->color_range = AVCOL_RANGE_MPEG;
  AVDictionary* options = nullptr;
  av_dict_set(&options, "crf", std::to_string(s.crf).c_str(), 0);
  // "good" quality at speed 5, rows in parallel: a few times real time on two cores.
  av_dict_set(&options, "deadline", "good", 0);
  av_dict_set(&options, "cpu-used", "5", 0);
  av_dict_set(&options, "row-mt", "1", 0);
  f.start(options);
  const int flags = SWS_BICUBIC | SWS_FULL_CHR_H_INP | SWS_ACCURATE_RND;
  impl_->scaler.reset(sws_getContext(s.width, s.height, AV_PIX_FMT_RGBA, s.width, s.height,
                                     AV_PIX_FMT_YUV420P, flags, nullptr, nullptr, nullptr));
  if (!impl_->scaler) throw EncoderError("swscale cannot convert RGBA to yuv420p");
  const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
  sws_setColorspaceDetails(impl_->scaler.get(), bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16);
  impl_->frame = make_frame(AV_PIX_FMT_YUV420P, s.width, s.height);
}

WebmEncoder::~WebmEncoder() = default;

void WebmEncoder::add_frame(const RgbaImage& image) {
  Impl& s = *impl_;
  if (s.file.closed) throw std::logic_error("WebmEncoder::add_frame after finish");
  check_frame(image, s.settings.width, s.settings.height, "WebM");
  const int rc = av_frame_make_writable(s.frame.get());
  if (rc < 0) throw EncoderError("frame buffer: " + libav::error_text(rc));
  const std::uint8_t* source[4] = {image.pixels.data(), nullptr, nullptr, nullptr};
  const int stride[4] = {image.width * 4, 0, 0, 0};
  sws_scale(s.scaler.get(), source, stride, 0, image.height, s.frame->data, s.frame->linesize);
  s.frame->pts = s.file.frames;
  s.file.encode(s.frame.get());
}

void WebmEncoder::finish() { impl_->file.finish(); }
std::int64_t WebmEncoder::frame_count() const { return impl_->file.frames; }

// ----------------------------------------------------------------------------------- GIF

int gif_height(const GifSettings& s) {
  const double h = static_cast<double>(s.width) * s.source_height / s.source_width;
  return std::max(2, 2 * static_cast<int>(std::lround(h / 2.0)));
}

int gif_step(const GifSettings& s) {
  return std::max(1, static_cast<int>(std::lround(static_cast<double>(s.fps) / s.gif_fps)));
}

std::int64_t gif_frame_count(const GifSettings& s, std::int64_t source_frames) {
  const int step = gif_step(s);
  return (source_frames + step - 1) / step;
}

struct GifEncoder::Impl {
  GifSettings settings;
  int step = 1;
  int height = 0;
  std::int64_t seen = 0;  ///< frames handed to add_frame
  StreamFile file;
  FilterGraphPtr graph;
  AVFilterContext* source = nullptr;  // owned by `graph`
  AVFilterContext* sink = nullptr;
  libav::FramePtr filtered;
  Impl(std::filesystem::path path, const GifSettings& s)
      : settings(s), file("GIF", std::move(path)) {}

  void build_graph();
  /// Encodes every frame the graph has ready; at the end (`eof`) until it has none left.
  void pull(bool eof);
};

void GifEncoder::Impl::build_graph() {
  graph.reset(avfilter_graph_alloc());
  if (!graph) throw EncoderError("out of memory allocating the GIF filter graph");
  graph->nb_threads = 1;
  const std::string args =
      "video_size=" + size_text(settings.source_width, settings.source_height) +
      ":pix_fmt=" + std::to_string(AV_PIX_FMT_RGBA) + ":time_base=" + std::to_string(step) + "/" +
      std::to_string(settings.fps) + ":pixel_aspect=1/1";
  int rc = avfilter_graph_create_filter(&source, avfilter_get_by_name("buffer"), "in", args.c_str(),
                                        nullptr, graph.get());
  if (rc < 0) throw EncoderError("GIF filter source: " + libav::error_text(rc));
  rc = avfilter_graph_create_filter(&sink, avfilter_get_by_name("buffersink"), "out", nullptr,
                                    nullptr, graph.get());
  if (rc < 0) throw EncoderError("GIF filter sink: " + libav::error_text(rc));
  // One palette for the whole clip (palettegen over every frame), applied with a small
  // ordered dither: ordered patterns stay put from frame to frame, so LZW and the frame
  // differences (diff_mode=rectangle) keep the file small.
  const std::string description = "scale=" + std::to_string(settings.width) + ":" +
                                  std::to_string(height) +
                                  ":flags=lanczos,split[a][b];[a]palettegen=stats_mode=full[p];"
                                  "[b][p]paletteuse=dither=bayer:bayer_scale=4:diff_mode=rectangle";
  AVFilterInOut* outputs = avfilter_inout_alloc();
  AVFilterInOut* inputs = avfilter_inout_alloc();
  if (outputs == nullptr || inputs == nullptr) {
    avfilter_inout_free(&outputs);
    avfilter_inout_free(&inputs);
    throw EncoderError("out of memory building the GIF filter graph");
  }
  outputs->name = av_strdup("in");
  outputs->filter_ctx = source;
  inputs->name = av_strdup("out");
  inputs->filter_ctx = sink;
  {
    libav::LogCapture capture;
    rc = avfilter_graph_parse_ptr(graph.get(), description.c_str(), &inputs, &outputs, nullptr);
    if (rc >= 0) rc = avfilter_graph_config(graph.get(), nullptr);
    avfilter_inout_free(&outputs);
    avfilter_inout_free(&inputs);
    if (rc < 0) {
      throw EncoderError("GIF palette filters (palettegen, paletteuse): " + capture.text() + " (" +
                         libav::error_text(rc) + ")");
    }
  }
}

void GifEncoder::Impl::pull(bool eof) {
  for (;;) {
    av_frame_unref(filtered.get());
    const int rc = av_buffersink_get_frame(sink, filtered.get());
    if (rc == AVERROR(EAGAIN) && !eof) return;
    if (rc == AVERROR_EOF) return;
    if (rc < 0) throw EncoderError("GIF palette filters: " + libav::error_text(rc));
    // The sink's time base is the source's (step/fps); the codec counts in the same unit.
    filtered->pict_type = AV_PICTURE_TYPE_NONE;
    file.encode(filtered.get());
  }
}

GifEncoder::GifEncoder(std::filesystem::path path, const GifSettings& s) {
  if (s.source_width <= 0 || s.source_height <= 0)
    throw std::invalid_argument("GIF source size " + size_text(s.source_width, s.source_height) +
                                " is not positive");
  if (s.fps < 1 || s.fps > 1000)
    throw std::invalid_argument("GIF source fps " + std::to_string(s.fps) + " is outside 1…1000");
  if (s.gif_fps < 1 || s.gif_fps > s.fps)
    throw std::invalid_argument("GIF fps " + std::to_string(s.gif_fps) + " is outside 1…" +
                                std::to_string(s.fps));
  if (s.width < 16 || s.width > s.source_width)
    throw std::invalid_argument("GIF width " + std::to_string(s.width) + " is outside 16…" +
                                std::to_string(s.source_width));
  impl_ = std::make_unique<Impl>(std::move(path), s);
  Impl& g = *impl_;
  g.step = gif_step(s);
  g.height = gif_height(s);
  AVCodecContext* c = g.file.open("gif", "gif");
  c->width = s.width;
  c->height = g.height;
  c->pix_fmt = AV_PIX_FMT_PAL8;
  c->time_base = AVRational{g.step, s.fps};
  c->framerate = AVRational{s.fps, g.step};
  g.build_graph();
  g.file.start(nullptr);
  g.filtered.reset(av_frame_alloc());
  if (!g.filtered) throw EncoderError("out of memory allocating a frame");
}

GifEncoder::~GifEncoder() = default;

void GifEncoder::add_frame(const RgbaImage& image) {
  Impl& g = *impl_;
  if (g.file.closed) throw std::logic_error("GifEncoder::add_frame after finish");
  check_frame(image, g.settings.source_width, g.settings.source_height, "GIF source");
  const std::int64_t index = g.seen++;
  if (index % g.step != 0) return;
  // The graph keeps a reference to each frame until the palette is known: a fresh buffer each.
  libav::FramePtr frame = make_frame(AV_PIX_FMT_RGBA, image.width, image.height);
  av_image_copy_plane(frame->data[0], frame->linesize[0], image.pixels.data(), image.width * 4,
                      image.width * 4, image.height);
  frame->pts = index / g.step;
  const int rc = av_buffersrc_add_frame_flags(g.source, frame.get(), 0);
  if (rc < 0) throw EncoderError("GIF palette filters rejected a frame: " + libav::error_text(rc));
  g.pull(false);
}

void GifEncoder::finish() {
  Impl& g = *impl_;
  if (!g.file.closed && g.seen > 0) {
    const int rc = av_buffersrc_add_frame_flags(g.source, nullptr, 0);  // end of stream
    if (rc < 0) throw EncoderError("GIF palette filters: " + libav::error_text(rc));
    g.pull(true);
  }
  g.file.finish();
}

std::int64_t GifEncoder::frame_count() const { return impl_->file.frames; }

}  // namespace bookspin::output
