#include "output/atomic_output.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include "common/text_file.hpp"
#include "output/output_dir.hpp"

namespace bookspin::output {
namespace fs = std::filesystem;

namespace {

// Errors are ignored on purpose: this runs on abandon and cleanup paths, where
// the only useful thing left to do is try.
void remove_quietly(const fs::path& path, bool is_directory) noexcept {
  std::error_code ignored;
  if (is_directory) {
    fs::remove_all(path, ignored);
  } else {
    fs::remove(path, ignored);
  }
}

// ---- Naming ---------------------------------------------------------------------

// A trailing slash ("out/frames/") names the directory itself.
fs::path normalise(fs::path path) {
  if (!path.has_filename() && path.has_parent_path()) path = path.parent_path();
  return path;
}

// `.<name>.<tag>-<pid>-<n>` beside `final_path`. The counter keeps two
// outputs of one process apart; the pid keeps concurrent processes apart.
fs::path sibling_name(const fs::path& final_path, const char* tag) {
  static std::atomic<unsigned> counter{0};
  // Built by appending: GCC 12 flags `"." + std::string` with a bogus -Wrestrict.
  std::string name(".");
  name.append(final_path.filename().string()).append(".").append(tag).append("-");
  name.append(std::to_string(::getpid())).append("-").append(std::to_string(counter++));
  return final_path.parent_path() / name;
}

bool exists_no_follow(const fs::path& path) {
  std::error_code ec;
  return fs::exists(fs::symlink_status(path, ec));
}

// ---- Temporaries of dead runs ------------------------------------------------------

// The pid in `.<name>.tmp-<pid>-<n>` (any name), if `entry` is such a temporary at all.
std::optional<pid_t> temporary_owner(const std::string& entry) {
  constexpr std::string_view kTag = ".tmp-";
  const auto tag = entry.rfind(kTag);
  if (entry.size() < 2 || entry.front() != '.' || tag == std::string::npos || tag < 2)
    return std::nullopt;
  const char* p = entry.data() + tag + kTag.size();
  const char* end = entry.data() + entry.size();
  long pid = 0;
  unsigned long n = 0;
  auto [after_pid, pid_ec] = std::from_chars(p, end, pid);
  if (pid_ec != std::errc() || after_pid == p || pid <= 0 || after_pid == end || *after_pid != '-')
    return std::nullopt;
  auto [after_n, n_ec] = std::from_chars(after_pid + 1, end, n);
  if (n_ec != std::errc() || after_n == after_pid + 1 || after_n != end) return std::nullopt;
  return static_cast<pid_t>(pid);
}

double seconds(const timespec& t) { return static_cast<double>(t.tv_sec) + 1e-9 * t.tv_nsec; }

// When the process now holding `pid` started (seconds since the epoch, to a clock tick), from
// /proc/<pid>/stat field 22 (clock ticks after boot); nullopt where that cannot be read.
std::optional<double> process_start(pid_t pid) {
  const std::string stat =
      try_read_text_file("/proc/" + std::to_string(pid) + "/stat").value_or(std::string());
  const auto close = stat.rfind(')');  // the command name may hold spaces and parentheses
  if (close == std::string::npos) return std::nullopt;
  std::istringstream fields(stat.substr(close + 1));
  std::string field;
  for (int i = 3; i <= 22; ++i) fields >> field;  // fields 3 … 22 follow the name
  if (!fields) return std::nullopt;
  const double ticks = std::strtod(field.c_str(), nullptr);
  const long hz = ::sysconf(_SC_CLK_TCK);
  timespec now_real{}, now_boot{};
  if (hz <= 0 || ::clock_gettime(CLOCK_REALTIME, &now_real) != 0 ||
      ::clock_gettime(CLOCK_BOOTTIME, &now_boot) != 0)
    return std::nullopt;
  return seconds(now_real) - (seconds(now_boot) - ticks / static_cast<double>(hz));
}

// A temporary's run is gone when no process has its pid, or when the process that has it now
// started after the temporary was last written (the pid was reused). The second test keeps a
// margin of a second for the clocks, in favour of keeping: a live run's output is never taken.
bool owner_gone(pid_t pid, const fs::path& temporary) {
  if (::kill(pid, 0) != 0 && errno == ESRCH) return true;
  struct stat st {};
  if (::lstat(temporary.c_str(), &st) != 0) return false;
  const std::optional<double> started = process_start(pid);
  return started && seconds(st.st_mtim) < *started - 1.0;
}

}  // namespace

// Removes the temporaries `.<name>.tmp-<pid>-<n>` in the folder of `final_path` that runs now
// gone left behind (killed with SIGKILL, or a crash), so that a later run writing there clears
// them. Each folder is looked through once per process (a frame dump makes one output per
// frame in one folder). Errors are ignored: this is tidying, and a temporary it cannot remove
// harms nothing.
void remove_dead_temporaries(const fs::path& final_path) noexcept {
  try {
    const fs::path dir = final_path.has_parent_path() ? final_path.parent_path() : fs::path(".");
    static std::mutex mutex;
    static std::set<fs::path> looked_through;
    {
      std::error_code ec;
      if (!fs::is_directory(dir, ec)) return;  // no folder yet: nothing to clear
      // As spelled (two spellings of one folder cost a second look, nothing more).
      const fs::path key = fs::absolute(dir, ec).lexically_normal();
      if (ec) return;
      const std::lock_guard lock(mutex);
      if (!looked_through.insert(key).second) return;
    }
    std::error_code ec;
    fs::directory_iterator it(dir, ec);
    if (ec) return;
    for (const auto& entry : it) {
      const std::optional<pid_t> pid = temporary_owner(entry.path().filename().string());
      if (!pid || !owner_gone(*pid, entry.path())) continue;
      std::error_code type_ec;
      remove_quietly(entry.path(), fs::is_directory(fs::symlink_status(entry.path(), type_ec)));
    }
  } catch (...) {
  }
}

namespace {

// Fallback for filesystems without RENAME_EXCHANGE: move the old directory
// aside, move the new one in, and put the old one back if that fails.
void replace_via_aside(const fs::path& temp, const fs::path& final_path) {
  const fs::path aside = sibling_name(final_path, "old");
  if (std::rename(final_path.c_str(), aside.c_str()) != 0) {
    throw_output_error("cannot move old output directory aside", final_path, errno);
  }
  if (std::rename(temp.c_str(), final_path.c_str()) != 0) {
    const int err = errno;
    std::rename(aside.c_str(), final_path.c_str());
    throw_output_error("cannot rename output directory into place", final_path, err);
  }
  remove_quietly(aside, true);
}

void replace_directory(const fs::path& temp, const fs::path& final_path) {
  if (!exists_no_follow(final_path)) {
    if (std::rename(temp.c_str(), final_path.c_str()) != 0) {
      throw_output_error("cannot rename output directory into place", final_path, errno);
    }
    return;
  }
  // Exchange keeps a complete directory under the final name at every instant.
  if (::renameat2(AT_FDCWD, temp.c_str(), AT_FDCWD, final_path.c_str(), RENAME_EXCHANGE) == 0) {
    remove_quietly(temp, true);  // now holds the old output
    return;
  }
  if (errno != EINVAL && errno != ENOSYS && errno != ENOTSUP) {
    throw_output_error("cannot exchange output directory into place", final_path, errno);
  }
  replace_via_aside(temp, final_path);
}

}  // namespace

// ---- AtomicOutput ----------------------------------------------------------------

namespace {

void make_temporary_directory(const fs::path& final_path, const fs::path& temp_path) {
  std::error_code ec;
  const auto status = fs::symlink_status(final_path, ec);
  if (fs::exists(status) && !fs::is_directory(status)) {
    throw_output_error("cannot replace non-directory with output directory", final_path,
                       std::strerror(ENOTDIR));
  }
  if (final_path.has_parent_path()) {
    make_directories(final_path.parent_path(), ec);
    if (ec)
      throw_output_error("cannot create parent of output directory", final_path, ec.message());
  }
  // A leftover with our exact name can only come from a dead process whose pid we reuse,
  // so it is safe to clear.
  remove_quietly(temp_path, true);
  if (::mkdir(temp_path.c_str(), 0777) != 0)
    throw_output_error("cannot create output directory", final_path, errno);
}

void replace_file(const fs::path& temp, const fs::path& final_path) {
  if (std::rename(temp.c_str(), final_path.c_str()) != 0)
    throw_output_error("cannot rename temporary into place as", final_path, errno);
}

}  // namespace

AtomicOutput::AtomicOutput(fs::path final_path, Kind kind)
    : final_path_(normalise(std::move(final_path))),
      temp_path_(sibling_name(final_path_, "tmp")),
      kind_(kind) {
  remove_dead_temporaries(final_path_);
  if (kind_ == Kind::directory) make_temporary_directory(final_path_, temp_path_);
}

AtomicOutput::~AtomicOutput() {
  if (!done_) abandon();
}

void AtomicOutput::commit() {
  if (done_) throw std::logic_error("AtomicOutput::commit called after commit or abandon");
  try {
    if (kind_ == Kind::directory) {
      replace_directory(temp_path_, final_path_);
    } else {
      replace_file(temp_path_, final_path_);
    }
  } catch (...) {
    abandon();
    throw;
  }
  committed_ = true;
  done_ = true;
}

void AtomicOutput::abandon() noexcept {
  if (done_) return;
  remove_quietly(temp_path_, kind_ == Kind::directory);
  done_ = true;
}

// ---- OutputSet -----------------------------------------------------------------------

namespace {

/// One output of a set put in place: where the earlier output under its final name is kept
/// until the whole set is in place (empty: there was none).
struct Placed {
  AtomicOutput* output;
  fs::path aside;
  bool exchanged = false;  ///< a directory swapped with its temporary (renameat2)
};

bool is_directory_no_follow(const fs::path& path) {
  std::error_code ec;
  return fs::is_directory(fs::symlink_status(path, ec));
}

/// Puts the complete temporary `temp` of `final_path` in place, keeping what was there aside
/// (returned in Placed::aside). Throws OutputError naming `final_path`; `final_path` is then
/// as it was.
Placed put_in_place(AtomicOutput& output, const fs::path& temp, bool directory) {
  const fs::path& final_path = output.final_path();
  Placed placed{&output, {}, false};
  if (!exists_no_follow(final_path)) {
    if (std::rename(temp.c_str(), final_path.c_str()) != 0)
      throw_output_error("cannot rename temporary into place as", final_path, errno);
    return placed;
  }
  if (is_directory_no_follow(final_path) != directory) {
    throw_output_error(directory ? "cannot replace non-directory with output directory"
                                 : "cannot replace a directory with output file",
                       final_path, std::strerror(directory ? ENOTDIR : EISDIR));
  }
  if (directory &&
      ::renameat2(AT_FDCWD, temp.c_str(), AT_FDCWD, final_path.c_str(), RENAME_EXCHANGE) == 0) {
    placed.aside = temp;  // now holds the earlier directory
    placed.exchanged = true;
    return placed;
  }
  placed.aside = sibling_name(final_path, "tmp");
  // A file: a second name for the earlier one, so that the final name never goes missing.
  const bool linked = !directory && ::link(final_path.c_str(), placed.aside.c_str()) == 0;
  if (!linked && std::rename(final_path.c_str(), placed.aside.c_str()) != 0)
    throw_output_error("cannot move the earlier output aside", final_path, errno);
  if (std::rename(temp.c_str(), final_path.c_str()) != 0) {
    const int err = errno;
    if (linked) {
      remove_quietly(placed.aside, false);
    } else {
      std::rename(placed.aside.c_str(), final_path.c_str());
    }
    throw_output_error("cannot rename temporary into place as", final_path, err);
  }
  return placed;
}

/// Undoes put_in_place(): the earlier output back under its name, or the new one removed.
void take_back(const Placed& placed, bool directory) noexcept {
  const fs::path& final_path = placed.output->final_path();
  if (placed.aside.empty()) {
    remove_quietly(final_path, directory);
  } else if (placed.exchanged) {
    if (::renameat2(AT_FDCWD, placed.aside.c_str(), AT_FDCWD, final_path.c_str(),
                    RENAME_EXCHANGE) == 0)
      remove_quietly(placed.aside, true);  // now holds the new one
  } else {
    if (directory) remove_quietly(final_path, true);
    std::rename(placed.aside.c_str(), final_path.c_str());
  }
}

}  // namespace

void OutputSet::add(AtomicOutput& output) {
  if (done_ || output.done_) throw std::logic_error("OutputSet::add of a finished output");
  outputs_.push_back(&output);
}

void OutputSet::commit() {
  if (done_) throw std::logic_error("OutputSet::commit called twice");
  done_ = true;
  std::vector<Placed> placed;
  try {
    for (AtomicOutput* output : outputs_) {
      placed.push_back(put_in_place(*output, output->temp_path_,
                                    output->kind_ == AtomicOutput::Kind::directory));
    }
  } catch (...) {
    for (auto it = placed.rbegin(); it != placed.rend(); ++it)
      take_back(*it, it->output->kind_ == AtomicOutput::Kind::directory);
    for (AtomicOutput* output : outputs_) output->abandon();
    throw;
  }
  for (const Placed& p : placed) {
    if (!p.aside.empty()) remove_quietly(p.aside, p.output->kind_ == AtomicOutput::Kind::directory);
    p.output->committed_ = true;
    p.output->done_ = true;
  }
}

// ---- Text files ----------------------------------------------------------------------

AtomicTextFile::AtomicTextFile(const fs::path& final_path) : file_(final_path) {
  stream_.open(file_.temp_path(), std::ios::binary);
  if (!stream_) throw_output_error("cannot create", file_.final_path(), errno);
}

void AtomicTextFile::close() {
  if (!stream_.is_open()) return;
  stream_.close();
  if (!stream_) throw_output_error("cannot write", file_.final_path(), errno);
}

void AtomicTextFile::commit() {
  close();
  file_.commit();
}

void AtomicTextFile::finish(OutputSet& set) {
  close();
  set.add(file_);
}

void write_text_file(const fs::path& path, std::string_view text) {
  AtomicTextFile file(path);
  file.stream() << text;
  file.commit();
}

}  // namespace bookspin::output
