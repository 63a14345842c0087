#include "video/web_encoders.hpp"

extern "C" {
#include <libavfilter/avfilter.h>
#include <libavfilter/buffersink.h>
#include <libavfilter/buffersrc.h>
#include <libavutil/imgutils.h>
#include <libavutil/opt.h>
}

#include <fcntl.h>
#include <libdeflate.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "output/atomic_output.hpp"
#include "video/libav_support.hpp"

namespace bookspin::video {
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
  output::AtomicFile output;
  libav::OutputFormatPtr format;
  libav::CodecContextPtr codec;
  AVStream* stream = nullptr;  // owned by `format`
  libav::PacketPtr packet;
  std::int64_t frames = 0;
  bool closed = false;

  StreamFile(const char* label_, std::filesystem::path path)
      : label(label_), output(std::move(path)) {}

  [[noreturn]] void throw_io(const std::string& action, int rc) const {
    throw_output_error(action, output.final_path(), libav::failure_text(rc));
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

  /// Encodes `frame` (null: flush) and muxes the packets that are ready. While flushing,
  /// `stop` is polled before each packet (`stage`): a signal throws Interrupted.
  void encode(const AVFrame* frame, const StopPoll& stop = {}, std::string_view stage = {}) {
    int rc = avcodec_send_frame(codec.get(), frame);
    if (rc < 0) {
      throw EncoderError(std::string(codec->codec->name) +
                         " rejected a frame: " + libav::failure_text(rc));
    }
    if (frame != nullptr) ++frames;
    for (;;) {
      if (frame == nullptr) stop_if_asked(stop, stage);
      rc = avcodec_receive_packet(codec.get(), packet.get());
      if (rc == AVERROR_EOF || (frame != nullptr && rc == AVERROR(EAGAIN))) return;
      if (rc < 0) {
        throw EncoderError(std::string(codec->codec->name) + " failed: " + libav::failure_text(rc));
      }
      if (packet->duration == 0) packet->duration = 1;  // one frame of the time base
      av_packet_rescale_ts(packet.get(), codec->time_base, stream->time_base);
      packet->stream_index = stream->index;
      rc = av_interleaved_write_frame(format.get(), packet.get());
      if (rc < 0) throw_io(std::string("cannot write ") + label, rc);
    }
  }

  /// Flushes the encoder (polling `stop` at `stage`, see encode()), writes the trailer,
  /// closes and renames the file into place (with `set`: adds it to the set, which puts it
  /// in place).
  void finish(output::OutputSet* set, const StopPoll& stop = {}, std::string_view stage = {}) {
    if (closed) throw std::logic_error(std::string(label) + " finish called twice");
    closed = true;
    if (frames == 0)
      throw EncoderError(std::string(label) + " \"" + output.final_path().string() +
                         "\" has no frames");
    encode(nullptr, stop, stage);
    int rc = av_write_trailer(format.get());
    if (rc < 0) throw_io(std::string("cannot finish ") + label, rc);
    rc = avio_closep(&format->pb);
    if (rc < 0) throw_io(std::string("cannot finish ") + label, rc);
    if (set != nullptr) {
      set->add(output);
    } else {
      output.commit();
    }
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

void WebmEncoder::finish(output::OutputSet* set, const StopPoll& stop) {
  impl_->file.finish(set, stop, "webm flush");
}
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

namespace {

/// The scaled frames between the GIF's two passes: each deflated (libdeflate, level 1) and
/// appended to a file of no name in the GIF's folder (O_TMPFILE, or a name removed at once),
/// so the clip's length costs disk, not memory, and the file goes with the process.
class FrameSpill {
 public:
  FrameSpill(const std::filesystem::path& gif, std::size_t frame_bytes)
      : gif_(gif), frame_bytes_(frame_bytes) {
    const std::filesystem::path dir = gif.has_parent_path() ? gif.parent_path() : ".";
    fd_ = open(dir.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0600);
    if (fd_ < 0) {  // a file system without O_TMPFILE: a name, removed once open
      std::string name = ".";
      name += gif.filename().string();
      name += ".frames-";
      name += std::to_string(getpid());
      const std::filesystem::path named = dir / name;
      fd_ = open(named.c_str(), O_CREAT | O_EXCL | O_RDWR | O_CLOEXEC, 0600);
      if (fd_ >= 0) unlink(named.c_str());
    }
    if (fd_ < 0) throw_output_error("cannot create the GIF's frame store for", gif, errno);
    compressor_ = libdeflate_alloc_compressor(1);
    decompressor_ = libdeflate_alloc_decompressor();
    if (compressor_ == nullptr || decompressor_ == nullptr)
      throw EncoderError("out of memory allocating the GIF's frame store");
    buffer_.resize(libdeflate_deflate_compress_bound(compressor_, frame_bytes_));
  }
  ~FrameSpill() {
    libdeflate_free_compressor(compressor_);
    libdeflate_free_decompressor(decompressor_);
    if (fd_ >= 0) close(fd_);
  }
  FrameSpill(const FrameSpill&) = delete;
  FrameSpill& operator=(const FrameSpill&) = delete;

  /// Stores `frame_bytes` bytes at `data` after the frames stored so far.
  void append(const std::uint8_t* data) {
    const std::uint64_t size = libdeflate_deflate_compress(compressor_, data, frame_bytes_,
                                                           buffer_.data(), buffer_.size());
    if (size == 0) throw EncoderError("libdeflate could not compress a GIF frame");
    write_all(&size, sizeof size);
    write_all(buffer_.data(), size);
  }
  /// The next stored frame into `data` (frame_bytes), from the first on; false after the last.
  bool read_next(std::uint8_t* data) {
    std::uint64_t size = 0;
    if (read_offset_ >= write_offset_) return false;
    read_all(&size, sizeof size);
    if (size > buffer_.size()) throw std::logic_error("GIF frame store: a record is too long");
    read_all(buffer_.data(), size);
    std::size_t out = 0;
    if (libdeflate_deflate_decompress(decompressor_, buffer_.data(), size, data, frame_bytes_,
                                      &out) != LIBDEFLATE_SUCCESS ||
        out != frame_bytes_) {
      throw std::logic_error("GIF frame store: a frame does not decompress to its size");
    }
    return true;
  }

 private:
  void write_all(const void* data, std::size_t bytes) {
    const auto* p = static_cast<const std::uint8_t*>(data);
    while (bytes > 0) {
      const ssize_t n = pwrite(fd_, p, bytes, write_offset_);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) throw_output_error("cannot store the frames of", gif_, n < 0 ? errno : ENOSPC);
      p += n;
      bytes -= static_cast<std::size_t>(n);
      write_offset_ += n;
    }
  }
  void read_all(void* data, std::size_t bytes) {
    auto* p = static_cast<std::uint8_t*>(data);
    while (bytes > 0) {
      const ssize_t n = pread(fd_, p, bytes, read_offset_);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) throw_output_error("cannot read back the frames of", gif_, n < 0 ? errno : EIO);
      p += n;
      bytes -= static_cast<std::size_t>(n);
      read_offset_ += n;
    }
  }

  std::filesystem::path gif_;
  std::size_t frame_bytes_;
  int fd_ = -1;
  off_t write_offset_ = 0, read_offset_ = 0;
  libdeflate_compressor* compressor_ = nullptr;
  libdeflate_decompressor* decompressor_ = nullptr;
  std::vector<std::uint8_t> buffer_;
};

/// A buffer source named `name` for frames of `width`×`height` in `format` at `time_base`.
AVFilterContext* add_source(AVFilterGraph* graph, const char* name, int width, int height,
                            AVPixelFormat format, AVRational time_base) {
  const std::string args = "video_size=" + size_text(width, height) +
                           ":pix_fmt=" + std::to_string(format) +
                           ":time_base=" + std::to_string(time_base.num) + "/" +
                           std::to_string(time_base.den) + ":pixel_aspect=1/1";
  AVFilterContext* source = nullptr;
  const int rc = avfilter_graph_create_filter(&source, avfilter_get_by_name("buffer"), name,
                                              args.c_str(), nullptr, graph);
  if (rc < 0) throw EncoderError("GIF filter source: " + libav::error_text(rc));
  return source;
}

/// A graph from `sources` (named as in `description`) through `description` into one sink.
FilterGraphPtr make_graph(const std::vector<std::pair<const char*, AVFilterContext**>>& sources,
                          const std::string& description,
                          const std::function<void(AVFilterGraph*)>& add_sources,
                          AVFilterContext** sink) {
  FilterGraphPtr graph(avfilter_graph_alloc());
  if (!graph) throw EncoderError("out of memory allocating the GIF filter graph");
  graph->nb_threads = 1;
  add_sources(graph.get());
  int rc = avfilter_graph_create_filter(sink, avfilter_get_by_name("buffersink"), "out", nullptr,
                                        nullptr, graph.get());
  if (rc < 0) throw EncoderError("GIF filter sink: " + libav::error_text(rc));
  AVFilterInOut* outputs = nullptr;
  AVFilterInOut* inputs = avfilter_inout_alloc();
  for (auto it = sources.rbegin(); it != sources.rend(); ++it) {
    AVFilterInOut* out = avfilter_inout_alloc();
    if (out == nullptr) break;
    out->name = av_strdup(it->first);
    out->filter_ctx = *it->second;
    out->next = outputs;
    outputs = out;
  }
  if (outputs == nullptr || inputs == nullptr) {
    avfilter_inout_free(&outputs);
    avfilter_inout_free(&inputs);
    throw EncoderError("out of memory building the GIF filter graph");
  }
  inputs->name = av_strdup("out");
  inputs->filter_ctx = *sink;
  libav::LogCapture capture;
  rc = avfilter_graph_parse_ptr(graph.get(), description.c_str(), &inputs, &outputs, nullptr);
  if (rc >= 0) rc = avfilter_graph_config(graph.get(), nullptr);
  avfilter_inout_free(&outputs);
  avfilter_inout_free(&inputs);
  if (rc < 0) {
    throw EncoderError("GIF palette filters (palettegen, paletteuse): " + capture.text() + " (" +
                       libav::error_text(rc) + ")");
  }
  return graph;
}

/// Hands `frame` (null: end of stream) to `source` and runs the graph on it at once, so that
/// no frame waits in the graph's queues.
void push(AVFilterContext* source, AVFrame* frame) {
  const int rc = av_buffersrc_add_frame_flags(source, frame,
                                              AV_BUFFERSRC_FLAG_KEEP_REF | AV_BUFFERSRC_FLAG_PUSH);
  if (rc < 0) throw EncoderError("GIF palette filters rejected a frame: " + libav::error_text(rc));
}

}  // namespace

// Two passes, so that memory does not grow with the clip: while frames come, each kept one is
// scaled, counted into the palette (palettegen over every frame) and stored deflated on disk;
// at the end the palette is applied to the stored frames one at a time (paletteuse) and each
// is encoded.
struct GifEncoder::Impl {
  GifSettings settings;
  int step = 1;
  int height = 0;
  std::int64_t seen = 0;  ///< frames handed to add_frame
  StreamFile file;
  libav::SwsPtr scaler;
  libav::FramePtr scaled;  ///< the last kept frame, scaled, RGB32 as palettegen takes it
  FilterGraphPtr palette_graph;
  AVFilterContext* palette_source = nullptr;  // owned by palette_graph
  AVFilterContext* palette_sink = nullptr;
  std::optional<FrameSpill> spill;
  libav::FramePtr filtered;
  Impl(std::filesystem::path path, const GifSettings& s)
      : settings(s), file("GIF", std::move(path)) {}

  AVRational time_base() const { return AVRational{step, settings.fps}; }
  std::size_t frame_bytes() const { return static_cast<std::size_t>(settings.width) * height * 4; }
  /// Applies `palette` to every stored frame and encodes them in order, polling `stop` as
  /// it starts ("gif palette pass") and before each frame ("gif palette frames").
  void apply_palette(AVFrame* palette, const StopPoll& stop);
  /// Encodes every frame `sink` has ready; at the end (`eof`) until it has none left.
  void pull(AVFilterContext* sink, bool eof, const StopPoll& stop = {});
};

void GifEncoder::Impl::pull(AVFilterContext* sink, bool eof, const StopPoll& stop) {
  for (;;) {
    if (eof) stop_if_asked(stop, "gif palette frames");
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

void GifEncoder::Impl::apply_palette(AVFrame* palette, const StopPoll& stop) {
  AVFilterContext* frames_source = nullptr;
  AVFilterContext* palette_in = nullptr;
  AVFilterContext* sink = nullptr;
  // A small ordered dither: ordered patterns stay put from frame to frame, so LZW and the
  // frame differences (diff_mode=rectangle) keep the file small.
  const FilterGraphPtr graph = make_graph(
      {{"frames", &frames_source}, {"palette", &palette_in}},
      "[frames][palette]paletteuse=dither=bayer:bayer_scale=4:diff_mode=rectangle",
      [&](AVFilterGraph* g) {
        frames_source =
            add_source(g, "frames", settings.width, height, AV_PIX_FMT_RGB32, time_base());
        palette_in = add_source(g, "palette", palette->width, palette->height,
                                static_cast<AVPixelFormat>(palette->format), time_base());
      },
      &sink);
  palette->pts = 0;
  push(palette_in, palette);
  push(palette_in, nullptr);  // one palette for the whole clip
  stop_if_asked(stop, "gif palette pass");
  for (std::int64_t index = 0;; ++index) {
    stop_if_asked(stop, "gif palette frames");
    const int rc = av_frame_make_writable(scaled.get());
    if (rc < 0) throw EncoderError("frame buffer: " + libav::error_text(rc));
    if (scaled->linesize[0] != settings.width * 4)
      throw std::logic_error("GIF frame rows are padded");
    if (!spill->read_next(scaled->data[0])) break;
    scaled->pts = index;
    push(frames_source, scaled.get());
    pull(sink, false);
  }
  push(frames_source, nullptr);
  pull(sink, true, stop);
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
  if (s.fps > kGifMaxFps * gif_step(s)) {
    throw std::invalid_argument("GIF fps " + std::to_string(s.gif_fps) + " of " +
                                std::to_string(s.fps) + " frames/s plays faster than " +
                                std::to_string(kGifMaxFps) + " frames/s");
  }
  impl_ = std::make_unique<Impl>(std::move(path), s);
  Impl& g = *impl_;
  g.step = gif_step(s);
  g.height = gif_height(s);
  AVCodecContext* c = g.file.open("gif", "gif");
  c->width = s.width;
  c->height = g.height;
  c->pix_fmt = AV_PIX_FMT_PAL8;
  c->time_base = g.time_base();
  c->framerate = AVRational{s.fps, g.step};
  g.palette_graph = make_graph(
      {{"in", &g.palette_source}}, "palettegen=stats_mode=full",
      [&](AVFilterGraph* graph) {
        g.palette_source =
            add_source(graph, "in", s.width, g.height, AV_PIX_FMT_RGB32, g.time_base());
      },
      &g.palette_sink);
  g.scaler.reset(sws_getContext(s.source_width, s.source_height, AV_PIX_FMT_RGBA, s.width, g.height,
                                AV_PIX_FMT_RGB32, SWS_LANCZOS, nullptr, nullptr, nullptr));
  if (!g.scaler) throw EncoderError("swscale cannot scale the GIF's frames");
  g.scaled = make_frame(AV_PIX_FMT_RGB32, s.width, g.height);
  g.spill.emplace(g.file.output.final_path(), g.frame_bytes());
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
  const int rc = av_frame_make_writable(g.scaled.get());
  if (rc < 0) throw EncoderError("frame buffer: " + libav::error_text(rc));
  if (g.scaled->linesize[0] != g.settings.width * 4)
    throw std::logic_error("GIF frame rows are padded");
  const std::uint8_t* source[4] = {image.pixels.data(), nullptr, nullptr, nullptr};
  const int stride[4] = {image.width * 4, 0, 0, 0};
  sws_scale(g.scaler.get(), source, stride, 0, image.height, g.scaled->data, g.scaled->linesize);
  g.scaled->pts = index / g.step;
  push(g.palette_source, g.scaled.get());
  g.spill->append(g.scaled->data[0]);
}

void GifEncoder::finish(output::OutputSet* set, const StopPoll& stop) {
  Impl& g = *impl_;
  stop_if_asked(stop, "gif finish");
  if (!g.file.closed && g.seen > 0) {
    push(g.palette_source, nullptr);  // end of stream: palettegen gives its palette
    libav::FramePtr palette(av_frame_alloc());
    if (!palette) throw EncoderError("out of memory allocating a frame");
    const int rc = av_buffersink_get_frame(g.palette_sink, palette.get());
    if (rc < 0) throw EncoderError("GIF palette (palettegen): " + libav::error_text(rc));
    g.palette_graph.reset();  // its counts are no longer needed
    g.apply_palette(palette.get(), stop);
  }
  g.file.finish(set, stop, "gif palette frames");
}

std::int64_t GifEncoder::frame_count() const { return impl_->file.frames; }

}  // namespace bookspin::video
