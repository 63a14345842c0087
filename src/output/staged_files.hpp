#pragma once
// The files of one run of a product of several files (an accuracy report's charts and tables, a
// sweep's CSV and picture, an export's JSON and CSV): each written whole under its temporary
// name, then all put in place together, or none (output::OutputSet; docs/outputs.md, "One run's
// outputs, all or nothing").
#include <filesystem>
#include <memory>
#include <string_view>
#include <vector>

#include "common/non_copyable.hpp"
#include "common/rgba_image.hpp"
#include "output/atomic_output.hpp"

namespace bookspin::output {

class StagedFiles : NonCopyable {
 public:
  /// Writes `text` whole under `path`'s temporary name. Throws OutputError naming `path` (a
  /// full disk: "No space left on device", "File too large"); nothing is put in place then.
  void text(const std::filesystem::path& path, std::string_view text);
  /// Writes `image` as a PNG (png_writer.hpp's encode_png) whole under `path`'s temporary
  /// name. Throws as text() does, and what encode_png throws.
  void png(const std::filesystem::path& path, const RgbaImage& image);
  /// Moves `made`, a complete file written elsewhere in the same filesystem (a clip rendered
  /// into a scratch folder of the run), to `path`'s temporary name, to be put in place with the
  /// others. Throws OutputError naming `path` when it cannot be moved.
  void adopt(const std::filesystem::path& path, const std::filesystem::path& made);
  /// Puts every file written in place, in the order written, or none (OutputSet::commit()).
  /// Throws OutputError naming the file that could not be put in place.
  void commit();

 private:
  std::vector<std::unique_ptr<AtomicFile>> files_;
  OutputSet set_;
};

}  // namespace bookspin::output
