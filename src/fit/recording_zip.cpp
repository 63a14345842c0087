#include "fit/recording_zip.hpp"

#include <unzip.h>

#include <cstdint>
#include <memory>
#include <vector>

#include "common/errors.hpp"
#include "common/text_file.hpp"

namespace bookspin::fit {
namespace {

struct ZipCloser {
  void operator()(void* zip) const { unzClose(zip); }
};

/// The most bytes a zip entry may inflate to (a recording of hours at 500 Hz is under 100 MB):
/// an entry that says it is larger, or inflates beyond it, is refused before it fills memory.
constexpr std::uint64_t kMaxZipEntryBytes = std::uint64_t{256} << 20;

}  // namespace

std::optional<std::string> zip_entry(const std::filesystem::path& path, std::string_view suffix) {
  std::error_code error;
  if (std::filesystem::file_size(path, error) == 0 && !error)
    throw InputError(path.string() + ": an empty file, not a zip file");
  const std::unique_ptr<void, ZipCloser> zip(unzOpen64(path.string().c_str()));
  if (!zip) {
    // A zip of no file is its end record alone ("PK\5\6"), which minizip may not open.
    const std::optional<std::string> head =
        std::filesystem::file_size(path, error) == 22 ? try_read_text_file(path) : std::nullopt;
    if (head && head->compare(0, 4, "PK\x05\x06") == 0)
      throw InputError(path.string() + ": an empty zip (no file in it)");
    throw InputError(path.string() + ": not a zip file");
  }
  unz_global_info64 global{};
  if (unzGetGlobalInfo64(zip.get(), &global) != UNZ_OK)
    throw InputError(path.string() + ": a damaged zip file");
  if (global.number_entry == 0) throw InputError(path.string() + ": an empty zip (no file in it)");
  std::vector<std::string> found;
  unz64_file_pos found_at{};
  std::uint64_t found_size = 0;
  for (int status = unzGoToFirstFile(zip.get()); status == UNZ_OK;
       status = unzGoToNextFile(zip.get())) {
    unz_file_info64 info{};
    char name[1024];
    if (unzGetCurrentFileInfo64(zip.get(), &info, name, sizeof name, nullptr, 0, nullptr, 0) !=
        UNZ_OK)
      throw InputError(path.string() + ": a damaged zip file");
    const std::string entry = name;
    if (entry.size() < suffix.size() ||
        entry.compare(entry.size() - suffix.size(), suffix.size(), suffix) != 0)
      continue;
    // "meta/time.csv" must not match "othermeta/time.csv": a folder boundary before it.
    if (entry.size() > suffix.size() && entry[entry.size() - suffix.size() - 1] != '/') continue;
    if (found.empty()) {
      unzGetFilePos64(zip.get(), &found_at);
      found_size = info.uncompressed_size;
    }
    found.push_back(entry);
  }
  if (found.empty()) return std::nullopt;
  if (found.size() > 1) {
    std::string names;
    for (const std::string& entry : found) names += (names.empty() ? "\"" : ", \"") + entry + "\"";
    throw InputError(path.string() + ": holds " + std::to_string(found.size()) + " exports (" +
                     names + "): which one? Unzip it and give that export's folder");
  }
  const std::string& entry = found.front();
  const std::string too_large = path.string() + ": " + entry + ": inflates to more than " +
                                std::to_string(kMaxZipEntryBytes >> 20) +
                                " MiB, more than a recording (a damaged zip, or not phyphox's)";
  if (found_size > kMaxZipEntryBytes) throw InputError(too_large);
  if (unzGoToFilePos64(zip.get(), &found_at) != UNZ_OK || unzOpenCurrentFile(zip.get()) != UNZ_OK)
    throw InputError(path.string() + ": " + entry + ": cannot open the zip entry");
  std::string bytes;
  char buffer[65536];
  int got = 0;
  // The declared size bounds the bytes read: minizip inflates an entry no further than its
  // header's uncompressed size, so an entry whose header understates it reads short and fails
  // its CRC at the close below (ZipLimits.AnUnderstatedSizeReadsShortAndIsADamagedEntry).
  while ((got = unzReadCurrentFile(zip.get(), buffer, sizeof buffer)) > 0)
    bytes.append(buffer, static_cast<std::size_t>(got));
  const int closed = unzCloseCurrentFile(zip.get());
  if (got < 0 || closed != UNZ_OK)
    throw InputError(path.string() + ": " + entry + ": a damaged zip entry");
  return bytes;
}

}  // namespace bookspin::fit
