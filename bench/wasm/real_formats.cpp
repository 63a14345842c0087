// What a wider-than-double real costs in WebAssembly (docs/performance-build.md, "npx flipcheck"):
// the same division-bound recurrence acc ← (acc·y + x)/(y + acc), the shape of the exact motion's
// kernels (Landen's descent, Carlson's duplication), in four formats: `long double` (x87's
// 80 bits in hardware natively, binary128 in software in WebAssembly), a double-double pair
// (Dekker's products and Knuth's sums, no FMA: WebAssembly's baseline has none) and double.
// Not built by CMake; by hand, one run each:
//   g++ -O2 bench/wasm/real_formats.cpp -o /tmp/real_formats && /tmp/real_formats
//   NODE_PATH=/usr/share/nodejs em++ -O3 -sSINGLE_FILE=1 -o /tmp/real_formats.js
//     bench/wasm/real_formats.cpp && node /tmp/real_formats.js   (one line)
#include <chrono>
#include <cstdio>

namespace {

struct DoubleDouble {
  double hi, lo;
};

DoubleDouble two_sum(double a, double b) {
  const double s = a + b, v = s - a;
  return {s, (a - (s - v)) + (b - v)};
}
DoubleDouble fast_two_sum(double a, double b) {
  const double s = a + b;
  return {s, b - (s - a)};
}
void split(double a, double& hi, double& lo) {
  const double t = 134217729.0 * a;  // 2^27 + 1
  hi = t - (t - a), lo = a - hi;
}
DoubleDouble two_product(double a, double b) {
  const double p = a * b;
  double ah, al, bh, bl;
  split(a, ah, al), split(b, bh, bl);
  return {p, ((ah * bh - p) + ah * bl + al * bh) + al * bl};
}
DoubleDouble operator+(DoubleDouble a, DoubleDouble b) {
  DoubleDouble s = two_sum(a.hi, b.hi);
  const DoubleDouble t = two_sum(a.lo, b.lo);
  s = fast_two_sum(s.hi, s.lo + t.hi);
  return fast_two_sum(s.hi, s.lo + t.lo);
}
DoubleDouble operator*(DoubleDouble a, DoubleDouble b) {
  const DoubleDouble p = two_product(a.hi, b.hi);
  return fast_two_sum(p.hi, p.lo + (a.hi * b.lo + a.lo * b.hi));
}
DoubleDouble operator/(DoubleDouble a, DoubleDouble b) {
  const double q1 = a.hi / b.hi;
  DoubleDouble r = a + b * DoubleDouble{-q1, 0.0};
  const double q2 = r.hi / b.hi;
  r = r + b * DoubleDouble{-q2, 0.0};
  return fast_two_sum(q1, q2) + DoubleDouble{r.hi / b.hi, 0.0};
}

template <class Real>
Real recurrence(Real x, Real y, int n) {
  Real acc = x;
  for (int i = 0; i < n; ++i) acc = (acc * y + x) / (y + acc);
  return acc;
}

}  // namespace

int main() {
  const int n = 20'000'000;
  const auto time = [](auto f) {
    const auto start = std::chrono::steady_clock::now();
    const double value = f();
    const auto stop = std::chrono::steady_clock::now();
    std::printf(" %.0f ms (%.17g)", std::chrono::duration<double, std::milli>(stop - start).count(),
                value);
  };
  std::printf("long double (%zu bytes):", sizeof(long double));
  time([&] { return static_cast<double>(recurrence<long double>(1.1L, 0.7L, n)); });
  std::printf("\ndouble-double:");
  time([&] { return recurrence(DoubleDouble{1.1, 0.0}, DoubleDouble{0.7, 0.0}, n).hi; });
  std::printf("\ndouble:");
  time([&] { return recurrence(1.1, 0.7, n); });
  std::printf("\n");
}
