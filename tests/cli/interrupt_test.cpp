// SIGINT at any point never leaves a partial output under a final name and never damages an
// earlier complete clip; SIGTERM and SIGINT take back the folders they made; a render after
// a SIGKILL removes what the killed run left.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <thread>

#include "support/signal_runner.hpp"

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

/// The PNGs written so far into the frames temporary `.frames.tmp-*` under `clip_dir`.
int partial_frames(const fs::path& clip_dir) {
  std::error_code ec;
  int count = 0;
  for (fs::directory_iterator it(clip_dir, ec), end; !ec && it != end; it.increment(ec)) {
    if (it->path().filename().string().rfind(".frames.tmp-", 0) != 0) continue;
    std::error_code inner;
    for (fs::directory_iterator f(it->path(), inner), fend; !inner && f != fend; f.increment(inner))
      ++count;
  }
  return count;
}

/// Waits (polling every millisecond, up to a minute) until the render `pid` writing into
/// `clip_dir` has at least `frames` partial PNGs: the signal then comes at a known point of
/// the run, whatever the machine's speed or load. False if it exited or the minute passed.
/// On false the render is killed and reaped, so that no stray process outlives the test.
bool wait_for_partial_frames(pid_t pid, const fs::path& clip_dir, int frames) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(1);
  while (std::chrono::steady_clock::now() < deadline) {
    if (partial_frames(clip_dir) >= frames) return true;
    if (waitpid(pid, nullptr, WNOHANG) != 0) return false;  // it ended (and is reaped)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  kill(pid, SIGKILL);
  waitpid(pid, nullptr, 0);
  return false;
}

const std::string kName = "fig09-matrix-unstable-x";
// Long enough that a render signalled within its first 30 frames cannot finish first, even
// on a loaded machine (the rest takes seconds); short runs stop early, so this costs little.
constexpr int kLongRun = 1000;

// The signal comes at a point of the run set by the number of frames already written (0 …
// 28 of 1000), not by a timer, so every attempt is interrupted on any machine, loaded or not.
TEST(Interrupt, SigintTwentyTimesNeverLeavesPartialOutputsOrDamagesEarlierClip) {
  const fs::path out = fresh_dir("interrupt");
  ASSERT_EQ(wait_status(start_render(out, 12)), 0);
  const auto complete = snapshot(out);
  ASSERT_TRUE(complete.count(kName + ".mp4"));
  ASSERT_TRUE(complete.count(kName + "/frames/frame_00011.png"));
  for (int attempt = 0; attempt < 20; ++attempt) {
    const int after_frames = (attempt * 3) / 2;
    const pid_t pid = start_render(out, kLongRun);
    ASSERT_TRUE(wait_for_partial_frames(pid, out / kName, after_frames)) << "attempt " << attempt;
    kill(pid, SIGINT);
    const int status = wait_status(pid);
    ASSERT_EQ(status, 130) << "attempt " << attempt << " (after " << after_frames << " frames)";
    const auto now = snapshot(out);
    for (const auto& [name, content] : now)
      EXPECT_EQ(name.find(".tmp-"), std::string::npos) << "leftover temporary " << name;
    EXPECT_EQ(now, complete) << "attempt " << attempt << " changed the earlier clip";
  }
}

// SIGKILL leaves the temporaries (nothing can run); the next render of the same output
// removes them and leaves exactly a complete clip.
TEST(Interrupt, RenderAfterKillNineRemovesTheDeadRunsTemporaries) {
  const fs::path out = fresh_dir("interrupt-kill9");
  const pid_t pid = start_render(out, kLongRun);
  ASSERT_TRUE(wait_for_partial_frames(pid, out / kName, 5));
  kill(pid, SIGKILL);
  ASSERT_EQ(wait_status(pid), 128 + SIGKILL);
  const auto debris = temporaries(out);
  // The MP4, the diagnostics CSV and the frames folder (and the PNGs in it) were left.
  EXPECT_GE(debris.size(), 3u + 5u);
  ASSERT_EQ(wait_status(start_render(out, 12)), 0);
  EXPECT_EQ(temporaries(out), std::vector<std::string>{});
  const auto now = snapshot(out);
  EXPECT_TRUE(now.count(kName + ".mp4"));
  EXPECT_TRUE(now.count(kName + "/frames/frame_00011.png"));
  EXPECT_FALSE(now.count(kName + "/frames/frame_00012.png"));
}

/// A pid that no process has: a child that has exited and been reaped.
pid_t dead_pid() {
  const pid_t pid = fork();
  if (pid == 0) _exit(0);
  waitpid(pid, nullptr, 0);
  return pid;
}

void write_forged(const fs::path& path) { std::ofstream(path) << "left behind"; }

// Which leftovers a render removes: those in its output folders whose run is gone (another
// output's too), never those of a live run (a concurrent render of the same scene).
TEST(Interrupt, RenderRemovesOnlyTheTemporariesOfDeadRuns) {
  const fs::path out = fresh_dir("interrupt-forged");
  const fs::path clip_dir = out / kName;
  fs::create_directories(clip_dir);
  const std::string dead = std::to_string(dead_pid());
  const std::string live = std::to_string(getpid());  // this test: alive, started earlier
  const std::string mp4 = "." + kName + ".mp4.tmp-";
  // Gone: a dead pid (a file and a frames folder with a PNG in it).
  write_forged(out / (mp4 + dead + "-0"));
  fs::create_directories(clip_dir / (".frames.tmp-" + dead + "-2"));
  write_forged(clip_dir / (".frames.tmp-" + dead + "-2") / "frame_00000.png");
  // Gone: a live pid that started after the temporary was last written (a reused pid).
  write_forged(clip_dir / (".diagnostics.csv.tmp-" + live + "-1"));
  fs::last_write_time(clip_dir / (".diagnostics.csv.tmp-" + live + "-1"),
                      fs::file_time_type::clock::now() - std::chrono::hours(24 * 365 * 20));
  // Gone: another output's, of a dead run.
  write_forged(out / (".other.mp4.tmp-" + dead + "-0"));
  // Kept: a live run's (written after its process started), names that are not temporaries.
  const std::vector<std::string> kept = {mp4 + live + "-7", mp4 + dead, mp4 + "x-0",
                                         mp4 + dead + "-0-1"};
  for (const auto& name : kept) write_forged(out / name);

  ASSERT_EQ(wait_status(start_render(out, 12)), 0);
  std::vector<std::string> expected_left = kept;
  std::sort(expected_left.begin(), expected_left.end());
  std::vector<std::string> left = temporaries(out);
  std::sort(left.begin(), left.end());
  EXPECT_EQ(left, expected_left);
}

// A run that finds its outputs up to date clears a killed run's leftovers beside them too (the
// MP4's in OUT, the frames folder's in the clip's folder), and still says "up to date".
TEST(Interrupt, AnUpToDateRunRemovesTheTemporariesOfDeadRuns) {
  const fs::path out = fresh_dir("interrupt-up-to-date");
  ASSERT_EQ(wait_status(start_render(out, 12)), 0);
  const auto before = snapshot(out);
  const std::string dead = std::to_string(dead_pid());
  const std::string live = std::to_string(getpid());
  write_forged(out / ("." + kName + ".mp4.tmp-" + dead + "-0"));
  fs::create_directories(out / kName / (".frames.tmp-" + dead + "-1"));
  write_forged(out / kName / (".frames.tmp-" + dead + "-1") / "frame_00000.png");
  write_forged(out / ("." + kName + ".mp4.tmp-" + live + "-3"));  // a live run's: kept
  ASSERT_EQ(temporaries(out).size(), 4u);  // the frames folder and the PNG in it count
  const fs::path manifest = out / kName / "manifest.json";
  const auto written = fs::last_write_time(manifest);
  ASSERT_EQ(wait_status(start_render(out, 12)), 0);
  EXPECT_EQ(fs::last_write_time(manifest), written) << "up to date: nothing made again";
  EXPECT_EQ(temporaries(out), std::vector<std::string>{"." + kName + ".mp4.tmp-" + live + "-3"});
  fs::remove(out / ("." + kName + ".mp4.tmp-" + live + "-3"));
  EXPECT_EQ(snapshot(out), before);
}

// A sweep, a plot and a gallery clear their outputs' leftovers of dead runs too (every
// output goes through the same atomic output).
TEST(Interrupt, SweepPlotAndGalleryRemoveTheTemporariesOfDeadRuns) {
  const fs::path out = fresh_dir("interrupt-other-commands");
  const std::string dead = std::to_string(dead_pid());
  const std::vector<std::string> forged = {".exact-unstable-x-sweep.csv.tmp-" + dead + "-0",
                                           ".exact-unstable-x-sweep.png.tmp-" + dead + "-1",
                                           ".exact-unstable-x-plot.png.tmp-" + dead + "-0",
                                           ".index.html.tmp-" + dead + "-0"};
  for (const auto& name : forged) write_forged(out / name);
  ASSERT_EQ(temporaries(out).size(), forged.size());
  const std::string scene = scene_path("exact-unstable-x");
  for (const std::string& args : {"sweep " + scene +
                                      " --set time.frames=20 --vary time.dt=0.01:0.02:2 --measure "
                                      "energy_drift -o " +
                                      out.string(),
                                  "plot " + scene + " --set time.frames=20 -o " + out.string(),
                                  "gallery " + out.string() + " " + scene}) {
    const CliResult r = run_bookspin(args);
    ASSERT_EQ(r.status, 0) << args << "\n" << r.output;
  }
  EXPECT_EQ(temporaries(out), std::vector<std::string>{});
}

// SIGTERM and SIGINT take back the folders the run made (the -o folder and its parents, the
// clip's folder), and only those: a folder that was there before stays.
TEST(Interrupt, SigtermAndSigintLeaveNoFolderTheyMade) {
  const fs::path root = fresh_dir("interrupt-folders");
  {
    const fs::path out = root / "new" / "deeper";
    const pid_t pid = start_render(out, kLongRun);
    ASSERT_TRUE(wait_for_partial_frames(pid, out / kName, 3));
    kill(pid, SIGTERM);
    EXPECT_EQ(wait_status(pid), 143);
    EXPECT_FALSE(fs::exists(root / "new"));
  }
  {
    const fs::path out = root / "existing";
    fs::create_directories(out);
    const pid_t pid = start_render(out, kLongRun);
    ASSERT_TRUE(wait_for_partial_frames(pid, out / kName, 3));
    kill(pid, SIGINT);
    EXPECT_EQ(wait_status(pid), 130);
    EXPECT_TRUE(fs::is_directory(out));
    EXPECT_TRUE(fs::is_empty(out));
  }
}

// SIGHUP (a closed terminal, a dropped ssh connection) stops a render as SIGTERM does: exit
// 129, its temporaries and the folders it made taken back.
TEST(Interrupt, SighupStopsARenderAndLeavesNothing) {
  const fs::path root = fresh_dir("interrupt-sighup");
  const fs::path out = root / "new";
  const pid_t pid = start_render(out, kLongRun);
  ASSERT_TRUE(wait_for_partial_frames(pid, out / kName, 3));
  kill(pid, SIGHUP);
  EXPECT_EQ(wait_status(pid), 129);
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace bookspin::cli
