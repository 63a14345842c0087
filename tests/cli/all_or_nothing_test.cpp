// One run's outputs, all or nothing (docs/outputs.md): a product remade over an earlier one
// that cannot write all its files (a real write failure: the file size limit of
// setrlimit(RLIMIT_FSIZE), `ulimit -f`, with SIGXFSZ ignored so that write(2) fails with EFBIG,
// "File too large") exits 1 naming the path and leaves the earlier outputs and their manifest
// byte for byte, with no temporary beside them: never a folder of two runs, never a manifest
// gone while its outputs stay.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "support/cli_runner.hpp"
#include "support/scratch.hpp"
#include "support/signal_runner.hpp"

namespace bookspin::cli {
namespace {

using namespace bookspin::test;
namespace fs = std::filesystem;

// (Appended: "'" + std::string&& made GCC 12 warn of an overlapping memcpy, -Wrestrict.)
std::string quoted(const fs::path& p) {
  return std::string(1, '\'').append(p.string()).append(1, '\'');
}

/// bookspin `args` with files limited to `blocks` × 512 bytes (stderr through a file of its
/// own, beyond the limit's reach: written by the shell before the limit is set).
SplitResult run_limited(const std::string& args, int blocks, const fs::path& err_file) {
  SplitResult r;
  r.status =
      run_shell("exec 2>" + quoted(err_file) + "; trap '' XFSZ; ulimit -f " +
                    std::to_string(blocks) + "; exec " + std::string(BOOKSPIN_EXE) + " " + args,
                r.out);
  r.err = read_file(err_file);
  return r;
}

/// The entries of `after` that differ from `before`'s, and those gone: their names.
std::vector<std::string> changed(const std::map<std::string, std::string>& before,
                                 const std::map<std::string, std::string>& after) {
  std::vector<std::string> names;
  for (const auto& [name, bytes] : after) {
    const auto it = before.find(name);
    if (it == before.end())
      names.push_back("new " + name);
    else if (it->second != bytes)
      names.push_back("changed " + name);
  }
  for (const auto& [name, bytes] : before)
    if (!after.count(name)) names.push_back("gone " + name);
  return names;
}

struct Case {
  std::string name;
  std::string first;   ///< the earlier run (made whole)
  std::string second;  ///< a run that remakes the outputs, under the limit
  int blocks;          ///< the limit: lets the smaller files through, not every one
};

TEST(AllOrNothing, AFailedRemakeKeepsTheEarlierOutputsAndManifestByteForByte) {
  ScratchDir dir;
  const std::string box =
      std::string(BOOKSPIN_SOURCE_DIR) + "/scenes/flipcheck/mujoco-test-box.toml";
  const std::string exact = scene_path("exact-unstable-x");
  const std::string sweep_args =
      exact + " --set time.frames=20 --measure energy_drift --vary time.dt=0.01:0.02:";
  const std::vector<Case> cases = {
      // Seven files: five charts (tens of kB), two tables (a few kB).
      {"accuracy",
       "accuracy " + exact +
           " --flips 1 --dt 0.05 0.1 --methods rigid-quaternion:rk4,rigid-quaternion:euler",
       "accuracy " + exact + " --flips 1 --dt 0.05 0.1 --methods rigid-quaternion:rk4", 40},
      // The CSV (under 1 kB) and the picture.
      {"sweep", "sweep " + sweep_args + "3", "sweep " + sweep_args + "4", 8},
      // The JSON (about 1 kB) and the exact motion's CSV (about 100 kB).
      {"flipcheck export", "flipcheck export " + box,
       "flipcheck export " + box + " --set time.frames=41", 8},
      {"plot", "plot " + exact + " --set time.frames=20",
       "plot " + exact + " --set time.frames=20 --width 900", 8},
      {"export --gltf", "export --gltf " + exact + " --set time.frames=20",
       "export --gltf " + exact + " --set time.frames=21", 8},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const fs::path out = dir / (c.name.substr(0, c.name.find(' ')) + "-out");
    const SplitResult first = run_bookspin_split(c.first + " -o " + quoted(out));
    ASSERT_EQ(first.status, 0) << first.err;
    const auto before = snapshot(out);
    const SplitResult second =
        run_limited(c.second + " -o " + quoted(out), c.blocks, dir / "stderr.txt");
    EXPECT_EQ(second.status, 1) << second.out << second.err;
    EXPECT_NE(second.err.find("File too large"), std::string::npos) << second.err;
    EXPECT_NE(second.err.find(out.string()), std::string::npos) << second.err;
    EXPECT_EQ(changed(before, snapshot(out)), std::vector<std::string>{});
    EXPECT_EQ(temporaries(out), std::vector<std::string>{});
    // And the same run without the limit makes it: the failure was the limit's.
    const SplitResult again = run_bookspin_split(c.second + " -o " + quoted(out));
    EXPECT_EQ(again.status, 0) << again.err;
    EXPECT_NE(changed(before, snapshot(out)), std::vector<std::string>{});
  }
}

}  // namespace
}  // namespace bookspin::cli
