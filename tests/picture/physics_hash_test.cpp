// Physics determinism: the diagnostics CSV that `bookspin simulate` writes for the first 100
// frames of every figure scene must hash to the value in tests/golden/physics_hashes.txt.
// Any change to a simulator, the jiggle or the CSV format shows up here as a physics
// failure, even where it moves the book too little for the picture goldens to see.
// BOOKSPIN_UPDATE_GOLDENS=1 rewrites the file (and says which hashes changed).
// The hash covers the 17 columns the CSV had when the hashes were made (frame …
// quaternion_norm); columns added later at the end (cos_smallest_L, cos_intermediate_L,
// cos_largest_L: docs/physics.md §9, §12) are cut off first, so the stored hashes still prove
// that every old column keeps bit-identical values.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

#include "golden_store.hpp"
#include "picture_scenes.hpp"

namespace bookspin::picture {
namespace {

constexpr int kHashedFrames = 100;
constexpr const char* kHashFile = "physics_hashes.txt";
constexpr int kHashedColumns = 17;  ///< frame … quaternion_norm
/// The other bodies' hashes were made with 20 columns (… cos_largest_L); the pose columns
/// appended since (q_w … com_z, docs/outputs.md) are cut off the same way.
constexpr int kBodyHashedColumns = 20;

/// Each line of `csv` cut to its first `columns` comma-separated fields (newlines kept).
std::string hashed_columns(const std::string& csv, int columns = kHashedColumns) {
  std::string out;
  out.reserve(csv.size());
  std::istringstream in(csv);
  for (std::string line; std::getline(in, line);) {
    std::size_t cut = std::string::npos;  // the comma after field kHashedColumns, if any
    for (int fields = 0, at = -1; fields < columns; ++fields) {
      cut = line.find(',', static_cast<std::size_t>(at + 1));
      if (cut == std::string::npos) break;
      at = static_cast<int>(cut);
    }
    out.append(line, 0, cut);
    if (!in.eof()) out.push_back('\n');
  }
  return out;
}

/// FNV-1a, 64 bit: tiny, fixed by its definition (std::hash is not), so the file holds.
std::uint64_t fnv1a64(const std::string& bytes) {
  std::uint64_t hash = 0xcbf29ce484222325ull;
  for (const unsigned char byte : bytes) hash = (hash ^ byte) * 0x100000001b3ull;
  return hash;
}

std::string hex(std::uint64_t value) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
  return text;
}

/// Standard output of `bookspin simulate scenes/<name>.toml` for the first frames.
std::string simulate_csv(const std::string& name, const std::string& extra = "") {
  const std::string command =
      std::string(BOOKSPIN_EXE) + " simulate " + BOOKSPIN_SOURCE_DIR + "/scenes/" + name +
      ".toml --set time.frames=" + std::to_string(kHashedFrames) + extra + " --csv - 2>/dev/null";
  std::string csv;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return csv;
  char buffer[4096];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) csv.append(buffer, n);
  const int status = pclose(pipe);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << command;
  return csv;
}

std::map<std::string, std::string> read_hashes(const std::filesystem::path& path) {
  std::map<std::string, std::string> hashes;
  std::ifstream in(path);
  for (std::string scene, hash; in >> scene >> hash;) hashes[scene] = hash;
  return hashes;
}

void write_hashes(const std::filesystem::path& path,
                  const std::map<std::string, std::string>& hashes) {
  std::ofstream out(path, std::ios::trunc);
  for (const auto& [scene, hash] : hashes) out << scene << ' ' << hash << '\n';
  if (!out) ADD_FAILURE() << "cannot write " << path;
}

/// Update mode: the line printed for one scene.
std::string change(const std::map<std::string, std::string>& old, const std::string& scene,
                   const std::string& hash) {
  const auto it = old.find(scene);
  if (it == old.end()) return "new";
  return it->second == hash ? "unchanged" : "changed (was " + it->second + ")";
}

TEST(PhysicsHash, HashedColumnsAreTheSeventeenOldOnes) {
  // A CSV in the old 17-column format is hashed as it is, so the stored hashes (made from
  // such files) still apply; the three columns appended since are cut off, nothing else.
  const std::string old_csv =
      "frame,t,omega_x,omega_y,omega_z,L_x,L_y,L_z,energy_kinetic,energy_potential,"
      "energy_total,cos_x_L,cos_y_L,cos_z_L,strain_max,orthogonality_error,quaternion_norm\n"
      "0,0,0.1,0,0,1,0,0,0.5,0,0.5,1,0,0,0,0,1\n"
      "1,0.1,0.1,-0,2e-05,1,0,0,0.5,0,0.5,0.99,-0.01,0,1e-17,3e-16,1\n";
  EXPECT_EQ(hashed_columns(old_csv), old_csv);
  const std::string new_csv =
      "frame,t,omega_x,omega_y,omega_z,L_x,L_y,L_z,energy_kinetic,energy_potential,"
      "energy_total,cos_x_L,cos_y_L,cos_z_L,strain_max,orthogonality_error,quaternion_norm,"
      "cos_smallest_L,cos_intermediate_L,cos_largest_L\n"
      "0,0,0.1,0,0,1,0,0,0.5,0,0.5,1,0,0,0,0,1,0,1,0\n"
      "1,0.1,0.1,-0,2e-05,1,0,0,0.5,0,0.5,0.99,-0.01,0,1e-17,3e-16,1,-0.01,0.99,0\n";
  EXPECT_EQ(hashed_columns(new_csv), old_csv);
  EXPECT_EQ(hex(fnv1a64(hashed_columns(new_csv))), hex(fnv1a64(old_csv)));
}

TEST(PhysicsHash, FirstHundredFramesOfEveryFigureAreUnchanged) {
  note_golden_used(kHashFile);
  const auto path = golden_dir() / kHashFile;
  const auto expected = read_hashes(path);
  std::map<std::string, std::string> actual;
  for (const std::string& scene : figure_scene_names()) {
    const std::string csv = simulate_csv(scene);
    ASSERT_GT(csv.size(), 1000u) << scene << ": `bookspin simulate` wrote no CSV";
    actual[scene] = hex(fnv1a64(hashed_columns(csv)));
  }
  // The other bodies (docs/physics.md §12, §13), the first 20 columns: the presets' rigid and exact
  // runs, and the T-handle's lattice (8 cells, to keep the test short).
  const std::string lattice =
      " --set model.kind='\"particle\"' --set model.integrator='\"velocity-verlet\"'"
      " --set model.damping=false --set model.spring_constant=10000.0 --set model.lattice_cells=8"
      " --set time.dt=0.00025 --set time.steps_per_frame=40";
  const std::pair<std::string, std::string> bodies[] = {{"t-handle-dzhanibekov", ""},
                                                        {"tennis-racket", ""},
                                                        {"phone-flip", ""},
                                                        {"t-handle-dzhanibekov", lattice}};
  for (const auto& [scene, extra] : bodies) {
    const std::string csv = simulate_csv(scene, extra);
    ASSERT_GT(csv.size(), 1000u) << scene << ": `bookspin simulate` wrote no CSV";
    actual[extra.empty() ? scene : "t-handle-lattice"] =
        hex(fnv1a64(hashed_columns(csv, kBodyHashedColumns)));
  }
  if (update_mode()) {
    for (const auto& [scene, hash] : actual)
      std::cout << "physics hash " << scene << ": " << change(expected, scene, hash) << '\n';
    write_hashes(path, actual);
    return;
  }
  ASSERT_FALSE(expected.empty()) << "no " << path << "; run `make update-goldens` to create it";
  for (const auto& [scene, hash] : actual) {
    const auto it = expected.find(scene);
    EXPECT_TRUE(it != expected.end() && it->second == hash)
        << scene << ": the first " << kHashedFrames << " frames' diagnostics CSV hashes to " << hash
        << ", " << path.filename().string() << " says "
        << (it == expected.end() ? std::string("nothing") : it->second)
        << ": the simulation changed. If intended: make update-goldens";
  }
}

}  // namespace
}  // namespace bookspin::picture
