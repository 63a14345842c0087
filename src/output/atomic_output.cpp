#include "output/atomic_output.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <system_error>
#include <vector>

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

}  // namespace

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
    fs::create_directories(final_path.parent_path(), ec);
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

void write_text_file(const fs::path& path, std::string_view text) {
  AtomicTextFile file(path);
  file.stream() << text;
  file.commit();
}

}  // namespace bookspin::output
