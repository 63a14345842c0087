// Every error becomes one line and an exit status in one place: bad input 2, a failed write
// 1, a bug (a broken internal check) 70 with "internal error", never 2.
#include "cli/run_guarded.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

#include "common/errors.hpp"
#include "render/render_error.hpp"
#include "video/video.hpp"

namespace bookspin::cli {
namespace {

struct Outcome {
  int status = -1;
  std::string stderr_text;
};

Outcome run(const std::function<int()>& command) {
  ::testing::internal::CaptureStderr();
  Outcome outcome;
  outcome.status = run_guarded(command);
  outcome.stderr_text = ::testing::internal::GetCapturedStderr();
  return outcome;
}

TEST(RunGuarded, AFailedInternalCheckIsAnInternalErrorWithStatus70) {
  const Outcome o = run([] {
    const int frames = 0;
    BOOKSPIN_ASSERT(frames > 0);
    return 0;
  });
  EXPECT_EQ(o.status, 70);
  EXPECT_EQ(o.stderr_text.rfind("bookspin: internal error: ", 0), 0u) << o.stderr_text;
  EXPECT_NE(o.stderr_text.find("check failed: frames > 0"), std::string::npos) << o.stderr_text;
  EXPECT_NE(o.stderr_text.find("run_guarded_test.cpp:"), std::string::npos) << o.stderr_text;
}

TEST(RunGuarded, StandardLibraryLogicErrorsAreBugsNotBadInput) {
  // Before this mapping an invalid_argument from an internal check was reported as bad input.
  EXPECT_EQ(run([]() -> int { throw std::invalid_argument("capacity must be positive"); }).status,
            70);
  EXPECT_EQ(run([]() -> int { throw std::out_of_range("frame 9 is outside"); }).status, 70);
  EXPECT_EQ(run([]() -> int { throw 42; }).status, 70);
}

TEST(RunGuarded, BadInputIsStatus2WithTheInputLine) {
  const Outcome o =
      run([]() -> int { throw InputError("scene.toml", 3, "time.dt", "must be > 0, got 0"); });
  EXPECT_EQ(o.status, 2);
  EXPECT_EQ(o.stderr_text, "bookspin: error: scene.toml:3: time.dt: must be > 0, got 0\n");
}

// Whatever a message quotes (an option's value, a path), the line stays one line and sends no
// control sequence to the terminal: newline, carriage return, tab and ESC written as escapes.
TEST(RunGuarded, ControlCharactersInAMessageAreEscaped) {
  const Outcome o = run([]() -> int {
    throw InputError(std::string("--methods mu\x1b[31mjoco:rk4\nx\r\t: unknown"));
  });
  EXPECT_EQ(o.status, 2);
  EXPECT_EQ(o.stderr_text, "bookspin: error: --methods mu\\x1b[31mjoco:rk4\\nx\\r\\t: unknown\n");
}

TEST(RunGuarded, FailedWritesAndMissingMachineryAreStatus1) {
  const Outcome o = run([]() -> int { throw_output_error("cannot write", "out/a.csv", ENOSPC); });
  EXPECT_EQ(o.status, 1);
  EXPECT_EQ(o.stderr_text,
            "bookspin: error: cannot write \"out/a.csv\": No space left on device\n");
  EXPECT_EQ(run([]() -> int { throw render::RenderError("no EGL display"); }).status, 1);
  EXPECT_EQ(run([]() -> int { throw video::EncoderError("libx264 missing"); }).status, 1);
}

TEST(RunGuarded, PassesTheCommandsOwnStatusThrough) {
  EXPECT_EQ(run([] { return 0; }).status, 0);
  EXPECT_EQ(run([] { return 130; }).status, 130);
}

}  // namespace
}  // namespace bookspin::cli
