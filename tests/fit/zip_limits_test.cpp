// The zip reader's limit (docs/phone-lab.md, "Reading a recording"): an entry that says it
// inflates to more than 256 MiB is refused on its claim, before a byte is inflated; one that
// says 256 MiB or less is read. The claims are made by hand (entries stored raw, their sizes
// declared), 1 MiB over and exactly at the limit; a claim under the entry's size reads no further.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "common/errors.hpp"
#include "fit/recording.hpp"
#include "support/scratch.hpp"
#include "zip_writer.hpp"

namespace bookspin::fit {
namespace {

std::string error_of(const std::filesystem::path& path) {
  try {
    read_recording(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(ZipLimits, AClaimOneMebibyteOverTheLimitIsRefusedOnItsClaim) {
  const auto dir = bookspin::test::fresh_dir("fit/zip-limits");
  const std::uint64_t limit = std::uint64_t{256} * 1024 * 1024;
  test::write_zip(dir / "over.zip", {{"toss/Raw Data.csv", "t,wx,wy,wz\n"}}, limit + (1u << 20));
  EXPECT_EQ(error_of(dir / "over.zip"),
            (dir / "over.zip").string() +
                ": toss/Raw Data.csv: inflates to more than 256 MiB, more than a recording (a "
                "damaged zip, or not phyphox's)");
  // At the limit the claim passes: what is refused then is the entry's own bytes (a header
  // and no samples), not its size.
  test::write_zip(dir / "at.zip", {{"toss/Raw Data.csv", "t,wx,wy,wz\n"}}, limit);
  EXPECT_EQ(error_of(dir / "at.zip").find("inflates to more than"), std::string::npos)
      << error_of(dir / "at.zip");
}

// A header that understates its entry (1 KiB of samples declared as 64 bytes, a CRC of 0): the
// reader stops at the declared 64 bytes (minizip inflates no further), so what a lying header
// hides is never read; the entry is refused as damaged.
TEST(ZipLimits, AnUnderstatedSizeReadsShortAndIsADamagedEntry) {
  const auto dir = bookspin::test::fresh_dir("fit/zip-understated");
  std::string samples = "t,wx,wy,wz\n";
  for (int i = 0; samples.size() < 1024; ++i)
    samples += std::to_string(0.01 * i) + ",0.1,0.2,0.3\n";
  test::write_zip(dir / "short.zip", {{"toss/Raw Data.csv", samples}}, 64);
  EXPECT_EQ(error_of(dir / "short.zip"),
            (dir / "short.zip").string() + ": toss/Raw Data.csv: a damaged zip entry");
}

}  // namespace
}  // namespace bookspin::fit
