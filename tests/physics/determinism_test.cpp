// Physics determinism, in process: each of the paper's methods, run from the original
// program's settings (docs/physics.md §6) with the seeded jiggle, must reproduce its states
// bit for bit. The hash covers the 3×8 corners and every diagnostic every 30 steps, so any
// change to a simulator, an integrator's arithmetic order, the jiggle or the initial state
// shows here — also where the book moves too little for the picture goldens to see. The
// end-to-end twin (the CSV that `bookspin simulate` writes, tests/golden/physics_hashes.txt)
// pins the same runs through the scene parser and the CSV format.
//
// A deliberate change of the physics changes these numbers: check why, then paste the new
// hash from the failure message.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>

#include "model_helpers.hpp"

namespace bookspin::physics {
namespace {

using testing::config;
using testing::original_book;

/// FNV-1a, 64 bit, over the bytes of doubles: fixed by its definition, unlike std::hash.
class StateHash {
 public:
  void add(double value) {
    std::uint64_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    for (int byte = 0; byte < 8; ++byte) hash_ = (hash_ ^ ((bits >> (8 * byte)) & 0xff)) * kPrime;
  }
  template <typename Matrix>
  void add_all(const Matrix& m) {
    for (Eigen::Index i = 0; i < m.size(); ++i) add(m.data()[i]);
  }
  std::string hex() const {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash_));
    return text;
  }

 private:
  static constexpr std::uint64_t kPrime = 0x100000001b3ull;
  std::uint64_t hash_ = 0xcbf29ce484222325ull;
};

struct HashedRun {
  const char* name;
  ModelConfig model;
  double dt;
  const char* expected_hash;
};

std::string hash_of(const HashedRun& run, long steps) {
  auto sim = make_simulator(original_book(), run.model);
  sim->reset(InitialState{{0.114819, 0.0, 0.0}, 0.001, 2012});
  StateHash hash;
  const bool finite = testing::run(*sim, run.dt, steps, 30, [&](const Simulator& s) {
    const Pose pose = s.pose();
    const Diagnostics& d = pose.diagnostics;
    hash.add_all(pose.corners);
    hash.add_all(d.omega_body);
    hash.add_all(d.L);
    hash.add_all(d.cos_axis_L);
    for (double v : {d.t, d.energy_kinetic, d.energy_potential, d.energy_total, d.strain_max,
                     d.orthogonality_error, d.quaternion_norm})
      hash.add(v);
  });
  EXPECT_TRUE(finite || !run.model.normalize) << run.name << " diverged";
  return hash.hex();
}

ModelConfig euler(ModelKind kind, bool normalize, bool damping = true) {
  ModelConfig c = config(kind, normalize, damping);
  c.integrator = Integrator::euler;
  return c;
}

// The paper's Euler methods of figures 5–12, 3000 steps (50 time units, a quarter flip).
const HashedRun kRuns[] = {
    {"particle, normalized, damped (fig. 5)", euler(ModelKind::particle, true), 1.0 / 60,
     "49b257ffdef3da64"},
    {"particle, not normalized (fig. 7)", euler(ModelKind::particle, false), 1.0 / 60,
     "0b71d1180e607847"},
    {"particle, undamped (fig. 6)", euler(ModelKind::particle, true, false), 1.0 / 60,
     "98a45b394e5c28c9"},
    {"matrix, SVD (fig. 9)", euler(ModelKind::rigid_matrix, true), 1.0 / 60, "1f125572176dac3c"},
    {"matrix, no SVD (fig. 10)", euler(ModelKind::rigid_matrix, false), 1.0 / 60,
     "20eb3d47cf97566b"},
    {"quaternion, normalized", euler(ModelKind::rigid_quaternion, true), 1.0 / 60,
     "875b6de5520c5a3b"},
    {"quaternion, not normalized (fig. 11)", euler(ModelKind::rigid_quaternion, false), 0.05,
     "adafccfb95acf08a"},
};

TEST(Determinism, ThePapersMethodsReproduceTheirStatesBitForBit) {
  for (const HashedRun& run : kRuns) EXPECT_EQ(hash_of(run, 3000), run.expected_hash) << run.name;
}

TEST(Determinism, TheHashSeesASmallChange) {
  // A time step one ulp longer must change the hash: the hash is not blind.
  HashedRun run = kRuns[3];
  const std::string base = hash_of(run, 300);
  run.dt = std::nextafter(run.dt, 1.0);
  EXPECT_NE(hash_of(run, 300), base);
}

}  // namespace
}  // namespace bookspin::physics
