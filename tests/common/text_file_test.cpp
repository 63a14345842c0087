// The whole-file reader (common/text_file.hpp): the bytes come back exactly as written by
// std::ofstream, and every kind of file that has none to give is a reason, not an exception
// (or, through read_text_file, an InputError naming the file).
#include "common/text_file.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fstream>
#include <random>

#include "common/errors.hpp"
#include "support/scratch.hpp"

namespace bookspin {
namespace {

using test::ScratchDir;

void write_bytes(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

TEST(TextFile, GivesBackTheBytesAsWritten) {
  ScratchDir dir;
  // CR LF, a lone CR, a NUL, bytes that are not UTF-8, no newline at the end.
  const std::string bytes = std::string("a = 1\r\nb\rc\0d", 12) + "\xff\xfe\x80 end";
  write_bytes(dir / "odd.toml", bytes);
  EXPECT_EQ(try_read_text_file(dir / "odd.toml"), bytes);
  EXPECT_EQ(read_text_file(dir / "odd.toml", "the scene file"), bytes);
}

TEST(TextFile, ReadsAFileLargerThanOneBufferAndAnEmptyOne) {
  ScratchDir dir;
  std::mt19937 random(7);
  std::string bytes(200'003, '\0');  // three 64 KiB reads and a bit
  for (char& c : bytes) c = static_cast<char>(random() & 0xff);
  write_bytes(dir / "big.bin", bytes);
  const auto text = try_read_text_file(dir / "big.bin");
  ASSERT_TRUE(text.has_value());
  EXPECT_EQ(text->size(), bytes.size());
  EXPECT_TRUE(*text == bytes);

  write_bytes(dir / "empty.toml", "");
  EXPECT_EQ(try_read_text_file(dir / "empty.toml"), std::string());
}

TEST(TextFile, SaysWhyThereIsNothingToRead) {
  ScratchDir dir;
  std::string reason;
  EXPECT_EQ(try_read_text_file(dir / "missing.toml", &reason), std::nullopt);
  EXPECT_EQ(reason, "no such file");
  EXPECT_EQ(try_read_text_file(dir.path(), &reason), std::nullopt);
  EXPECT_EQ(reason, "is a directory");
  ASSERT_EQ(mkfifo((dir / "fifo").c_str(), 0600), 0);  // reading it would wait for a writer
  EXPECT_EQ(try_read_text_file(dir / "fifo", &reason), std::nullopt);
  EXPECT_EQ(reason, "is a FIFO, not a regular file");
  EXPECT_EQ(try_read_text_file("/dev/zero", &reason), std::nullopt);  // would never end
  EXPECT_EQ(reason, "is a device, not a regular file");
  EXPECT_EQ(try_read_text_file(dir / "missing.toml"), std::nullopt);  // no reason wanted
}

TEST(TextFile, TrimmedAndWithoutBom) {
  EXPECT_EQ(trimmed(" \t t,wx \r"), "t,wx");
  EXPECT_EQ(trimmed(" \t\r "), "");
  EXPECT_EQ(without_bom("\xEF\xBB\xBFt,wx"), "t,wx");
  EXPECT_EQ(without_bom("t,wx"), "t,wx");
  EXPECT_EQ(without_bom("\xEF\xBBt"), "\xEF\xBBt");  // half a mark is not one
}

TEST(TextFile, AnUnreadableFileIsTheOsError) {
  if (geteuid() == 0) GTEST_SKIP() << "root reads a file whatever its mode";
  ScratchDir dir;
  write_bytes(dir / "secret.toml", "x = 1\n");
  std::filesystem::permissions(dir / "secret.toml", std::filesystem::perms::none);
  std::string reason;
  EXPECT_EQ(try_read_text_file(dir / "secret.toml", &reason), std::nullopt);
  EXPECT_EQ(reason, "Permission denied");
  std::filesystem::permissions(dir / "secret.toml", std::filesystem::perms::owner_all);
}

TEST(TextFile, ReadTextFileThrowsAnInputErrorNamingTheFileAndWhatItIs) {
  ScratchDir dir;
  const auto missing = dir / "missing.toml";
  try {
    read_text_file(missing, "the scene file");
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              missing.string() + ": cannot read the scene file: no such file");
  }
}

}  // namespace
}  // namespace bookspin
