// A sweep's shards (jobs/sweep_shard.hpp, docs/sweeps.md): the file's lines against lines
// written out by hand, and shards read back into their sweep's table, in any order, with LF or
// CRLF line endings, a missing one named. (The merge through the program, and every way a
// shard can be of another sweep: tests/cli/sweep_command_test.cpp.)
#include "jobs/sweep_shard.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <regex>

#include "common/errors.hpp"
#include "output/atomic_output.hpp"
#include "support/scratch.hpp"

namespace bookspin::jobs {
namespace {

namespace fs = std::filesystem;

/// A 2 × 2 sweep's table, rows 0 … 3 with their cells; first_flip empty where a run did not
/// flip; point 1 refused by its engine, with a reason that holds a comma and quotes.
SweepTable two_by_two() {
  SweepTable table;
  table.scene_name = "exact-unstable-x";
  table.ranges = {parse_vary("time.dt=0.01:0.02:2"),
                  parse_vary("initial.angular_velocity[1]=1e-3:1e-2:2:log")};
  table.measures = parse_measures("first_flip");
  table.header = sweep_csv_header(table.ranges, table.measures);
  table.rows = {{0, {"0.01", "0.001", "40.5", "40.25", ""}},
                {1, {"0.01", "0.01", "", "", "time.dt: refused, \"why\""}},
                {2, {"0.02", "0.001", "41", "40.25", ""}},
                {3, {"0.02", "0.01", "19.5", "20", ""}}};
  return table;
}

/// Shard k of n of `table`: its rows k, k + n, …
SweepTable shard_of(const SweepTable& table, int k, int n) {
  SweepTable shard = table;
  shard.rows.clear();
  for (const auto& row : table.rows)
    if (row.first % static_cast<std::size_t>(n) == static_cast<std::size_t>(k))
      shard.rows.push_back(row);
  return shard;
}

const scene::Scene& base_scene() {
  static const scene::Scene scene =
      scene::parse_scene(std::string(BOOKSPIN_SOURCE_DIR) + "/scenes/exact-unstable-x.toml");
  return scene;
}

std::vector<std::string> lines_of(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

ShardPath nowhere() {
  return [](const std::string& name, int k, int n) {
    return fs::path("/nowhere") / (name + "." + std::to_string(k) + "-" + std::to_string(n));
  };
}

TEST(SweepShard, TheFileRecordsTheSweepThenTheGridIndexBeforeEachRow) {
  const test::ScratchDir dir;
  const fs::path path = dir.path() / "shard.csv";
  output::write_text_file(path,
                          sweep_shard_text(shard_of(two_by_two(), 1, 2), base_scene(), 4, 1, 2));
  const auto lines = lines_of(path);
  ASSERT_EQ(lines.size(), 4u);
  static const std::regex first(
      "# bookspin sweep shard 1 of 2: scene=exact-unstable-x scene_sha256=[0-9a-f]{64} "
      "build=[0-9a-f]{64} points=4 vary=time\\.dt=0\\.01:0\\.02:2 "
      "vary=initial\\.angular_velocity\\[1\\]=0\\.001:0\\.01:2:log measure=first_flip");
  EXPECT_TRUE(std::regex_match(lines[0], first)) << lines[0];
  EXPECT_EQ(lines[1],
            "grid_index,time.dt,initial.angular_velocity[1],first_flip,first_flip_exact,refused");
  EXPECT_EQ(lines[2], "1,0.01,0.01,,,\"time.dt: refused, \"\"why\"\"\"");
  EXPECT_EQ(lines[3], "3,0.02,0.01,19.5,20,");
}

TEST(SweepShard, ShardsReadBackInAnyOrderAsTheWholeTableAndCrlfReadsAlike) {
  const test::ScratchDir dir;
  const SweepTable table = two_by_two();
  const fs::path a = dir.path() / "a.csv", b = dir.path() / "b.csv";
  output::write_text_file(a, sweep_shard_text(shard_of(table, 0, 2), base_scene(), 4, 0, 2));
  output::write_text_file(b, sweep_shard_text(shard_of(table, 1, 2), base_scene(), 4, 1, 2));
  // b through Windows: every line ending CRLF.
  std::string crlf;
  for (const std::string& line : lines_of(b)) crlf += line + "\r\n";
  std::ofstream(b, std::ios::binary) << crlf;
  const SweepTable read = read_sweep_shards({b, a}, nowhere());
  EXPECT_EQ(read.scene_name, table.scene_name);
  EXPECT_EQ(read.header, table.header);
  EXPECT_EQ(read.measures, table.measures);
  ASSERT_EQ(read.ranges.size(), 2u);
  EXPECT_EQ(read.ranges[1].spec(), table.ranges[1].spec());
  EXPECT_EQ(read.rows, table.rows);
  EXPECT_EQ(read.scene_title, "");  // none given: none recorded
}

// The scene's title, which heads the picture, travels in the shard line as one word
// (percent-encoded spaces, '%' and control bytes; UTF-8 as it is) and reads back byte for byte.
TEST(SweepShard, TheTitleTravelsAsOneWordAndReadsBackAsWritten) {
  const test::ScratchDir dir;
  SweepTable table = two_by_two();
  table.scene_title = "When to normalize: 100% the book, ω0\tx";
  const fs::path a = dir.path() / "a.csv", b = dir.path() / "b.csv";
  output::write_text_file(a, sweep_shard_text(shard_of(table, 0, 2), base_scene(), 4, 0, 2));
  output::write_text_file(b, sweep_shard_text(shard_of(table, 1, 2), base_scene(), 4, 1, 2));
  const std::string first = lines_of(a)[0];
  EXPECT_NE(first.find(" title=When%20to%20normalize:%20100%25%20the%20book,%20ω0%09x"),
            std::string::npos)
      << first;
  EXPECT_EQ(read_sweep_shards({a, b}, nowhere()).scene_title, table.scene_title);
}

TEST(SweepShard, AMissingShardIsNamedWhereItWouldBe) {
  const test::ScratchDir dir;
  const fs::path a = dir.path() / "a.csv";
  output::write_text_file(a, sweep_shard_text(shard_of(two_by_two(), 0, 2), base_scene(), 4, 0, 2));
  try {
    read_sweep_shards({a}, nowhere());
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(),
                 "/nowhere/exact-unstable-x.1-2: grid point 1 of 4 is missing (shard not given)");
  }
  EXPECT_THROW(read_sweep_shards({}, nowhere()), InputError);
}

/// The message of reading shard `b` after editing its line 3 to `row`, beside shard 0.
std::string edited_row_error(const fs::path& dir, const std::string& row) {
  const fs::path a = dir / "a.csv", b = dir / "b.csv";
  output::write_text_file(a, sweep_shard_text(shard_of(two_by_two(), 0, 2), base_scene(), 4, 0, 2));
  std::string text = sweep_shard_text(shard_of(two_by_two(), 1, 2), base_scene(), 4, 1, 2);
  const std::size_t third = text.find('\n', text.find('\n') + 1) + 1;
  text.replace(third, text.find('\n', third) - third, row);
  output::write_text_file(b, text);
  try {
    read_sweep_shards({a, b}, nowhere());
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(SweepShard, ARefusedRowWithAMeasureOrAQuoteNotClosedIsNamedByLine) {
  const test::ScratchDir dir;
  const std::string b3 = (dir.path() / "b.csv").string() + ":3: ";
  EXPECT_EQ(edited_row_error(dir.path(), "1,0.01,0.01,20.5,,\"time.dt: refused\""),
            b3 + "first_flip has a value in a refused point's row");
  EXPECT_EQ(edited_row_error(dir.path(), "1,0.01,0.01,,20,\"time.dt: refused\""),
            b3 + "first_flip_exact has a value in a refused point's row");
  EXPECT_EQ(edited_row_error(dir.path(), "1,0.01,0.01,,,\"time.dt: refused"),
            b3 + "a quoted cell is not closed");
  EXPECT_EQ(edited_row_error(dir.path(), "1,0.01,0.01,,,\"time.dt\": refused"),
            b3 + "text after a quoted cell's closing quote");
  // The row as written reads back.
  EXPECT_EQ(edited_row_error(dir.path(), "1,0.01,0.01,,,\"time.dt: refused, \"\"why\"\"\""),
            "no error");
}

}  // namespace
}  // namespace bookspin::jobs
