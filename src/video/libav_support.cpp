#include "video/libav_support.hpp"

#include <cstdarg>
#include <mutex>

namespace bookspin::video::libav {
namespace {

// The capture target of the calling thread; libav calls the log callback on
// the thread that triggered the message, so this needs no locking.
thread_local std::string* capture_target = nullptr;
// The last message logged on this thread outside a capture, for failure_text().
thread_local std::string last_message;

void append_line(std::string& text, const char* line) {
  std::string trimmed(line);
  while (!trimmed.empty() && (trimmed.back() == '\n' || trimmed.back() == ' ')) trimmed.pop_back();
  if (trimmed.empty()) return;
  if (!text.empty()) text += "; ";
  text += trimmed;
}

void log_callback(void* context, int level, const char* format, va_list args) {
  if (level > av_log_get_level()) return;
  char line[1024];
  int print_prefix = 0;  // drop "[h264_nvenc @ 0x…]": the caller names the encoder
  av_log_format_line2(context, level, format, args, line, sizeof line, &print_prefix);
  if (capture_target != nullptr) {
    append_line(*capture_target, line);
  } else {
    last_message.clear();
    append_line(last_message, line);
  }
}

}  // namespace

std::string error_text(int code) {
  char buffer[AV_ERROR_MAX_STRING_SIZE] = {};
  if (av_strerror(code, buffer, sizeof buffer) < 0) {
    return "libav error " + std::to_string(code);
  }
  return buffer;
}

std::string failure_text(int code) {
  std::string text = error_text(code);
  if (!last_message.empty()) text += " (" + last_message + ")";
  last_message.clear();
  return text;
}

void configure_logging() {
  static std::once_flag once;
  std::call_once(once, [] {
    av_log_set_level(AV_LOG_ERROR);
    av_log_set_callback(log_callback);
  });
}

LogCapture::LogCapture() : previous_(capture_target) { capture_target = &text_; }

LogCapture::~LogCapture() { capture_target = previous_; }

void OutputFormatDeleter::operator()(AVFormatContext* context) const {
  if (context == nullptr) return;
  if (context->pb != nullptr && !(context->oformat->flags & AVFMT_NOFILE)) {
    avio_closep(&context->pb);
  }
  avformat_free_context(context);
}

}  // namespace bookspin::video::libav
