// SIGINT at a random moment never leaves a partial output under a final name and never
// damages an earlier complete clip.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <random>
#include <thread>

#include "support/cli_runner.hpp"

namespace bookspin::cli {
namespace {

using namespace bookspin::test;  // the shared runner (tests/support)

namespace fs = std::filesystem;

const std::vector<std::string> kArgs = {"render", scene_path("fig09-matrix-unstable-x"),
                                        "--set",  "render.width=96",
                                        "--set",  "render.height=64",
                                        "--set",  "render.preset=\"ultrafast\"",
                                        "--jobs", "2"};

pid_t start_render(const fs::path& out, int frames) {
  std::vector<std::string> args = kArgs;
  args.insert(args.end(), {"-o", out.string(), "--frames", std::to_string(frames)});
  const pid_t pid = fork();
  if (pid == 0) {
    std::vector<char*> argv{const_cast<char*>(BOOKSPIN_EXE)};
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    freopen("/dev/null", "w", stderr);
    execv(BOOKSPIN_EXE, argv.data());
    _exit(127);
  }
  return pid;
}

int wait_status(pid_t pid) {
  int raw = 0;
  waitpid(pid, &raw, 0);
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
}

/// Every entry under `dir` (recursively) with its size and content for files.
std::map<std::string, std::string> snapshot(const fs::path& dir) {
  std::map<std::string, std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    out[fs::relative(e.path(), dir).string()] = e.is_regular_file() ? read_file(e.path()) : "<dir>";
  }
  return out;
}

TEST(Interrupt, SigintTwentyTimesNeverLeavesPartialOutputsOrDamagesEarlierClip) {
  const fs::path out = fresh_dir("interrupt");
  ASSERT_EQ(wait_status(start_render(out, 12)), 0);
  const auto complete = snapshot(out);
  ASSERT_TRUE(complete.count("fig09-matrix-unstable-x.mp4"));
  ASSERT_TRUE(complete.count("fig09-matrix-unstable-x/frames/frame_00011.png"));
  // The signal comes at a random moment between 5% and 120% of how long a whole render
  // takes on this machine (measured here, so that a fast machine or a slow sanitizer build
  // interrupts about as often): most renders are cut short, a few finish first.
  const fs::path timing = fresh_dir("interrupt-timing");
  const auto start = std::chrono::steady_clock::now();
  ASSERT_EQ(wait_status(start_render(timing, 60)), 0);
  const double whole_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  std::mt19937 random(20121);
  std::uniform_real_distribution<double> moment(0.05 * whole_ms, 1.2 * whole_ms);
  int interrupted = 0;
  for (int attempt = 0; attempt < 20; ++attempt) {
    const pid_t pid = start_render(out, 60);
    std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(moment(random)));
    kill(pid, SIGINT);
    const int status = wait_status(pid);
    ASSERT_TRUE(status == 130 || status == 0) << "attempt " << attempt << ": status " << status;
    const auto now = snapshot(out);
    for (const auto& [name, content] : now)
      EXPECT_EQ(name.find(".tmp-"), std::string::npos) << "leftover temporary " << name;
    if (status == 130) {
      ++interrupted;
      EXPECT_EQ(now, complete) << "attempt " << attempt << " changed the earlier clip";
    } else {
      // It finished before the signal: a complete new clip replaced the old one.
      EXPECT_TRUE(now.count("fig09-matrix-unstable-x/frames/frame_00059.png"));
      EXPECT_EQ(wait_status(start_render(out, 12)), 0);  // back to the reference clip
    }
  }
  EXPECT_GE(interrupted, 10) << "too few renders were actually interrupted";
}

}  // namespace
}  // namespace bookspin::cli
