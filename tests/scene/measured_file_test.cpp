// measured.omega (scenes/README.md): a measured ω file read beside the scene, its samples
// checked row by row, and every bad file one line naming the key, the file and the row.
#include "scene/measured_file.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>

#include "scene/scene.hpp"
#include "support/scratch.hpp"

namespace bookspin::scene {
namespace {

namespace fs = std::filesystem;

/// parse_measured_omega's answer for `text` ("" when it reads).
std::string problem(const std::string& text) {
  MeasuredOmega out;
  return parse_measured_omega(text, out);
}

TEST(MeasuredFile, ReadsTheSamples) {
  MeasuredOmega out;
  ASSERT_EQ(parse_measured_omega("t,wx,wy,wz\r\n0,1,2,3\r\n0.01, -4e-1 ,5,6.5\n", out), "");
  EXPECT_EQ(out.t, (std::vector<double>{0.0, 0.01}));
  ASSERT_EQ(out.omega.cols(), 2);
  EXPECT_EQ(out.omega.col(0), Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(out.omega.col(1), Eigen::Vector3d(-0.4, 5, 6.5));
  // A spreadsheet's UTF-8 byte-order mark before the header is read past.
  MeasuredOmega marked;
  ASSERT_EQ(parse_measured_omega("\xEF\xBB\xBFt,wx,wy,wz\n0,1,2,3\n", marked), "");
  EXPECT_EQ(marked.omega.col(0), Eigen::Vector3d(1, 2, 3));
}

TEST(MeasuredFile, RefusesWhatIsNotASample) {
  EXPECT_EQ(problem(""), "row 1: the header must be t,wx,wy,wz");
  EXPECT_EQ(problem("t,x,y,z\n0,1,2,3\n"), "row 1: the header must be t,wx,wy,wz");
  EXPECT_EQ(problem("t,wx,wy,wz\n"), "no samples (a header alone)");
  EXPECT_EQ(problem("t,wx,wy,wz\n0,1,2\n"), "row 2: expected 4 cells (t,wx,wy,wz)");
  EXPECT_EQ(problem("t,wx,wy,wz\n0,1,2,3,4\n"), "row 2: expected 4 cells (t,wx,wy,wz)");
  EXPECT_EQ(problem("t,wx,wy,wz\n0,1,nan,3\n"), "row 2: wy: not a finite number: \"nan\"");
  EXPECT_EQ(problem("t,wx,wy,wz\n0,1,2,x\n"), "row 2: wz: not a finite number: \"x\"");
  EXPECT_EQ(problem("t,wx,wy,wz\n0,1,2,3\n0,1,2,3\n"), "row 3: t: not after the row before");
  EXPECT_EQ(problem("t,wx,wy,wz\n-1,1,2,3\n"), "row 2: t: negative (time since the scene's start)");
  EXPECT_EQ(problem("t,wx,wy,wz\n0,2e6,2,3\n"), "row 2: wx: beyond ±1e6 rad per time unit");
  // On the magnitude, both signs: far below −1e6 as far above.
  EXPECT_EQ(problem("t,wx,wy,wz\n0,1,-3e7,3\n"), "row 2: wy: beyond ±1e6 rad per time unit");
  EXPECT_EQ(problem("t,wx,wy,wz\n0,1,2,-1e300\n"), "row 2: wz: beyond ±1e6 rad per time unit");
}

TEST(MeasuredFile, TheSceneReadsItBesideItself) {
  bookspin::test::ScratchDir dir;
  std::ofstream(dir.path() / "w.csv") << "t,wx,wy,wz\n0,1,2,3\n0.5,1,2,3\n";
  std::ofstream(dir.path() / "bad.csv") << "t,wx,wy,wz\n0,1,2,3\n0.5,1,2\n";
  const auto scene_file = [&](const std::string& file) {
    const fs::path path = dir.path() / "s.toml";
    std::ofstream(path) << "[measured]\nomega = \"" << file << "\"\n";
    return path;
  };
  const Scene s = parse_scene(scene_file("w.csv"));
  EXPECT_EQ(fs::path(s.measured.file), dir.path() / "w.csv");
  EXPECT_EQ(s.measured.t.size(), 2u);
  EXPECT_TRUE(parse_scene_text("[scene]\n", "x.toml").measured.file.empty());
  const auto error = [&](const std::string& file) {
    try {
      parse_scene(scene_file(file));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string where = (dir.path() / "s.toml").string() + ":2: measured.omega: ";
  EXPECT_EQ(error("none.csv"),
            where + (dir.path() / "none.csv").string() + ": no such file (the measured ω file)");
  // A folder, a FIFO, a device: said as what they are, never "not found" (nor read forever).
  EXPECT_EQ(error(dir.path().string()),
            where + dir.path().string() + ": is a directory (the measured ω file)");
  ASSERT_EQ(mkfifo((dir.path() / "fifo").c_str(), 0600), 0);
  EXPECT_EQ(error("fifo"), where + (dir.path() / "fifo").string() +
                               ": is a FIFO, not a regular file (the measured ω file)");
  EXPECT_EQ(error("/dev/zero"),
            where + "/dev/zero: is a device, not a regular file (the measured ω file)");
  EXPECT_EQ(error("bad.csv"), (dir.path() / "s.toml").string() +
                                  ":2: measured.omega: " + (dir.path() / "bad.csv").string() +
                                  ": row 3: expected 4 cells (t,wx,wy,wz)");
}

}  // namespace
}  // namespace bookspin::scene
