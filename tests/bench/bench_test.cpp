// bookspin-bench. No timings are asserted:
// the numbers depend on the machine; only that they are measured and written.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <thread>
#include <vector>

#include "support/cli_runner.hpp"

namespace bookspin::bench {
namespace {

using namespace bookspin::test;  // the shared runner (tests/support)

struct BenchRun {
  std::filesystem::path dir;  ///< the -o directory
  CliResult result;
  std::string csv;  ///< dir/bench.csv ("" if not written)
};

/// `bookspin bench fig09 ARGS -o <fresh NAME dir>`.
BenchRun run_bench(const std::string& name, const std::string& args) {
  BenchRun run{fresh_dir(name), {}, {}};
  run.result =
      run_program("", BOOKSPIN_BENCH_EXE,
                  scene_path("fig09-matrix-unstable-x") + " " + args + " -o " + run.dir.string());
  run.csv = read_file(run.dir / "bench.csv");
  return run;
}

/// The value column of the pipeline CSV row whose metric starts with `metric`; NaN if there
/// is none. Metrics holding a comma are quoted (and none of these holds a quote).
double csv_value(const std::string& csv, const std::string& metric,
                 const std::string& section = "pipeline") {
  for (const std::string& field : {"\"" + metric, metric}) {
    const auto at = csv.find("\n" + section + "," + field);
    if (at == std::string::npos) continue;
    const auto metric_start = at + section.size() + 2;
    const auto metric_end =
        field[0] == '"' ? csv.find("\",", metric_start + 1) + 1 : csv.find(',', metric_start);
    return std::stod(csv.substr(metric_end + 1));
  }
  return std::nan("");
}

/// MemAvailable in GiB (0 where /proc/meminfo cannot be read).
double available_gib() {
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  double kib = 0.0;
  while (meminfo >> key >> kib)
    if (key == "MemAvailable:") return kib / (1024.0 * 1024.0);
  return 0.0;
}

TEST(Bench, MemorySectionWritesTheCsvWithBothRunsAndTheirRatio) {
  const BenchRun run = run_bench("bench-memory", "--only memory --memory-frames 150");
  const CliResult& r = run.result;
  ASSERT_EQ(r.status, 0) << r.output;
  const std::string& csv = run.csv;
  EXPECT_EQ(csv.rfind("section,metric,value,unit,note\n", 0), 0u) << csv;
  EXPECT_NE(csv.find("peak RSS, render --no-png 100 frames"), std::string::npos) << csv;
  EXPECT_NE(csv.find("peak RSS, render --no-png 150 frames"), std::string::npos) << csv;
  EXPECT_NE(csv.find("peak RSS 150 / 100 frames"), std::string::npos) << csv;
  EXPECT_NE(r.output.find("section"), std::string::npos) << "the table goes to stdout";
}

TEST(Bench, PipelineSectionReportsBestOfAlternatedRunsAndTheRatios) {
  const BenchRun run = run_bench("bench-pipeline", "--only pipeline --frames 2 --rounds 2");
  ASSERT_EQ(run.result.status, 0) << run.result.output;
  const std::string& csv = run.csv;
  for (const char* row : {"encoder alone (the floor), 2 frames 1280x720", "render --no-png / floor",
                          "render with PNGs / floor", "render --no-png, 4x anisotropic / floor",
                          "render --no-png, render.msaa = 1 / floor"}) {
    EXPECT_NE(csv.find(row), std::string::npos) << row << " missing from\n" << csv;
  }
  EXPECT_NE(csv.find("best of 2 alternated runs"), std::string::npos) << csv;
  EXPECT_EQ(csv.find("physics"), std::string::npos) << "--only pipeline ran other sections";
  // CPU time counts every thread: more than nothing, at most all cores for the whole run
  // (10% for the two clocks being read at slightly different instants).
  const double cores = std::thread::hardware_concurrency();
  for (const char* run : {"encoder alone (the floor)", "render --no-png", "render with PNGs"}) {
    const double wall = csv_value(csv, std::string(run) + ", 2 frames");
    const double cpu = csv_value(csv, std::string(run) + ", CPU time, 2 frames");
    EXPECT_GT(cpu, 0.0) << run << "\n" << csv;
    EXPECT_LE(cpu, 1.1 * cores * wall) << run << "\n" << csv;
  }
  EXPECT_GT(csv_value(csv, "render --no-png start-up (2 frames), CPU time"), 0.0) << csv;
  EXPECT_NEAR(csv_value(csv, "render --no-png / floor, CPU time"),
              csv_value(csv, "render --no-png, CPU time") /
                  csv_value(csv, "encoder alone (the floor), CPU time"),
              1e-3 * csv_value(csv, "render --no-png / floor, CPU time"))
      << csv;
  // The split of a frame's cost: every part measured, in ms per frame; the parts the render
  // adds cannot together exceed what the whole render costs (the PNG aside, 2 frames: a
  // generous bound, start-up included in the whole).
  double parts = 0.0;
  for (const char* part :
       {"simulation", "GL draw + MSAA resolve", "read-back", "overlay: panel plots",
        "overlay: momentum sphere inset", "overlay: caption"}) {
    const double ms = csv_value(csv, std::string(part) + ", per frame", "pipeline split");
    EXPECT_GE(ms, 0.0) << part << "\n" << csv;
    parts += ms;
  }
  EXPECT_GT(parts, 0.0) << csv;
  // The PNG writer and its yardstick, the former libpng + zlib writer, on the same frames.
  const double png =
      csv_value(csv, "PNG (libdeflate, as render writes it), per frame", "pipeline split");
  const double zlib = csv_value(csv, "PNG through libpng and zlib (the former writer), per frame",
                                "pipeline split");
  EXPECT_GT(png, 0.0) << csv;
  EXPECT_GT(zlib, 0.0) << csv;
  EXPECT_NEAR(csv_value(csv, "PNG libdeflate / libpng+zlib, CPU time", "pipeline split"),
              png / zlib, 1e-3 * png / zlib)
      << csv;
  EXPECT_GT(csv_value(csv, "PNG file (libdeflate), per frame", "pipeline split"), 10.0) << csv;
  EXPECT_GT(csv_value(csv, "PNG file (libpng+zlib), per frame", "pipeline split"), 10.0) << csv;
  EXPECT_GT(csv_value(csv, "conversion RGBA to yuv420p, per frame", "pipeline split"), 0.0) << csv;
  EXPECT_LE(parts, 1e3 * csv_value(csv, "render --no-png, CPU time") / 2) << csv;
  // The renders went to a scratch directory that is gone: only the CSV is left here.
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(run.dir),
                          std::filesystem::directory_iterator()),
            1);
}

// MuJoCo's renderer beside bookspin's on the same poses: both rows, with and without the
// encoder, and their ratios; the middle frame of each written for a look.
TEST(Bench, PeerSectionTimesMujocosRendererAgainstBookspinsOnTheSamePoses) {
  const BenchRun run = run_bench("bench-peer", "--only peer --frames 4 --rounds 1");
  ASSERT_EQ(run.result.status, 0) << run.result.output;
  const std::string& csv = run.csv;
  if (run.result.output.find("peer: skipped") != std::string::npos) {
    GTEST_SKIP() << "bookspin-bench was built without MuJoCo";
  }
  const double own = csv_value(csv, "bookspin draw + read-back,", "peer");
  const double mujoco = csv_value(csv, "MuJoCo mjr_render + mjr_readPixels,", "peer");
  const double own_encoded = csv_value(csv, "bookspin draw + read-back + encoder", "peer");
  const double mujoco_encoded =
      csv_value(csv, "MuJoCo mjr_render + mjr_readPixels + encoder", "peer");
  for (double seconds : {own, mujoco, own_encoded, mujoco_encoded}) EXPECT_GT(seconds, 0.0) << csv;
  EXPECT_NEAR(csv_value(csv, "MuJoCo / bookspin, draw + read-back", "peer"), mujoco / own,
              1e-3 * mujoco / own)
      << csv;
  EXPECT_NEAR(csv_value(csv, "MuJoCo / bookspin, with the encoder", "peer"),
              mujoco_encoded / own_encoded, 1e-3 * mujoco_encoded / own_encoded)
      << csv;
  EXPECT_NE(csv.find("4 poses 1280x720, best of 1 alternated runs"), std::string::npos) << csv;
  EXPECT_TRUE(std::filesystem::exists(run.dir / "peer-bookspin.png"));
  EXPECT_TRUE(std::filesystem::exists(run.dir / "peer-mujoco.png"));
}

TEST(Bench, RefusesUpFrontAPipelineWhoseFramesWouldNotFitInMemory) {
  // 100,000 frames of 1280x720 RGBA are 343 GiB.
  if (available_gib() > 400.0) GTEST_SKIP() << "this machine could hold them";
  const BenchRun run = run_bench("bench-oversized", "--frames 100000");
  EXPECT_EQ(run.result.status, 1) << run.result.output;  // the machine's limit, not bad input
  EXPECT_NE(run.result.output.find("--frames 100000 holds 343.3 GiB"), std::string::npos)
      << run.result.output;
  EXPECT_EQ(run.result.output.find("peak RSS"), std::string::npos)
      << "a section ran before the check";
  EXPECT_TRUE(run.csv.empty());
}

TEST(Bench, BadSceneStopsTheBenchWithTheScenesOwnMessage) {
  // The memory section renders in child processes, which could only say that they failed.
  const CliResult r = run_program("", BOOKSPIN_BENCH_EXE, "no-such-scene.toml --only memory");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("no-such-scene.toml: scene file not found"), std::string::npos)
      << r.output;
}

TEST(Bench, ExplorerSectionTimesEveryMethodOfThePage) {
  const BenchRun run =
      run_bench("bench-explorer", "--only explorer --explorer-steps 50 --rounds 1");
  ASSERT_EQ(run.result.status, 0) << run.result.output;
  for (const char* method :
       {"particle euler", "particle symplectic-euler", "particle velocity-verlet",
        "rigid-matrix euler", "rigid-matrix rk4", "rigid-matrix implicit-midpoint",
        "rigid-matrix splitting", "rigid-matrix splitting4", "rigid-quaternion euler",
        "rigid-quaternion rk4", "rigid-quaternion implicit-midpoint", "rigid-quaternion splitting",
        "rigid-quaternion splitting4", "exact"}) {
    EXPECT_GT(csv_value(run.csv, method, "explorer"), 0.0) << method << "\n" << run.csv;
  }
  EXPECT_NE(run.csv.find("50 steps of dt 0.016667, best of 1, wall time"), std::string::npos)
      << run.csv;
}

TEST(Bench, FitSectionTimesTheFitAgainstReadingTheFile) {
  // 0.2 minutes at 500 Hz: five tosses of the bench's phone on a book.
  const BenchRun run = run_bench("bench-fit", "--only fit --fit-minutes 0.2");
  ASSERT_EQ(run.result.status, 0) << run.result.output;
  const double floor = csv_value(run.csv, "read Raw Data.csv alone (the floor)", "fit");
  const double fit = csv_value(run.csv, "read, find the flights and fit, wall clock", "fit");
  ASSERT_GT(floor, 0.0) << run.csv;
  ASSERT_GT(fit, 0.0) << run.csv;
  EXPECT_GT(csv_value(run.csv, "read, find the flights and fit, CPU time", "fit"), 0.0);
  EXPECT_NEAR(csv_value(run.csv, "read, find and fit / floor", "fit"), fit / floor,
              1e-6 * fit / floor)
      << run.csv;
  // The body the bench made was found (the 1 % and 1°).
  EXPECT_LT(csv_value(run.csv, "moment ratios' largest relative error", "fit"), 0.01) << run.csv;
  EXPECT_LT(csv_value(run.csv, "principal axes' largest error", "fit"), 1.0) << run.csv;
  EXPECT_NE(run.csv.find("0.2 min at 500 Hz, 5 tosses"), std::string::npos) << run.csv;
}

TEST(Bench, ExactSectionTimesTheEvaluationAgainstTheOldOneOnTheSameRows) {
  const BenchRun run = run_bench("bench-exact", "--only exact");
  ASSERT_EQ(run.result.status, 0) << run.result.output;
  for (const char* motion :
       {"(2, 1, 3), case A", "(2, 1, 3), case B", "book, x spin with a 1e-3 jiggle",
        "(2, 1, 3), k' = 3e-6 (near the separatrix)"}) {
    const std::string name = motion;
    const double now = csv_value(run.csv, name + ": state(), per-motion constants", "exact");
    const double before = csv_value(run.csv, name + ": Boost, as before", "exact");
    ASSERT_GT(now, 0.0) << name << "\n" << run.csv;
    ASSERT_GT(before, 0.0) << name << "\n" << run.csv;
    // The ratio is the two rows' (no timed assertion: the machine may be busy).
    EXPECT_NEAR(csv_value(run.csv, name + ": before / now", "exact"), before / now,
                1e-6 * before / now)
        << run.csv;
  }
  EXPECT_GT(csv_value(run.csv, "book, x spin with a 1e-3 jiggle: jobs::exact_motion_at", "exact"),
            0.0)
      << run.csv;
  EXPECT_EQ(run.csv.find("physics"), std::string::npos) << "--only exact ran other sections";
}

/// The rows of a CSV without quoted fields, each split at its commas (the header first).
std::vector<std::vector<std::string>> csv_rows(const std::string& csv) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream lines(csv);
  std::string line;
  while (std::getline(lines, line)) {
    std::vector<std::string> fields;
    std::istringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, ',')) fields.push_back(cell);
    rows.push_back(fields);
  }
  return rows;
}

// Every preset from ultrafast to medium at CRF 17 and 18 on a few frames of one clip: one row
// each in presets.csv, medium/CRF 18 the reference, and the pick in bench.csv the pair this
// test's own reading of the rule picks from those rows.
TEST(Bench, PresetsSectionWritesEveryPresetAndCrfAndPicksByTheRule) {
  const BenchRun run =
      run_bench("bench-presets",
                "--only presets --preset-frames 4 --preset-crfs 17 --frames 3 --rounds 1 "
                "--preset-scenes " +
                    scene_path("fig09-matrix-unstable-x"));
  ASSERT_EQ(run.result.status, 0) << run.result.output;
  const auto rows = csv_rows(read_file(run.dir / "presets.csv"));
  ASSERT_EQ(rows.size(), 1u + 6 * 2) << read_file(run.dir / "presets.csv");
  ASSERT_EQ(rows[0][4], "preset");
  const auto column = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(rows[0].begin(), rows[0].end(), name) -
                                    rows[0].begin());
  };
  const std::size_t preset = column("preset"), crf = column("crf"), ssim = column("ssim"),
                    psnr = column("psnr_db"), bytes = column("bytes"), cpu = column("encode_cpu_s");
  ASSERT_LT(cpu, rows[0].size());
  std::map<std::pair<std::string, int>, std::vector<double>> by_pair;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const auto& r = rows[i];
    EXPECT_EQ(r[0], "fig09-matrix-unstable-x");
    EXPECT_EQ(r[1], "4");
    EXPECT_EQ(r[2] + "x" + r[3], "1280x720");
    by_pair[{r[preset], std::stoi(r[crf])}] = {std::stod(r[ssim]), std::stod(r[psnr]),
                                               std::stod(r[bytes]), std::stod(r[cpu])};
    EXPECT_GT(std::stod(r[ssim]), 0.9) << r[preset];
    EXPECT_LE(std::stod(r[ssim]), 1.0) << r[preset];
    EXPECT_GT(std::stod(r[psnr]), 30.0) << r[preset];
  }
  ASSERT_EQ(by_pair.size(), 12u);
  const std::vector<double>& ref = by_pair.at({"medium", 18});
  // ultrafast turns off CABAC and most of the search: a larger file at the same CRF.
  EXPECT_GT(by_pair.at({"ultrafast", 18})[2], ref[2]);
  // The rule, read from the rows: the least CPU among pairs within 0.0005 SSIM, 0.1 dB PSNR
  // and 1.25x the size of medium/CRF 18.
  std::pair<std::string, int> pick{"medium", 18};
  for (const auto& [pair, v] : by_pair) {
    if (v[0] >= ref[0] - 0.0005 && v[1] >= ref[1] - 0.1 && v[2] <= 1.25 * ref[2] &&
        v[3] < by_pair.at(pick)[3])
      pick = pair;
  }
  const std::string picked =
      "the rule's pick: " + pick.first + " crf " + std::to_string(pick.second);
  EXPECT_NE(run.csv.find(picked), std::string::npos) << picked << "\n" << run.csv;
  EXPECT_GT(csv_value(run.csv, "pick / medium crf 18, wall time", "presets"), 0.0) << run.csv;
  EXPECT_GT(csv_value(run.csv, "medium crf 18, render --no-png 3 frames 1280x720", "presets"), 0.0)
      << run.csv;
}

TEST(Bench, GifMemorySectionMeasuresTheGifAgainstTheMp4) {
  const BenchRun run =
      run_bench("bench-gif-memory", "--only gif-memory --gif-frames 20 --gif-scene " +
                                        scene_path("fig09-matrix-unstable-x"));
  ASSERT_EQ(run.result.status, 0) << run.result.output;
  const double mp4 =
      csv_value(run.csv, "peak RSS, render --format mp4, fig09-matrix-unstable-x", "memory");
  const double gif =
      csv_value(run.csv, "peak RSS, render --format gif, fig09-matrix-unstable-x", "memory");
  EXPECT_GT(mp4, 10.0) << run.csv;
  EXPECT_GT(gif, 10.0) << run.csv;
  EXPECT_NEAR(csv_value(run.csv, "peak RSS gif / mp4", "memory"), gif / mp4, 1e-3 * gif / mp4)
      << run.csv;
}

TEST(Bench, UnknownSectionIsAUsageError) {
  EXPECT_EQ(run_program("", BOOKSPIN_BENCH_EXE, "--only nonsense").status, 2);
}

}  // namespace
}  // namespace bookspin::bench
