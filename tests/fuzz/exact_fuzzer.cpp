// libFuzzer target for the exact motion (physics::ExactRotation, docs/physics.md §8, "How far in
// time"). Input: a mode byte, then either (even mode) raw doubles, 3 moments, 3 components of ω0
// and up to 4 times, every bit pattern (NaN, inf, subnormals, ±1e-300…1e308), or (odd mode) a
// seed for the structured draw of tests/support/exact_motion_property.hpp (moments across
// 1e-300…1e300, near-symmetric bodies, the separatrix, times up to and past the horizon). The
// property: finite states that keep E and |L|, starting at ω0 and the identity to rounding for
// every body however far apart its moments (docs/physics.md §8, "The phase by quarter periods"),
// or a refusal for the true cause; anything else (a broken property, a crash, another
// exception, a sanitizer report) is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>

#include "support/exact_motion_property.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  bookspin::test_support::ExactInput in;
  const std::uint8_t mode = data[0];
  ++data;
  --size;
  if (mode % 2 == 0) {
    auto next = [&](double& x) {
      if (size < sizeof x) return false;
      std::memcpy(&x, data, sizeof x);
      data += sizeof x;
      size -= sizeof x;
      return true;
    };
    for (int i = 0; i < 3; ++i)
      if (!next(in.moments[i])) return 0;
    for (int i = 0; i < 3; ++i)
      if (!next(in.omega0[i])) return 0;
    double t = 0.0;
    for (int n = 0; n < 4 && next(t); ++n) in.t.push_back(t);
  } else {
    std::uint64_t seed = 0;
    std::memcpy(&seed, data, size < sizeof seed ? size : sizeof seed);
    std::mt19937_64 rng(seed);
    in = bookspin::test_support::draw_exact_input(rng);
  }
  const std::string broken = bookspin::test_support::check_exact_property(in);
  if (!broken.empty()) {
    std::fprintf(stderr, "exact_fuzzer: %s\n", broken.c_str());
    std::abort();
  }
  return 0;
}
