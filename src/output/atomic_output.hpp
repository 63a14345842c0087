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
#include <fstream>
#include <ostream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "common/errors.hpp"

namespace bookspin::output {

/// One output, a file or a directory, built under the hidden temporary name
/// `.<name>.tmp-<pid>-<n>` next to its final path and put in place by commit(). Without
/// commit() (an error, an interrupt) the destructor removes the temporary, and an earlier
/// complete output under the final name is left untouched. Not copyable or movable.
class AtomicOutput {
 public:
  enum class Kind { file, directory };

  /// Reserves the temporary name. A file's temporary is created by the caller at
  /// temp_path(); a directory's is created here, with the final path's missing parents.
  /// Throws OutputError naming the final path if the directory cannot be made, or if the
  /// final path exists and is not a directory.
  AtomicOutput(std::filesystem::path final_path, Kind kind);
  /// Removes the temporary unless committed. Never throws.
  ~AtomicOutput();
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;

  const std::filesystem::path& final_path() const { return final_path_; }
  /// Where the caller writes the output (the file, or the directory's contents).
  const std::filesystem::path& temp_path() const { return temp_path_; }
  bool committed() const { return committed_; }

  /// Puts the complete temporary under the final name, replacing what is there: a file by
  /// rename(2); a directory by an atomic exchange (renameat2 RENAME_EXCHANGE) and only then
  /// deleting the old one, or where the filesystem lacks exchange by moving the old one
  /// aside and back if the second rename fails. Throws OutputError naming the final path
  /// (the temporary is then removed); std::logic_error if called twice.
  void commit();
  /// Removes the temporary if it exists; idempotent, never throws.
  void abandon() noexcept;

 private:
  friend class OutputSet;
  std::filesystem::path final_path_;
  std::filesystem::path temp_path_;
  Kind kind_;
  bool committed_ = false;
  bool done_ = false;
};

/// The outputs of one run, put in place together or not at all (docs/outputs.md, "One run's
/// outputs, all or nothing"). Each output is written complete under its temporary name and
/// added; commit() then puts every one in place in the order added, keeping each earlier
/// output under the final name aside (a hard link, or for a directory the exchanged
/// temporary) until all are in place. If any cannot be put in place, the ones already put in
/// place are undone (the earlier outputs back under their names, byte for byte; where there
/// was none, the new one removed), every temporary is removed and the error goes on: a
/// failed commit leaves the folder as it was. Not copyable; the outputs added must outlive
/// commit(). Without commit() (an error or an interrupt before it) nothing is put in place:
/// the outputs' own destructors remove their temporaries.
class OutputSet {
 public:
  OutputSet() = default;
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;

  /// Adds `output`, whose temporary is complete (written and closed). Throws std::logic_error
  /// if it was committed or abandoned already, or after commit().
  void add(AtomicOutput& output);
  /// The outputs added so far.
  std::size_t size() const { return outputs_.size(); }
  /// Puts every output in place, or none. Throws OutputError naming the output that could not
  /// be put in place (after undoing the others); std::logic_error if called twice.
  void commit();

 private:
  std::vector<AtomicOutput*> outputs_;
  bool done_ = false;
};

/// An output file (MP4, PNG): the caller opens and writes temp_path().
class AtomicFile : public AtomicOutput {
 public:
  explicit AtomicFile(std::filesystem::path final_path)
      : AtomicOutput(std::move(final_path), Kind::file) {}
};

/// An output directory (PNG frames): the caller writes into temp_path().
class AtomicDirectory : public AtomicOutput {
 public:
  explicit AtomicDirectory(std::filesystem::path final_path)
      : AtomicOutput(std::move(final_path), Kind::directory) {}
};

/// A text output written through a stream (CSV, HTML): the stream is open on the temporary
/// from construction; commit() closes it, checks that every write succeeded and puts the
/// file in place. Throws OutputError naming the final path and the OS error.
class AtomicTextFile {
 public:
  explicit AtomicTextFile(const std::filesystem::path& final_path);
  std::ostream& stream() { return stream_; }
  /// Closes the stream and checks that every write succeeded (idempotent).
  void close();
  /// close(), then puts the file in place.
  void commit();
  /// close(), then adds the file to `set`, which puts it in place with the run's other
  /// outputs.
  void finish(OutputSet& set);

 private:
  AtomicFile file_;
  std::ofstream stream_;
};

/// Writes `text` to `path` through an AtomicTextFile. Throws OutputError.
void write_text_file(const std::filesystem::path& path, std::string_view text);

/// Removes the temporaries `.<name>.tmp-<pid>-<n>` (and `.old-`) in the folder of `final_path`
/// whose run is gone (killed with SIGKILL, or a crash; a process with that pid that started
/// after the temporary was written is another one), once per folder and process. Every
/// AtomicOutput does this in its folder; an up-to-date run (cache::make_cached) does it beside
/// the outputs it keeps. Errors are ignored (tidying: a temporary left harms nothing).
void remove_dead_temporaries(const std::filesystem::path& final_path) noexcept;

}  // namespace bookspin::output
