// Bench section: peak resident memory of a short and a long render. Each runs as a child
// process (this same binary), so that its peak is its own and not the bench's.
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/sections.hpp"

namespace bookspin::bench {

namespace {

// Small frames: what grows with the clip's length (if anything) is then not hidden
// behind the size of the frame buffers, and 10,000 frames take a minute or two. The plot
// panel is off: it redraws every curve up to the current frame, so its time (not its
// memory, a few doubles per frame) grows with the clip. Textures are filtered without
// anisotropy (render.anisotropy = 1), as the automatic choice does on llvmpipe: on a GPU
// it would not change what memory is held either.
constexpr int kWidth = 128, kHeight = 72;

/// The `bookspin` program built beside this bench (build/bookspin next to
/// build/bookspin-bench): the memory runs measure the real command in its own process.
std::filesystem::path bookspin_executable() {
  return std::filesystem::read_symlink("/proc/self/exe").parent_path() / "bookspin";
}

std::vector<std::string> render_arguments(const BenchContext& c, int frames) {
  std::vector<std::string> args = {bookspin_executable().string(),
                                   "render",
                                   c.options.scene_path,
                                   "--no-png",
                                   "--frames",
                                   std::to_string(frames),
                                   "--set",
                                   "render.width=" + std::to_string(kWidth),
                                   "--set",
                                   "render.height=" + std::to_string(kHeight),
                                   "--set",
                                   "render.panel=false",
                                   "--set",
                                   "render.anisotropy=1",
                                   "-o",
                                   (c.scratch / ("memory-" + std::to_string(frames))).string()};
  if (c.options.jobs > 0) args.insert(args.end(), {"--jobs", std::to_string(c.options.jobs)});
  return args;
}

/// Runs `args[0]` with `args` (output discarded) and returns its peak resident set size
/// in KiB from wait4(). Throws std::runtime_error if it cannot run or fails.
long peak_rss_kib(const std::vector<std::string>& args) {
  std::vector<char*> argv;  // built before fork: the child may only exec
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("bench: cannot fork");
  if (pid == 0) {
    const int null = open("/dev/null", O_WRONLY);
    if (null >= 0) {
      dup2(null, STDOUT_FILENO);
      dup2(null, STDERR_FILENO);
    }
    execv(argv[0], argv.data());
    _exit(127);
  }
  int status = 0;
  rusage usage{};
  if (wait4(pid, &status, 0, &usage) != pid) throw std::runtime_error("bench: wait4 failed");
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error("bench: the memory render failed: " + args[0] + " " + args[1] + " " +
                             args[2]);
  return usage.ru_maxrss;  // KiB on Linux
}

/// This process's resident set now, in MiB: a fork copies it into the child's count, so it
/// is a floor under every peak measured here.
double own_rss_mib() {
  std::ifstream statm("/proc/self/statm");
  long pages = 0, resident = 0;
  statm >> pages >> resident;
  return static_cast<double>(resident) * static_cast<double>(sysconf(_SC_PAGESIZE)) /
         (1024.0 * 1024.0);
}

/// `bookspin render GIF_SCENE --no-png --format FORMAT [--frames N] -o SCRATCH/gif-FORMAT`.
std::vector<std::string> format_arguments(const BenchContext& c, const std::string& format) {
  std::vector<std::string> args = {bookspin_executable().string(),
                                   "render",
                                   c.options.gif_scene,
                                   "--no-png",
                                   "--format",
                                   format,
                                   "-o",
                                   (c.scratch / ("gif-memory-" + format)).string()};
  if (c.options.gif_frames > 0)
    args.insert(args.end(), {"--frames", std::to_string(c.options.gif_frames)});
  if (c.options.jobs > 0) args.insert(args.end(), {"--jobs", std::to_string(c.options.jobs)});
  return args;
}

}  // namespace

// The scene as `make figures` renders it (its own size and length unless --gif-frames): the
// GIF sink's memory must not grow with the clip, so it is measured on a long one.
void bench_gif_memory(const BenchContext& c) {
  const std::string what =
      std::filesystem::path(c.options.gif_scene).stem().string() +
      (c.options.gif_frames > 0 ? ", " + std::to_string(c.options.gif_frames) + " frames"
                                : ", the scene's frames");
  const std::string note = "child process, wait4 ru_maxrss; --no-png";
  const double mp4 = peak_rss_kib(format_arguments(c, "mp4")) / 1024.0;
  c.report->add({"memory", "peak RSS, render --format mp4, " + what, mp4, "MiB", note});
  const double gif = peak_rss_kib(format_arguments(c, "gif")) / 1024.0;
  c.report->add({"memory", "peak RSS, render --format gif, " + what, gif, "MiB", note});
  c.report->add({"memory", "peak RSS gif / mp4", gif / mp4, "x", "the two rows above"});
  std::filesystem::remove_all(c.scratch / "gif-memory-mp4");
  std::filesystem::remove_all(c.scratch / "gif-memory-gif");
}

void bench_memory(const BenchContext& c) {
  const int short_frames = 100, long_frames = c.options.memory_frames;
  const std::string size = std::to_string(kWidth) + "x" + std::to_string(kHeight);
  char note[96];
  std::snprintf(note, sizeof note, "child process, wait4 ru_maxrss (bench itself %.0f MiB at fork)",
                own_rss_mib());
  const double short_mib = peak_rss_kib(render_arguments(c, short_frames)) / 1024.0;
  c.report->add({"memory",
                 "peak RSS, render --no-png " + std::to_string(short_frames) + " frames " + size,
                 short_mib, "MiB", note});
  const double long_mib = peak_rss_kib(render_arguments(c, long_frames)) / 1024.0;
  c.report->add({"memory",
                 "peak RSS, render --no-png " + std::to_string(long_frames) + " frames " + size,
                 long_mib, "MiB", note});
  c.report->add(
      {"memory",
       "peak RSS " + std::to_string(long_frames) + " / " + std::to_string(short_frames) + " frames",
       long_mib / short_mib, "x", "what grows with the clip's length"});
}

}  // namespace bookspin::bench
