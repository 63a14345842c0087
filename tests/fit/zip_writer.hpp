#pragma once
// Zips written by hand for the recording reader's tests (minizip, as Debian ships it).
#include <gtest/gtest.h>
#include <zip.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace bookspin::fit::test {

/// A zip at `path` of `files` (name, bytes), deflated; with `declared` set, each entry stored
/// raw and declared to inflate to that many bytes (a zip bomb's claim). Fails the test (gtest
/// ASSERT) where minizip cannot write it.
inline void write_zip(const std::filesystem::path& path,
                      const std::vector<std::pair<std::string, std::string>>& files,
                      std::optional<std::uint64_t> declared = std::nullopt) {
  zipFile zip = zipOpen64(path.string().c_str(), APPEND_STATUS_CREATE);
  ASSERT_NE(zip, nullptr);
  for (const auto& [name, bytes] : files) {
    ASSERT_EQ(zipOpenNewFileInZip2_64(zip, name.c_str(), nullptr, nullptr, 0, nullptr, 0, nullptr,
                                      declared ? 0 : Z_DEFLATED,
                                      declared ? 0 : Z_DEFAULT_COMPRESSION, declared ? 1 : 0, 1),
              ZIP_OK);
    ASSERT_EQ(zipWriteInFileInZip(zip, bytes.data(), static_cast<unsigned>(bytes.size())), ZIP_OK);
    if (declared)
      zipCloseFileInZipRaw64(zip, *declared, 0);
    else
      zipCloseFileInZip(zip);
  }
  zipClose(zip, nullptr);
}

}  // namespace bookspin::fit::test
