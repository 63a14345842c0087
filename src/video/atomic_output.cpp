#include "video/atomic_output.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <string>
#include <system_error>
#include <vector>

namespace bookspin::video {
namespace fs = std::filesystem;

void throw_output_error(std::string_view action, const fs::path& path, std::string_view reason) {
  std::string message(action);
  message += " \"" + path.string() + "\": ";
  message += reason;
  throw OutputError(message);
}

void throw_output_error(std::string_view action, const fs::path& path, int errno_value) {
  throw_output_error(action, path, std::strerror(errno_value));
}

namespace {

// ---- Registry of live temporaries --------------------------------------------

struct Temporary {
  std::string path;
  bool is_directory;
};

std::mutex registry_mutex;
std::vector<Temporary>& registry() {
  static std::vector<Temporary> entries;  // never destroyed before static AtomicFiles
  return entries;
}

void register_temporary(const fs::path& path, bool is_directory) {
  std::lock_guard lock(registry_mutex);
  registry().push_back({path.string(), is_directory});
}

void unregister_temporary(const fs::path& path) noexcept {
  std::lock_guard lock(registry_mutex);
  auto& entries = registry();
  const std::string key = path.string();
  for (auto it = entries.begin(); it != entries.end(); ++it) {
    if (it->path == key) {
      entries.erase(it);
      return;
    }
  }
}

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

}  // namespace

// ---- AtomicFile -----------------------------------------------------------------

AtomicFile::AtomicFile(fs::path final_path)
    : final_path_(normalise(std::move(final_path))), temp_path_(sibling_name(final_path_, "tmp")) {
  register_temporary(temp_path_, false);
}

AtomicFile::~AtomicFile() {
  if (!done_) abandon();
}

void AtomicFile::commit() {
  if (done_) throw std::logic_error("AtomicFile::commit called after commit or abandon");
  if (std::rename(temp_path_.c_str(), final_path_.c_str()) != 0) {
    const int err = errno;
    abandon();
    throw_output_error("cannot rename temporary into place as", final_path_, err);
  }
  unregister_temporary(temp_path_);
  committed_ = true;
  done_ = true;
}

void AtomicFile::abandon() noexcept {
  if (done_) return;
  remove_quietly(temp_path_, false);
  unregister_temporary(temp_path_);
  done_ = true;
}

// ---- AtomicDirectory ------------------------------------------------------------

AtomicDirectory::AtomicDirectory(fs::path final_path)
    : final_path_(normalise(std::move(final_path))), temp_path_(sibling_name(final_path_, "tmp")) {
  std::error_code ec;
  const auto status = fs::symlink_status(final_path_, ec);
  if (fs::exists(status) && !fs::is_directory(status)) {
    throw_output_error("cannot replace non-directory with output directory", final_path_,
                       std::strerror(ENOTDIR));
  }
  if (final_path_.has_parent_path()) {
    fs::create_directories(final_path_.parent_path(), ec);
    if (ec)
      throw_output_error("cannot create parent of output directory", final_path_, ec.message());
  }
  // A leftover with our exact name can only come from a dead process whose
  // pid we reuse, so it is safe to clear.
  remove_quietly(temp_path_, true);
  register_temporary(temp_path_, true);
  if (::mkdir(temp_path_.c_str(), 0777) != 0) {
    const int err = errno;
    unregister_temporary(temp_path_);
    throw_output_error("cannot create output directory", final_path_, err);
  }
}

AtomicDirectory::~AtomicDirectory() {
  if (!done_) abandon();
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

void AtomicDirectory::commit() {
  if (done_) throw std::logic_error("AtomicDirectory::commit called after commit or abandon");
  try {
    replace_directory(temp_path_, final_path_);
  } catch (...) {
    abandon();
    throw;
  }
  unregister_temporary(temp_path_);
  committed_ = true;
  done_ = true;
}

void AtomicDirectory::abandon() noexcept {
  if (done_) return;
  remove_quietly(temp_path_, true);
  unregister_temporary(temp_path_);
  done_ = true;
}

// ---- Process-wide cleanup --------------------------------------------------------

int remove_all_temporaries() noexcept {
  std::lock_guard lock(registry_mutex);
  auto& entries = registry();
  const int count = static_cast<int>(entries.size());
  for (const auto& entry : entries) {
    // unlink(2) for plain files: no allocation, async-signal-safe.
    if (entry.is_directory) {
      remove_quietly(entry.path, true);
    } else {
      ::unlink(entry.path.c_str());
    }
  }
  entries.clear();
  return count;
}

int live_temporary_count() noexcept {
  std::lock_guard lock(registry_mutex);
  return static_cast<int>(registry().size());
}

}  // namespace bookspin::video
