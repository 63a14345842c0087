#pragma once
// Runs the built bookspin and signals it at a named stage of its run (the command line's test
// hooks, src/cli/interrupt.hpp): what the interrupt and signal tests of tests/cli share, with
// the snapshot of an output folder they compare before and after.
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli_runner.hpp"

namespace bookspin::test {

/// The exit status of the child `pid` (waits for it), or 128 + signal if a signal ended it.
inline int wait_status(pid_t pid) {
  int raw = 0;
  waitpid(pid, &raw, 0);
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
}

/// Every entry under `dir` (recursively) with the content of each file ("<dir>" for a folder).
inline std::map<std::string, std::string> snapshot(const std::filesystem::path& dir) {
  std::map<std::string, std::string> out;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir)) {
    out[std::filesystem::relative(e.path(), dir).string()] =
        e.is_regular_file() ? read_file(e.path()) : "<dir>";
  }
  return out;
}

/// The temporaries under `dir` (recursively): names holding ".tmp-" (output::AtomicOutput's).
inline std::vector<std::string> temporaries(const std::filesystem::path& dir) {
  std::vector<std::string> found;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir)) {
    const std::string name = std::filesystem::relative(e.path(), dir).string();
    if (name.find(".tmp-") != std::string::npos) found.push_back(name);
  }
  return found;
}

/// The CPU seconds (user + system, all its threads) the running process `pid` has used so far,
/// from /proc/<pid>/stat (utime and stime, the 14th and 15th fields, in clock ticks); -1 where
/// it cannot be read.
inline double cpu_seconds_so_far(pid_t pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(in, line)) return -1.0;
  // Fields after the command name, which may hold spaces, in parentheses: state is field 3.
  std::istringstream rest(line.substr(line.rfind(')') + 2));
  std::string field;
  long long utime = -1, stime = -1;
  for (int n = 3; n <= 15 && rest >> field; ++n) {
    if (n == 14) utime = std::stoll(field);
    if (n == 15) stime = std::stoll(field);
  }
  if (utime < 0 || stime < 0) return -1.0;
  return static_cast<double>(utime + stime) / static_cast<double>(sysconf(_SC_CLK_TCK));
}

/// How a run signalled at a stage ended.
struct SignalledRun {
  bool reached = false;     ///< the stage's line came before the program ended
  int status = -1;          ///< exit status, or 128 + signal
  double to_exit_s = -1.0;  ///< seconds from the signal to the program's exit (reached only)
  /// CPU seconds the program used from the signal to its exit (reached only): what its polls
  /// bound whatever the machine's load, where to_exit_s grows with the load.
  double cpu_to_exit_s = -1.0;
  std::string err;  ///< its standard error
};

/// Starts bookspin with `args` (one word each; stdout to /dev/null, stderr read here) and the
/// environment variable `hook` ("BOOKSPIN_TEST_REPORT_STAGES" or "BOOKSPIN_TEST_HOLD_AT") set to
/// `stage`; on reading the line "bookspin: stage: <stage>" sends `signal` and waits for the
/// exit. A run that has not reached the stage within five minutes, or not ended half a minute
/// after the signal, is killed (status 137).
inline SignalledRun signal_at_stage(const std::vector<std::string>& args, const std::string& hook,
                                    const std::string& stage, int signal) {
  using Clock = std::chrono::steady_clock;
  int fds[2];
  SignalledRun run;
  if (pipe(fds) != 0) return run;
  const pid_t pid = fork();
  if (pid == 0) {
    setenv(hook.c_str(), stage.c_str(), 1);
    dup2(fds[1], STDERR_FILENO);
    const int null = open("/dev/null", O_WRONLY);
    dup2(null, STDOUT_FILENO);
    close(fds[0]);
    close(fds[1]);
    std::vector<std::string> words = args;
    std::vector<char*> argv{const_cast<char*>(BOOKSPIN_EXE)};
    for (auto& w : words) argv.push_back(w.data());
    argv.push_back(nullptr);
    execv(BOOKSPIN_EXE, argv.data());
    _exit(127);
  }
  close(fds[1]);
  const std::string marker = "bookspin: stage: " + stage + "\n";
  const auto deadline = Clock::now() + std::chrono::minutes(5);
  Clock::time_point signalled;
  double cpu_at_signal = -1.0;
  char buffer[4096];
  for (;;) {
    pollfd p{fds[0], POLLIN, 0};
    const int ready = poll(&p, 1, 100);
    if (ready > 0) {
      const ssize_t n = read(fds[0], buffer, sizeof buffer);
      if (n <= 0) break;  // the program closed stderr: it is ending
      run.err.append(buffer, static_cast<std::size_t>(n));
    }
    if (!run.reached && run.err.find(marker) != std::string::npos) {
      run.reached = true;
      signalled = Clock::now();
      cpu_at_signal = cpu_seconds_so_far(pid);
      kill(pid, signal);
    }
    // Not there within five minutes, or still running half a minute after the signal.
    if (Clock::now() > (run.reached ? signalled + std::chrono::seconds(30) : deadline)) {
      kill(pid, SIGKILL);
      break;
    }
  }
  close(fds[0]);
  int raw = 0;
  rusage usage{};
  wait4(pid, &raw, 0, &usage);
  run.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
  if (run.reached) {
    run.to_exit_s = std::chrono::duration<double>(Clock::now() - signalled).count();
    const auto seconds = [](const timeval& v) { return v.tv_sec + v.tv_usec * 1e-6; };
    if (cpu_at_signal >= 0.0)
      run.cpu_to_exit_s = seconds(usage.ru_utime) + seconds(usage.ru_stime) - cpu_at_signal;
  }
  return run;
}

/// How a run signalled after a delay ended.
struct TimedRun {
  bool ended_first = false;  ///< the program ended before the delay was up (no signal sent)
  int status = -1;           ///< exit status, or 128 + signal
  std::string err;           ///< its standard error
};

/// Whether a file under `dir` (recursively, temporaries aside) was put there at or after
/// `since`: a run has begun to put its outputs in place (an output is written under a
/// temporary name and renamed, keeping the time it was written).
inline bool outputs_placed_since(const std::filesystem::path& dir,
                                 std::filesystem::file_time_type since) {
  std::error_code ec;
  if (!std::filesystem::exists(dir, ec)) return false;
  for (auto it = std::filesystem::recursive_directory_iterator(dir, ec);
       !ec && it != std::filesystem::recursive_directory_iterator(); it.increment(ec)) {
    const std::string name = it->path().lexically_relative(dir).string();
    if (name.find(".tmp-") != std::string::npos || !it->is_regular_file(ec)) continue;
    if (it->last_write_time(ec) >= since) return true;
  }
  return false;
}

/// Starts bookspin with `args` (stdout to /dev/null, stderr read here), sends `signal`
/// `delay_s` seconds after the start (unless it has ended by then) and waits for the exit; a run
/// still going half a minute after the signal is killed (status 137). With `out`, a run that
/// has already begun to put its outputs in place there when the moment comes (its work done:
/// the stop contract's moments are before it) is not signalled and counts as ended first.
inline TimedRun signal_after(const std::vector<std::string>& args, double delay_s, int signal,
                             const std::filesystem::path& out = {}) {
  using Clock = std::chrono::steady_clock;
  int fds[2];
  TimedRun run;
  if (pipe(fds) != 0) return run;
  const auto started = std::filesystem::file_time_type::clock::now();
  const auto start = Clock::now();
  const pid_t pid = fork();
  if (pid == 0) {
    dup2(fds[1], STDERR_FILENO);
    const int null = open("/dev/null", O_WRONLY);
    dup2(null, STDOUT_FILENO);
    close(fds[0]);
    close(fds[1]);
    std::vector<std::string> words = args;
    std::vector<char*> argv{const_cast<char*>(BOOKSPIN_EXE)};
    for (auto& w : words) argv.push_back(w.data());
    argv.push_back(nullptr);
    execv(BOOKSPIN_EXE, argv.data());
    _exit(127);
  }
  close(fds[1]);
  const auto when =
      start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(delay_s));
  bool sent = false, placed = false, open_pipe = true;
  char buffer[4096];
  for (;;) {
    if (open_pipe) {
      pollfd p{fds[0], POLLIN, 0};
      if (poll(&p, 1, 2) > 0) {
        const ssize_t n = read(fds[0], buffer, sizeof buffer);
        if (n <= 0) {
          open_pipe = false;
        } else {
          run.err.append(buffer, static_cast<std::size_t>(n));
        }
      }
    } else {
      usleep(2000);
    }
    int raw = 0;
    if (waitpid(pid, &raw, WNOHANG) == pid) {
      run.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
      run.ended_first = !sent;
      break;
    }
    if (!sent && !placed && Clock::now() >= when) {
      if (!out.empty() && outputs_placed_since(out, started)) {
        placed = true;  // waited for without a signal: ended first
      } else {
        kill(pid, signal);
        sent = true;
      }
    }
    if (sent && Clock::now() > when + std::chrono::seconds(30)) {
      kill(pid, SIGKILL);
      run.status = wait_status(pid);
      break;
    }
  }
  // What is left of its standard error.
  for (ssize_t n; open_pipe && (n = read(fds[0], buffer, sizeof buffer)) > 0;)
    run.err.append(buffer, static_cast<std::size_t>(n));
  close(fds[0]);
  return run;
}

}  // namespace bookspin::test
