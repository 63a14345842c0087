// FFmpeg's own log lines never reach the user as they are: once the video stage has set up
// logging, a message libav logs goes into the error that follows it, or nowhere.
#include "video/libav_support.hpp"

#include <gtest/gtest.h>

#include <string>
#include <thread>

namespace bookspin::video {
namespace {

TEST(LibavLogging, MessagesGoIntoTheNextFailureNotToStderr) {
  libav::configure_logging();
  ::testing::internal::CaptureStderr();
  av_log(nullptr, AV_LOG_ERROR, "non monotonically increasing dts to muxer: 3 >= 3\n");
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
  EXPECT_EQ(libav::failure_text(AVERROR(EINVAL)),
            "Invalid argument (non monotonically increasing dts to muxer: 3 >= 3)");
  // Told once: the next failure does not repeat it.
  EXPECT_EQ(libav::failure_text(AVERROR(EINVAL)), "Invalid argument");
}

TEST(LibavLogging, ACaptureTakesTheMessagesOfItsThreadAndOthersAreKeptApart) {
  libav::configure_logging();
  ::testing::internal::CaptureStderr();
  std::string captured;
  {
    libav::LogCapture capture;
    av_log(nullptr, AV_LOG_ERROR, "first\n");
    av_log(nullptr, AV_LOG_FATAL, "second\n");
    av_log(nullptr, AV_LOG_INFO, "below the level: dropped\n");
    std::thread([] { av_log(nullptr, AV_LOG_ERROR, "another thread\n"); }).join();
    captured = capture.text();
  }
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
  EXPECT_EQ(captured, "first; second");
  EXPECT_EQ(libav::failure_text(AVERROR(ENOSPC)), "No space left on device");
}

}  // namespace
}  // namespace bookspin::video
