#include "video/mp4_encoder.hpp"

#include <ctime>
#include <stdexcept>
#include <string>

#include "output/atomic_output.hpp"
#include "video/codec_selection.hpp"
#include "video/libav_support.hpp"

namespace bookspin::video {
namespace {

double thread_cpu_seconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

std::string size_text(int width, int height) {
  return std::to_string(width) + "x" + std::to_string(height);
}

void validate(const EncoderSettings& settings) {
  const std::string size = size_text(settings.width, settings.height);
  if (settings.width <= 0 || settings.height <= 0) {
    throw std::invalid_argument("MP4 size " + size + " is not positive");
  }
  if (settings.width % 2 != 0 || settings.height % 2 != 0) {
    throw std::invalid_argument("MP4 size " + size + " is odd: 4:2:0 video needs even sizes");
  }
  if (settings.fps < 1 || settings.fps > 1000) {
    throw std::invalid_argument("MP4 fps " + std::to_string(settings.fps) + " is outside 1…1000");
  }
  if (settings.crf < 0 || settings.crf > 51) {
    throw std::invalid_argument("MP4 crf " + std::to_string(settings.crf) + " is outside 0…51");
  }
}

}  // namespace

// Member order matters: members die in reverse, so the libav objects (and the
// open file, via `format`) are released before `output` deletes the temporary.
struct Mp4Encoder::Impl {
  EncoderSettings settings;
  output::AtomicFile output;
  std::string codec_name;
  std::string fallback_message;
  libav::OutputFormatPtr format;
  libav::CodecContextPtr codec;
  AVStream* stream = nullptr;  // owned by `format`
  libav::SwsPtr scaler;
  libav::FramePtr frame;
  libav::PacketPtr packet;
  std::int64_t frames_added = 0;
  double conversion_seconds = 0.0;  ///< CPU time in sws_scale so far
  bool closed = false;

  Impl(std::filesystem::path path, const EncoderSettings& s)
      : settings(s), output(std::move(path)) {}

  [[noreturn]] void throw_io(const char* action, int rc) const {
    throw_output_error(action, output.final_path(), libav::failure_text(rc));
  }

  void open_container();
  void add_stream();
  void write_header();
  void make_converter();
  void encode(const AVFrame* input, const StopPoll& stop = {});
  void drain(bool flushing, const StopPoll& stop = {});
};

void Mp4Encoder::Impl::open_container() {
  // "file:" keeps ':' or a leading '-' in the path from being read as a
  // protocol; the mov muxer reopens this same URL for the faststart pass.
  const std::string url = "file:" + output.temp_path().string();
  AVFormatContext* raw = nullptr;
  // The muxer is named explicitly: the temporary's extension is not ".mp4".
  const int rc = avformat_alloc_output_context2(&raw, nullptr, "mp4", url.c_str());
  if (rc < 0 || raw == nullptr) throw EncoderError("mp4 muxer: " + libav::error_text(rc));
  format.reset(raw);
}

void Mp4Encoder::Impl::add_stream() {
  stream = avformat_new_stream(format.get(), nullptr);
  if (stream == nullptr) throw EncoderError("cannot add a video stream to the MP4");
  const AVRational fps{settings.fps, 1};
  stream->time_base = AVRational{1, settings.fps};  // a hint; the muxer may refine it
  stream->avg_frame_rate = fps;
  stream->r_frame_rate = fps;
  const int rc = avcodec_parameters_from_context(stream->codecpar, codec.get());
  if (rc < 0) throw EncoderError("codec parameters: " + libav::error_text(rc));
}

void Mp4Encoder::Impl::write_header() {
  int rc = avio_open(&format->pb, format->url, AVIO_FLAG_WRITE);
  if (rc < 0) throw_io("cannot create MP4", rc);
  AVDictionary* raw_options = nullptr;
  av_dict_set(&raw_options, "movflags", "+faststart", 0);
  rc = avformat_write_header(format.get(), &raw_options);
  av_dict_free(&raw_options);
  if (rc < 0) throw_io("cannot write MP4 header of", rc);
}

void Mp4Encoder::Impl::make_converter() {
  const int w = settings.width, h = settings.height;
  // Bicubic luma plus full-resolution chroma input and accurate rounding:
  // thin dark edges on a light page smear least this way.
  const int flags = SWS_BICUBIC | SWS_FULL_CHR_H_INP | SWS_ACCURATE_RND;
  scaler.reset(sws_getContext(w, h, AV_PIX_FMT_RGBA, w, h, AV_PIX_FMT_YUV420P, flags, nullptr,
                              nullptr, nullptr));
  if (!scaler) throw EncoderError("swscale cannot convert RGBA to yuv420p");
  // Match the BT.709 limited-range tags set on the codec (codec_selection.cpp).
  const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
  sws_setColorspaceDetails(scaler.get(), bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16);

  frame.reset(av_frame_alloc());
  packet.reset(av_packet_alloc());
  if (!frame || !packet) throw EncoderError("out of memory allocating a frame");
  frame->format = AV_PIX_FMT_YUV420P;
  frame->width = w;
  frame->height = h;
  const int rc = av_frame_get_buffer(frame.get(), 0);
  if (rc < 0) throw EncoderError("frame buffer: " + libav::error_text(rc));
}

void Mp4Encoder::Impl::encode(const AVFrame* input, const StopPoll& stop) {
  const int rc = avcodec_send_frame(codec.get(), input);
  if (rc < 0) throw EncoderError(codec_name + " rejected a frame: " + libav::failure_text(rc));
  drain(input == nullptr, stop);
}

// Moves every packet the encoder has ready into the muxer. When flushing,
// runs until the encoder reports end of stream.
void Mp4Encoder::Impl::drain(bool flushing, const StopPoll& stop) {
  for (;;) {
    if (flushing) stop_if_asked(stop, "mp4 flush");
    int rc = avcodec_receive_packet(codec.get(), packet.get());
    if (rc == AVERROR_EOF || (!flushing && rc == AVERROR(EAGAIN))) return;
    if (rc < 0) throw EncoderError(codec_name + " failed: " + libav::failure_text(rc));
    // Every packet is one frame of 1/fps; without a duration the muxer would
    // have to guess the last frame's length and avg_frame_rate would drift.
    if (packet->duration == 0) packet->duration = 1;
    av_packet_rescale_ts(packet.get(), codec->time_base, stream->time_base);
    packet->stream_index = stream->index;
    rc = av_interleaved_write_frame(format.get(), packet.get());  // takes the packet's data
    if (rc < 0) throw_io("cannot write MP4", rc);
  }
}

Mp4Encoder::Mp4Encoder(std::filesystem::path path, const EncoderSettings& settings) {
  validate(settings);
  impl_ = std::make_unique<Impl>(std::move(path), settings);
  Impl& s = *impl_;
  s.open_container();
  const bool global_header = (s.format->oformat->flags & AVFMT_GLOBALHEADER) != 0;
  OpenedEncoder opened = open_h264_encoder(settings, global_header);
  s.codec = std::move(opened.context);
  s.codec_name = std::move(opened.name);
  s.fallback_message = std::move(opened.fallback_message);
  s.add_stream();
  s.write_header();
  s.make_converter();
}

Mp4Encoder::~Mp4Encoder() = default;
Mp4Encoder::Mp4Encoder(Mp4Encoder&&) noexcept = default;
Mp4Encoder& Mp4Encoder::operator=(Mp4Encoder&&) noexcept = default;

void Mp4Encoder::add_frame(const RgbaImage& image) {
  Impl& s = *impl_;
  if (s.closed) throw std::logic_error("Mp4Encoder::add_frame after finish");
  if (image.width != s.settings.width || image.height != s.settings.height ||
      image.pixels.size() != static_cast<std::size_t>(image.width) * image.height * 4) {
    throw std::invalid_argument("frame " + size_text(image.width, image.height) +
                                " does not match MP4 size " +
                                size_text(s.settings.width, s.settings.height));
  }
  // The encoder may still reference the previous picture's buffer.
  const int rc = av_frame_make_writable(s.frame.get());
  if (rc < 0) throw EncoderError("frame buffer: " + libav::error_text(rc));
  // sws_scale reads four plane pointers and strides, even for packed RGBA.
  const std::uint8_t* source[4] = {image.pixels.data(), nullptr, nullptr, nullptr};
  const int source_stride[4] = {image.width * 4, 0, 0, 0};
  const double start = thread_cpu_seconds();
  sws_scale(s.scaler.get(), source, source_stride, 0, image.height, s.frame->data,
            s.frame->linesize);
  s.conversion_seconds += thread_cpu_seconds() - start;
  s.frame->pts = s.frames_added;
  s.encode(s.frame.get());
  ++s.frames_added;
}

void Mp4Encoder::finish(output::OutputSet* set, const StopPoll& stop) {
  Impl& s = *impl_;
  if (s.closed) throw std::logic_error("Mp4Encoder::finish called twice");
  s.closed = true;  // a failed finish cannot be retried; the destructor cleans up
  if (s.frames_added == 0) {
    throw EncoderError("MP4 \"" + s.output.final_path().string() + "\" has no frames");
  }
  s.encode(nullptr, stop);
  int rc = av_write_trailer(s.format.get());  // also the faststart rewrite
  if (rc < 0) s.throw_io("cannot finish MP4", rc);
  rc = avio_closep(&s.format->pb);  // flushes: a full disk may show up only here
  if (rc < 0) s.throw_io("cannot finish MP4", rc);
  if (set != nullptr) {
    set->add(s.output);
  } else {
    s.output.commit();
  }
}

std::int64_t Mp4Encoder::frame_count() const { return impl_->frames_added; }
const std::string& Mp4Encoder::codec_name() const { return impl_->codec_name; }
const std::string& Mp4Encoder::fallback_message() const { return impl_->fallback_message; }
const std::filesystem::path& Mp4Encoder::path() const { return impl_->output.final_path(); }
double Mp4Encoder::conversion_seconds() const { return impl_->conversion_seconds; }

}  // namespace bookspin::video
