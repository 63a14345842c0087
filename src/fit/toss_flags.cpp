#include "fit/toss_flags.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "fit/median.hpp"
#include "fit/rigid_bounds.hpp"

namespace bookspin::fit {
namespace {

// The flags (docs/phone-lab.md, "Flags"): a 50 ms block of the residual over kBlockFactor times
// both the flight's median block and the noise at rest; or the median block over kNoFit of |ω|.
constexpr double kBlock = 0.05;
// The widest range of a phone's or a consumer IMU's gyroscope: ±4000 °/s (69.8 rad/s; most
// phones stop at ±2000 °/s, 34.9 rad/s). A sample beyond it cannot be a measurement: the
// recording is in other units (°/s) or scaled (docs/phone-lab.md, "Flags").
constexpr double kGyroRangeMax = 4000.0 * 3.14159265358979323846 / 180.0;
constexpr double kBlockFactor = 4.0;
// 5 %: between the clean throws of a bare phone in real air (1.0–1.8 % of |ω| with drag) and a
// fit with its flips visibly mistimed (8.8 %); the gyroscope's noise (0.005–0.03 rad/s) is 10–40
// times below a clean throw's residual, so it cannot set this one (docs/phone-lab.md, "Flags").
constexpr double kNoFit = 0.05;
// The clock test (docs/phone-lab.md, "Flags"): k1 + k2 + k3 + k1 k2 k3 measured on the samples
// is 0 for every rigid body's free flight; a clock running at 1/f of the true rate makes it
// k1 k2 k3 (1/f³ − 1/f). Measured: the flights of the development recordings as recorded, at
// most 0.047 (the derivative's and the gyroscope's own errors); re-stamped 1.5× or 2×, a bare
// phone's flights 0.16–0.17. Judged only where its σ is under kClockSigma (a stable toss's
// ω_j ω_k stays near 0 and leaves its k poorly determined).
constexpr double kClockMismatch = 0.1;
constexpr double kClockSigma = 0.05;
constexpr double kClockSignificance = 5.0;

/// The flag of one toss from its residual r_i = ω_fitted − ω_measured (docs/phone-lab.md,
/// "Flags"): 50 ms blocks' RMS against the median block and the noise at rest; empty for a
/// toss whose residual looks like noise and an unmodelled smooth remainder.
/// Each 50 ms block's RMS of `value` (at times `at`) over a flight [front, front + duration]
/// cut into `blocks`.
std::vector<double> block_rms(const std::vector<double>& at, const std::vector<double>& value,
                              double front, double duration, int blocks) {
  std::vector<double> sum2(blocks, 0.0);
  std::vector<int> count(blocks, 0);
  for (std::size_t i = 0; i < at.size(); ++i) {
    const int b = std::clamp(static_cast<int>((at[i] - front) / duration * blocks), 0, blocks - 1);
    sum2[b] += value[i] * value[i];
    ++count[b];
  }
  std::vector<double> rms(blocks, 0.0);
  for (int b = 0; b < blocks; ++b)
    if (count[b]) rms[b] = std::sqrt(sum2[b] / count[b]);
  return rms;
}

/// Whether the samples within a block of `worst` need a torque: the step torque's block RMS
/// over kBlockFactor × its median block. A residual that jumps where the samples are free is the
/// fitted motion drifting off (near the separatrix a small error in the body or ω0 grows
/// fastest), which kNoFit judges on the typical block, not a throw or a catch.
bool torque_near(const std::vector<double>& tau, const std::vector<double>& torque, int worst,
                 int blocks) {
  const double duration = tau.back() - tau.front();
  std::vector<double> mid(torque.size());
  for (std::size_t i = 0; i < torque.size(); ++i) mid[i] = 0.5 * (tau[i] + tau[i + 1]);
  const std::vector<double> rms = block_rms(mid, torque, tau.front(), duration, blocks);
  const double median = median_of(rms);
  for (int b = std::max(0, worst - 1); b <= std::min(blocks - 1, worst + 1); ++b)
    if (rms[b] > kBlockFactor * median) return true;
  return false;
}

/// What a toss's residual says (flag_of): the flag's words, and whether they are the residual's
/// "throughout" (its typical block over kNoFit of |ω|) rather than a jump's.
struct ResidualFlag {
  std::string text;
  bool throughout = false;
};

ResidualFlag flag_of(const std::vector<double>& tau, const std::vector<Eigen::Vector3d>& residual,
                     const std::vector<double>& torque, double mean_omega,
                     std::optional<double> noise) {
  const double duration = tau.back() - tau.front();
  const auto fixed = [](double value, int digits) {
    char text[32];
    std::snprintf(text, sizeof text, "%.*f", digits, value);
    return std::string(text);
  };
  // Blocks of 50 ms (at least 4 samples each).
  const int blocks = std::max(1, static_cast<int>(duration / kBlock));
  std::vector<double> block2(blocks, 0.0);
  std::vector<int> block_n(blocks, 0);
  for (std::size_t i = 0; i < tau.size(); ++i) {
    const int b =
        std::min(blocks - 1, static_cast<int>((tau[i] - tau.front()) / duration * blocks));
    block2[b] += residual[i].squaredNorm();
    ++block_n[b];
  }
  std::vector<double> block_rms;
  for (int b = 0; b < blocks; ++b)
    block_rms.push_back(block_n[b] ? std::sqrt(block2[b] / block_n[b]) : 0.0);
  // The typical block among those holding samples: where the samples lie further apart than a
  // block, the empty ones say nothing of the residual.
  std::vector<double> sorted;
  for (int b = 0; b < blocks; ++b)
    if (block_n[b]) sorted.push_back(block_rms[b]);
  const double median = median_of(std::move(sorted));
  const double floor = noise ? std::sqrt(3.0) * 5.0 * *noise : 0.0;  // |r| of 5σ per component
  int worst = 0;
  for (int b = 1; b < blocks; ++b)
    if (block_rms[b] > block_rms[worst]) worst = b;
  if (blocks >= 4 && block_rms[worst] > kBlockFactor * median && block_rms[worst] > floor &&
      torque_near(tau, torque, worst, blocks)) {
    const double at = tau.front() + (worst + 0.5) * duration / blocks;
    const std::string where = "the residual jumps to " + fixed(block_rms[worst], 2) +
                              " rad/s near t = " + fixed(at, 2) + " s of the flight (typical " +
                              fixed(median, 2) + ")";
    if (worst >= blocks - 2) return {"a catch inside the flight? " + where};
    if (worst <= 1) return {"the throw inside the flight? " + where};
    return {"a knock, or the phone slipping on the body? " + where};
  }
  // Throughout: the typical (median) 50 ms block, not the whole RMS, which a drift confined to
  // the flight's last 0.1 s lifts past kNoFit on its own (docs/phone-lab.md, "Flags").
  if (median > kNoFit * mean_omega)
    return {"a body that flexes, or not a free flight: the residual is " +
                fixed(100 * median / mean_omega, 1) + " % of |ω| throughout",
            true};
  return {};
}

/// What the fitted body's moments `inertia` (phone frame) say where no rigid body has them
/// (rigid_bounds.hpp's flagged_moments): the two smaller summing to less than the largest (less
/// 2 % of it), or a needle's (docs/physics.md §8); empty for a rigid body's.
std::string body_flag(const Eigen::Matrix3d& inertia) {
  const Eigen::Vector3d m = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(inertia).eigenvalues();
  if (!(m[2] > 0.0)) return "no rigid body has the fitted moments (not all positive)";
  char text[240];
  if (flagged_moments(m)) {
    // The two smaller short of the largest is also what a near-axisymmetric body's recording
    // with its stamps compressed gives (docs/physics.md §8: I1/I3 → 1/(1 + (I3/I1 − 1)/f), f < 1).
    std::snprintf(text, sizeof text,
                  "no rigid body has the fitted moments %.3g : %.3g : 1 (%s): a hand's motion "
                  "inside the flight, %sor not a free flight?",
                  m[0] / m[2], m[1] / m[2],
                  needle(m) ? "a needle's" : "the two smaller sum to less than the largest",
                  needle(m) ? "" : "its times compressed (a clock off its rate), ");
    return text;
  }
  return {};
}

/// The clock test (docs/phone-lab.md, "Flags"): Euler's equations in the fitted body's
/// principal frame, ω̇_a = k_a ω_b ω_c − r ω_a (a, b, c cyclic; k_a = (I_b − I_c)/I_a, r a drag
/// rate), each k_a measured by least squares on the samples' own derivative (omega_rate); every
/// rigid body's k obey k1 + k2 + k3 + k1 k2 k3 = 0, a time scaled by f makes each k_a/f, which
/// obey it only where k1 k2 k3 = 0 (an axisymmetric body's, whose stamps no body can check).
/// Empty where the samples agree, or say too little.
std::string clock_flag(const std::vector<double>& tau, const std::vector<Eigen::Vector3d>& omega,
                       const Eigen::Matrix3d& inertia) {
  const int n = static_cast<int>(tau.size());
  if (n < 10) return {};
  const Eigen::Matrix3d axes =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(inertia).eigenvectors();
  const std::vector<Eigen::Vector3d> rate = omega_rate(tau, omega);
  Eigen::Vector3d k, sigma;
  for (int a = 0; a < 3; ++a) {
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    Eigen::MatrixXd A(n, 2);
    Eigen::VectorXd y(n);
    for (int i = 0; i < n; ++i) {
      const Eigen::Vector3d w = axes.transpose() * omega[i];
      A(i, 0) = w[b] * w[c];
      A(i, 1) = w[a];
      y[i] = (axes.transpose() * rate[i])[a];
    }
    const Eigen::Matrix2d normal = A.transpose() * A;
    if (!(std::abs(normal.determinant()) > 0.0)) return {};
    const Eigen::Vector2d x = normal.ldlt().solve(A.transpose() * y);
    const double s2 = (A * x - y).squaredNorm() / (n - 2);
    k[a] = x[0];
    sigma[a] = std::sqrt(s2 * normal.inverse()(0, 0));
  }
  const double mismatch = k.sum() + k.prod();
  const double spread = std::sqrt(std::pow(sigma[0] * (1.0 + k[1] * k[2]), 2) +
                                  std::pow(sigma[1] * (1.0 + k[0] * k[2]), 2) +
                                  std::pow(sigma[2] * (1.0 + k[0] * k[1]), 2));
  if (!std::isfinite(mismatch) || !(spread < kClockSigma) ||
      !(std::abs(mismatch) > kClockMismatch) || !(std::abs(mismatch) > kClockSignificance * spread))
    return {};
  char text[300];
  std::snprintf(text, sizeof text,
                "no rigid body moves as the samples do: Euler's equations measured on them give "
                "k1 + k2 + k3 + k1 k2 k3 = %.3f ± %.3f, 0 for every rigid body: a clock running "
                "fast or slow (stamps scaled), or not a free flight?",
                mismatch, spread);
  return text;
}

}  // namespace

std::optional<double> rest_noise(const GyroRecording& recording, const FlightSearch& search) {
  const double rest = 0.5 * FinderSettings{}.rest_omega;
  std::size_t flight = 0;
  double sum2 = 0.0;
  int count = 0;
  for (const RecordingPart& part : recording.parts)
    for (int i = part.first; i <= part.last; ++i) {
      while (flight < search.flights.size() && search.flights[flight].last < i) ++flight;
      if (flight < search.flights.size() && search.flights[flight].first <= i) continue;
      const Eigen::Vector3d d = recording.omega[i] - part.bias;
      if (d.norm() > rest) continue;
      sum2 += d.squaredNorm();
      ++count;
    }
  if (count < 20) return std::nullopt;
  return std::sqrt(sum2 / (3.0 * count));
}

std::vector<double> step_torque(const std::vector<double>& tau,
                                const std::vector<Eigen::Vector3d>& omega,
                                const Eigen::Matrix3d& inertia) {
  std::vector<double> torque;
  if (omega.size() < 2) return torque;
  const double largest = inertia.cwiseAbs().maxCoeff() > 0
                             ? Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(inertia)
                                   .eigenvalues()
                                   .cwiseAbs()
                                   .maxCoeff()
                             : 1.0;
  for (std::size_t i = 0; i + 1 < omega.size(); ++i) {
    const double dt = tau[i + 1] - tau[i];
    const Eigen::Vector3d w = 0.5 * (omega[i] + omega[i + 1]);
    const double w2 = w.squaredNorm();
    if (!(dt > 0.0) || !(w2 > 0.0)) {
      torque.push_back(0.0);
      continue;
    }
    const Eigen::Vector3d tq = inertia * (omega[i + 1] - omega[i]) / dt + w.cross(inertia * w);
    torque.push_back(tq.norm() / (largest * w2));
  }
  return torque;
}

std::string toss_flag(const TossData& data, const std::vector<Eigen::Vector3d>& residual,
                      const Saturation& saturation, std::optional<double> noise,
                      const Eigen::Matrix3d& inertia) {
  const TossData& d = data;
  double mean_omega = 0.0;
  for (const Eigen::Vector3d& w : d.omega) mean_omega += w.norm() / d.omega.size();
  double peak_omega = 0.0;  // the largest component measured, rad/s
  for (const Eigen::Vector3d& w : d.omega)
    peak_omega = std::max(peak_omega, w.cwiseAbs().maxCoeff());
  const int at_range = d.at_range;  // the flight's samples at the range, left out or not
  if (peak_omega > kGyroRangeMax) {
    char text[200];
    std::snprintf(text, sizeof text,
                  "ω reaches %.4g rad/s, beyond any gyroscope's range (phones: ±2000 °/s, "
                  "34.9 rad/s; at most ±4000 °/s, 69.8 rad/s): a recording in °/s, or scaled?",
                  peak_omega);
    return text;
  }
  if (at_range > 0 && 4 * (d.samples - at_range) < d.samples) {  // under a quarter left
    char text[200];
    std::snprintf(text, sizeof text,
                  "gyroscope saturated: %d of the flight's %d samples read its range (±%.4g "
                  "rad/s), under a quarter left: too much of the motion is missing to trust "
                  "the fit",
                  at_range, d.samples, *saturation.range);
    return text;
  }
  const ResidualFlag said =
      flag_of(d.tau, residual, step_torque(d.tau, d.omega, inertia), mean_omega, noise);
  // A jump first; then a body no rigid object has, before a residual throughout: a fit that
  // ends at such a body leaves a residual throughout, and the body says why (docs/phone-lab.md,
  // "Flags"). A near-axisymmetric body's recording re-timed by f (a clock at 1/f of its rate) is
  // the axisymmetric body I1/I3 → 1/(1 + (I3/I1 − 1)/f) (docs/physics.md §8), which at f = 0.7
  // breaks the triangle inequality (the real book 0.51 : 0.53 : 1 → 0.42 : 0.42 : 1), while the
  // clock test sees f only through k1 k2 k3 (1/f³ − 1/f), 0.018 × 1.49 = 0.026 there, under the
  // scatter of k (±0.035).
  std::string flag = said.throughout ? std::string() : said.text;
  if (flag.empty()) flag = body_flag(inertia);
  if (flag.empty()) flag = said.text;
  if (flag.empty()) flag = clock_flag(d.tau, d.omega, inertia);
  if (!flag.empty() && d.saturated > 0) {  // the clip named beside what the rest shows
    char text[100];
    std::snprintf(text, sizeof text,
                  " (the gyroscope saturated: %d of its samples read its range, left out)",
                  d.saturated);
    flag += text;
  }
  return flag;
}

std::string scale_cause(const std::vector<TossData>& data) {
  Eigen::Vector3d peak = Eigen::Vector3d::Zero();
  for (const TossData& d : data)
    for (const Eigen::Vector3d& w : d.omega) peak = peak.cwiseMax(w.cwiseAbs());
  static const char* const kAxis[3] = {"ω_x", "ω_y", "ω_z"};
  std::string beyond, within;
  int beyond_count = 0;
  double inside = 0.0;  // the largest |ω| of the axes within the range
  for (int c = 0; c < 3; ++c) {
    if (peak[c] > kGyroRangeMax) {
      beyond += std::string(beyond.empty() ? "" : " and ") + kAxis[c];
      ++beyond_count;
    } else {
      within += std::string(within.empty() ? "" : " and ") + kAxis[c];
      inside = std::max(inside, peak[c]);
    }
  }
  if (beyond_count == 0) return {};
  char text[300];
  if (beyond_count == 3)
    std::snprintf(text, sizeof text,
                  "every axis of ω passes any gyroscope's range (±%.1f rad/s), up to %.4g rad/s: "
                  "a recording in °/s, or scaled?",
                  kGyroRangeMax, peak.maxCoeff());
  else
    std::snprintf(text, sizeof text,
                  "%s %s %.4g rad/s, beyond any gyroscope's range (±%.1f rad/s), while %s %s "
                  "within %.3g: %s in °/s, or scaled?",
                  beyond.c_str(), beyond_count == 1 ? "reaches" : "reach", peak.maxCoeff(),
                  kGyroRangeMax, within.c_str(), beyond_count == 1 ? "stay" : "stays", inside,
                  beyond_count == 1 ? "that axis" : "those axes");
  return text;
}

}  // namespace bookspin::fit
