#pragma once
// Internal to the video stage: RAII owners and error/log plumbing for FFmpeg.
// Nothing outside src/video (and its tests) should include this: it drags in libav headers.
extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/frame.h>
#include <libswscale/swscale.h>
}

#include <memory>
#include <stdexcept>
#include <string>

#include "common/non_copyable.hpp"

namespace bookspin::video::libav {

/// av_strerror text for a libav error code, e.g. "No space left on device".
std::string error_text(int code);

/// Once per process: libav logs only AV_LOG_ERROR and worse, through a
/// callback that diverts messages into an active LogCapture on this thread. No
/// line of FFmpeg's reaches stderr as it is: without a capture, the thread's
/// last message is kept for failure_text() (and dropped when no failure follows).
void configure_logging();

/// error_text(code) followed by what libav last logged on this thread, if
/// anything, in parentheses ("Invalid argument (Application provided invalid, non
/// monotonically increasing dts to muxer …)"); takes that message, so it is told once.
std::string failure_text(int code);

/// While alive, libav error messages logged on this thread are collected in
/// text() instead of printed (used to explain why an encoder failed to open).
class LogCapture : NonCopyable {
 public:
  LogCapture();
  ~LogCapture();
  /// Captured messages joined with "; ", trailing newlines stripped.
  const std::string& text() const { return text_; }

 private:
  std::string text_;
  std::string* previous_;
};

struct CodecContextDeleter {
  void operator()(AVCodecContext* context) const { avcodec_free_context(&context); }
};
struct FrameDeleter {
  void operator()(AVFrame* frame) const { av_frame_free(&frame); }
};
struct PacketDeleter {
  void operator()(AVPacket* packet) const { av_packet_free(&packet); }
};
struct SwsDeleter {
  void operator()(SwsContext* context) const { sws_freeContext(context); }
};
/// Closes the output file (if the muxer opened one) and frees the context.
struct OutputFormatDeleter {
  void operator()(AVFormatContext* context) const;
};
struct DictionaryDeleter {
  void operator()(AVDictionary* dictionary) const { av_dict_free(&dictionary); }
};

using CodecContextPtr = std::unique_ptr<AVCodecContext, CodecContextDeleter>;
using FramePtr = std::unique_ptr<AVFrame, FrameDeleter>;
using PacketPtr = std::unique_ptr<AVPacket, PacketDeleter>;
using SwsPtr = std::unique_ptr<SwsContext, SwsDeleter>;
using OutputFormatPtr = std::unique_ptr<AVFormatContext, OutputFormatDeleter>;

}  // namespace bookspin::video::libav
