#pragma once
// Outputs that appear under their final name only when complete.
//
// A writer puts its bytes under a temporary name in the same directory as the
// final one (same filesystem, so the final rename(2) is atomic) and renames it
// into place on commit(). An interrupted or failed run therefore never leaves a
// half-written PNG or MP4 under the name a user or script would look for.
// This protects against process crashes and interrupts, not power loss: there
// is no fsync, because fsyncing every frame would make frame dumps crawl.
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

namespace bookspin::video {

/// A file or directory could not be created, written, renamed or removed.
/// what() is one line: `<action> "<path>": <strerror text>`.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Throws OutputError `<action> "<path>": <reason>`.
[[noreturn]] void throw_output_error(std::string_view action, const std::filesystem::path& path,
                                     std::string_view reason);
/// Throws OutputError `<action> "<path>": strerror(errno_value)`.
[[noreturn]] void throw_output_error(std::string_view action, const std::filesystem::path& path,
                                     int errno_value);

/// A single output file written under `.<name>.tmp-<pid>-<n>` next to the final
/// path. The object only reserves the name; the caller creates and writes the
/// temporary at temp_path(). Not copyable or movable (the registry keys on it).
class AtomicFile {
 public:
  /// Reserves a temporary name next to `final_path` and registers it for
  /// remove_all_temporaries(). Creates nothing on disk; never throws OutputError.
  explicit AtomicFile(std::filesystem::path final_path);
  /// Removes the temporary unless committed. Never throws.
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  const std::filesystem::path& final_path() const { return final_path_; }
  const std::filesystem::path& temp_path() const { return temp_path_; }
  bool committed() const { return committed_; }

  /// Renames the (closed, complete) temporary onto the final path, replacing an
  /// existing file there. Throws OutputError naming the final path if the
  /// rename fails (the temporary is then removed), std::logic_error if called twice.
  void commit();
  /// Removes the temporary if it exists; idempotent, never throws.
  void abandon() noexcept;

 private:
  std::filesystem::path final_path_;
  std::filesystem::path temp_path_;
  bool committed_ = false;
  bool done_ = false;
};

/// A directory of outputs (for example PNG frames) built in `.<dir>.tmp-<pid>-<n>/`
/// and swapped into place on commit(). Until commit() returns, an earlier
/// complete directory under the final name is left untouched.
class AtomicDirectory {
 public:
  /// Creates the temporary directory (and missing parents of the final path).
  /// Throws OutputError naming the final path if it cannot, or if the final
  /// path exists and is not a directory.
  explicit AtomicDirectory(std::filesystem::path final_path);
  /// Removes the temporary tree unless committed. Never throws.
  ~AtomicDirectory();
  AtomicDirectory(const AtomicDirectory&) = delete;
  AtomicDirectory& operator=(const AtomicDirectory&) = delete;

  const std::filesystem::path& final_path() const { return final_path_; }
  /// Where the caller writes the directory's contents.
  const std::filesystem::path& temp_path() const { return temp_path_; }
  bool committed() const { return committed_; }

  /// Puts the new directory under the final name. If an old one exists it is
  /// atomically exchanged (renameat2 RENAME_EXCHANGE) and only then deleted;
  /// where the filesystem lacks exchange, the old one is first renamed aside
  /// and restored if the second rename fails. Throws OutputError naming the
  /// final path; std::logic_error if called twice.
  void commit();
  /// Removes the temporary tree if present; idempotent, never throws.
  void abandon() noexcept;

 private:
  std::filesystem::path final_path_;
  std::filesystem::path temp_path_;
  bool committed_ = false;
  bool done_ = false;
};

/// Removes every temporary file and directory of this process that has not
/// been committed or abandoned yet, and forgets them. Meant for the main thread
/// after a SIGINT/SIGTERM handler has set a flag: it never throws, takes only
/// the registry's short-held mutex, and ignores errors. Do NOT call it from
/// inside a signal handler (it allocates). Returns how many entries it removed.
int remove_all_temporaries() noexcept;

/// Number of live (uncommitted, unabandoned) temporaries; for tests and logs.
int live_temporary_count() noexcept;

}  // namespace bookspin::video
