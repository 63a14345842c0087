#pragma once
// One entry of a zip (a phyphox export zipped) read through minizip (docs/phone-lab.md, "The
// recording"), no bigger than a recording may be.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace bookspin::fit {

/// The bytes of the one entry of the zip `path` whose name ends in `suffix` (after a folder
/// boundary); nullopt when none. Throws InputError when the file is empty, not a readable zip,
/// an empty zip, holds two such entries (naming them: which one is meant?), or the entry
/// inflates beyond kMaxZipEntryBytes.
std::optional<std::string> zip_entry(const std::filesystem::path& path, std::string_view suffix);

}  // namespace bookspin::fit
