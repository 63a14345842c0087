// ClipSinks with a comparison's CSVs: every tile's rows in its own file, put in place with
// the run's other outputs or not at all.
#include "clip/clip_sinks.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "support/scratch.hpp"
#include "support/test_images.hpp"

namespace bookspin::clip {
namespace {
namespace fs = std::filesystem;
using bookspin::test::ScratchDir;
using test::moving_square_frame;

constexpr int kWidth = 64, kHeight = 48, kFrames = 3, kTiles = 3;

SinkOptions small_options() {
  SinkOptions options;
  options.write_png = false;
  options.encoder.width = kWidth;
  options.encoder.height = kHeight;
  options.encoder.fps = 24;
  options.encoder.codec = "libx264";
  options.encoder.preset = "ultrafast";
  return options;
}

ClipPaths paths_in(const ScratchDir& dir) {
  return {dir / "clip.mp4", dir / "clip.webm", dir / "clip.gif", dir / "clip/frames",
          dir / "clip/diagnostics-a.csv"};
}

std::vector<fs::path> tile_csvs_in(const ScratchDir& dir) {
  return {dir / "clip/diagnostics-b.csv", dir / "clip/diagnostics-c.csv"};
}

/// Tile `tile`'s row of frame `index`: t = index + tile/4, E = tile + 1, the rest at rest
/// (L = 0, identity orientation).
physics::Diagnostics row_of(int index, int tile) {
  physics::Diagnostics d;
  d.t = index + 0.25 * tile;
  d.energy_total = tile + 1.0;
  return d;
}

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

std::vector<std::string> files_under(const fs::path& dir) {
  std::vector<std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) files.push_back(e.path().lexically_relative(dir).generic_string());
  std::sort(files.begin(), files.end());
  return files;
}

TEST(ClipSinks, WritesEveryTilesRowsToItsOwnCsv) {
  const ScratchDir dir;
  {
    ClipSinks sinks(paths_in(dir), small_options(), tile_csvs_in(dir));
    for (int i = 0; i < kFrames; ++i) {
      const std::vector<physics::Diagnostics> rows{row_of(i, 0), row_of(i, 1), row_of(i, 2)};
      sinks.add(i, moving_square_frame(kWidth, kHeight, i), rows);
    }
    output::OutputSet outputs;
    sinks.finish(outputs);
    for (const char* name : {"clip.mp4", "clip/diagnostics-a.csv", "clip/diagnostics-b.csv"})
      EXPECT_FALSE(fs::exists(dir / name)) << name << " in place before the commit";
    outputs.commit();
  }
  EXPECT_EQ(files_under(dir.path()),
            (std::vector<std::string>{"clip.mp4", "clip/diagnostics-a.csv",
                                      "clip/diagnostics-b.csv", "clip/diagnostics-c.csv"}));
  // Written by hand from the columns (docs/outputs.md): frame, t, ω, L, the energies, three
  // empty cosines (L = 0), strain, orthogonality, |q|, three empty cosines, q = (1, 0, 0, 0),
  // the centre of mass.
  const char* rows[kTiles][kFrames] = {{"0,0,0,0,0,0,0,0,0,0,1,,,,0,0,1,,,,1,0,0,0,0,0,0",
                                        "1,1,0,0,0,0,0,0,0,0,1,,,,0,0,1,,,,1,0,0,0,0,0,0",
                                        "2,2,0,0,0,0,0,0,0,0,1,,,,0,0,1,,,,1,0,0,0,0,0,0"},
                                       {"0,0.25,0,0,0,0,0,0,0,0,2,,,,0,0,1,,,,1,0,0,0,0,0,0",
                                        "1,1.25,0,0,0,0,0,0,0,0,2,,,,0,0,1,,,,1,0,0,0,0,0,0",
                                        "2,2.25,0,0,0,0,0,0,0,0,2,,,,0,0,1,,,,1,0,0,0,0,0,0"},
                                       {"0,0.5,0,0,0,0,0,0,0,0,3,,,,0,0,1,,,,1,0,0,0,0,0,0",
                                        "1,1.5,0,0,0,0,0,0,0,0,3,,,,0,0,1,,,,1,0,0,0,0,0,0",
                                        "2,2.5,0,0,0,0,0,0,0,0,3,,,,0,0,1,,,,1,0,0,0,0,0,0"}};
  const char* names[kTiles] = {"a", "b", "c"};
  for (int tile = 0; tile < kTiles; ++tile) {
    std::string expected = output::diagnostics_csv_header() + "\n";
    for (const char* row : rows[tile]) expected += std::string(row) + "\n";
    EXPECT_EQ(read_file(dir / ("clip/diagnostics-" + std::string(names[tile]) + ".csv")), expected)
        << "tile " << names[tile];
  }
}

TEST(ClipSinks, LeavesNoCsvBehindWithoutACommit) {
  const ScratchDir dir;
  {
    ClipSinks sinks(paths_in(dir), small_options(), tile_csvs_in(dir));
    const std::vector<physics::Diagnostics> rows{row_of(0, 0), row_of(0, 1), row_of(0, 2)};
    sinks.add(0, moving_square_frame(kWidth, kHeight, 0), rows);
  }
  EXPECT_EQ(files_under(dir.path()), std::vector<std::string>{});
}

TEST(ClipSinks, RefusesFramesWithoutOneRowPerCsv) {
  const ScratchDir dir;
  ClipSinks sinks(paths_in(dir), small_options(), tile_csvs_in(dir));
  EXPECT_THROW(sinks.add(0, moving_square_frame(kWidth, kHeight, 0), row_of(0, 0)),
               std::invalid_argument);
}

}  // namespace
}  // namespace bookspin::clip
