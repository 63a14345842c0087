#pragma once
// Synthetic gyroscope recordings for the fit stage's tests, made independently of the code
// under test: the free flights are Euler's equations (docs/physics.md §8) integrated by RK4 at a
// fine step (not physics::ExactRotation), the half periods the closed form 2K(k)/λ evaluated
// with Boost's elliptic integral; around them rest with the gyroscope's bias and noise, a
// throw (a ramp with spikes), a catch (spikes, then rest), 100 Hz sampling with jitter, and
// pauses. Written in each CSV dialect phyphox exports.
#include <Eigen/Dense>
#include <algorithm>
#include <boost/math/special_functions/ellint_1.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "fit/pool.hpp"
#include "fit/recording.hpp"

namespace bookspin::fit::test {

struct SyntheticBody {
  Eigen::Vector3d moments;  ///< principal moments, ascending (any scale)
  Eigen::Matrix3d axes;     ///< columns: principal axes 1, 2, 3 in the phone frame
};

struct SyntheticToss {
  Eigen::Vector3d omega0_principal;  ///< rad/s, ω at release about principal axes 1, 2, 3
  double flight = 1.2;               ///< s of free flight
};

struct TrueToss {
  double t_start = 0, t_end = 0;  ///< the free flight, s
  double half_period = 0;         ///< T/2 = 2K(k)/λ, s
  Eigen::Vector3d omega0_phone;   ///< rad/s
};

struct SyntheticRecording {
  std::vector<double> t;
  std::vector<Eigen::Vector3d> omega;  ///< phone frame, bias and noise included
  std::vector<double> pauses;
  std::vector<TrueToss> tosses;
  Eigen::Vector3d bias;
};

/// ω̇ of Euler's equations, principal frame (docs/physics.md §8).
inline Eigen::Vector3d euler_rate(const Eigen::Vector3d& I, const Eigen::Vector3d& w) {
  return {(I[1] - I[2]) / I[0] * w[1] * w[2], (I[2] - I[0]) / I[1] * w[2] * w[0],
          (I[0] - I[1]) / I[2] * w[0] * w[1]};
}

/// Air drag on the flights, written from the torque alone (not from the stretched time of
/// docs/physics.md §21): τ = −r_eff · a ⊙ L (principal frame), r_eff = rate (linear) or
/// rate·|L|/|L0| (quadratic); a = (1, 1, 1) is the isotropic drag the fit models, another `a` an
/// anisotropic one it cannot fit.
struct SyntheticDrag {
  double rate = 0.0;  ///< 1/s: the initial loss of |L| per second (isotropic)
  bool quadratic = false;
  Eigen::Vector3d anisotropy = Eigen::Vector3d::Ones();
};

/// ω after `time` s from `w`, RK4 with steps of at most 1e-4 s, under `drag`: I ω̇ = (I ω) × ω + τ.
inline Eigen::Vector3d rk4(const Eigen::Vector3d& I, Eigen::Vector3d w, double time,
                           const SyntheticDrag& drag = {}) {
  const int steps = std::max(1, static_cast<int>(std::ceil(time / 1e-4)));
  const double h = time / steps;
  const double L0 = I.cwiseProduct(w).norm();
  const auto rate = [&](const Eigen::Vector3d& v) -> Eigen::Vector3d {
    const double r = drag.quadratic ? drag.rate * I.cwiseProduct(v).norm() / L0 : drag.rate;
    return euler_rate(I, v) - r * drag.anisotropy.cwiseProduct(v);
  };
  for (int s = 0; s < steps; ++s) {
    const Eigen::Vector3d k1 = rate(w), k2 = rate(w + 0.5 * h * k1), k3 = rate(w + 0.5 * h * k2),
                          k4 = rate(w + h * k3);
    w += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  return w;
}

/// T/2 = 2K(k)/λ for moments I1 < I2 < I3 and principal ω (Landau & Lifshitz §37).
inline double closed_form_half_period(const Eigen::Vector3d& I, const Eigen::Vector3d& w) {
  const Eigen::Vector3d L = I.cwiseProduct(w);
  const double L2 = L.squaredNorm(), E2 = w.dot(L);  // E2 = 2E
  const double I1 = I[0], I2 = I[1], I3 = I[2];
  double lambda2, k2;
  if (L2 > E2 * I2) {
    lambda2 = (I3 - I2) * (L2 - E2 * I1) / (I1 * I2 * I3);
    k2 = (I2 - I1) * (E2 * I3 - L2) / ((I3 - I2) * (L2 - E2 * I1));
  } else {
    lambda2 = (I2 - I1) * (E2 * I3 - L2) / (I1 * I2 * I3);
    k2 = (I3 - I2) * (L2 - E2 * I1) / ((I2 - I1) * (E2 * I3 - L2));
  }
  return 2.0 * boost::math::ellint_1(std::sqrt(k2)) / std::sqrt(lambda2);
}

/// A recording of `tosses` of `body`: 1.5 s rest, then per toss a throw (`throw_time` s, a ramp
/// to ω0 with Gaussian spikes of `throw_spikes` rad/s), the flight (under a linear isotropic
/// drag of rate `drag` 1/s, or under `air` where given: 0 is torque-free), sampled at `rate` Hz
/// with ±10 % jitter, the flight, a 0.12 s catch and 1.2 s rest; a pause after the second
/// toss's rest. The rest turns `rest_turn` (rad/s, phone frame: a hand not quite still) on top
/// of its wobble; the gyroscope reads `bias` (rad/s) on every sample, where given, else
/// (0.021, -0.014, 0.008).
inline SyntheticRecording make_recording(const SyntheticBody& body,
                                         const std::vector<SyntheticToss>& tosses,
                                         unsigned seed = 1, double noise = 0.01,
                                         double throw_time = 0.15, double throw_spikes = 4.0,
                                         double drag = 0.0, double rate = 100.0,
                                         std::optional<SyntheticDrag> air = std::nullopt,
                                         const Eigen::Vector3d& rest_turn = Eigen::Vector3d::Zero(),
                                         std::optional<Eigen::Vector3d> bias = std::nullopt) {
  const SyntheticDrag flight_drag = air ? *air : SyntheticDrag{drag};
  std::mt19937 random(seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  SyntheticRecording rec;
  rec.bias = bias ? *bias : Eigen::Vector3d(0.021, -0.014, 0.008);
  // The truth as a function of time, piece by piece.
  struct Piece {
    double t0, t1;
    int kind;              // 0 rest, 1 throw, 2 flight, 3 catch
    Eigen::Vector3d a, b;  // throw: 0 → b; flight: ω0 (principal) in a; catch: a → 0
  };
  std::vector<Piece> pieces;
  double now = 0.0;
  pieces.push_back({now, now + 1.5, 0, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()});
  now += 1.5;
  for (const SyntheticToss& toss : tosses) {
    const Eigen::Vector3d w0_phone = body.axes * toss.omega0_principal;
    pieces.push_back({now, now + throw_time, 1, Eigen::Vector3d::Zero(), w0_phone});
    now += throw_time;
    pieces.push_back({now, now + toss.flight, 2, toss.omega0_principal, Eigen::Vector3d::Zero()});
    rec.tosses.push_back({now, now + toss.flight,
                          closed_form_half_period(body.moments, toss.omega0_principal), w0_phone});
    const Eigen::Vector3d w_end =
        body.axes * rk4(body.moments, toss.omega0_principal, toss.flight, flight_drag);
    now += toss.flight;
    pieces.push_back({now, now + 0.12, 3, w_end, Eigen::Vector3d::Zero()});
    now += 0.12;
    pieces.push_back({now, now + 1.2, 0, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()});
    if (rec.tosses.size() == 2) rec.pauses.push_back(now + 0.6);
    now += 1.2;
  }
  double t = 0.0;
  std::size_t p = 0;
  while (t < now) {
    while (p + 1 < pieces.size() && t >= pieces[p].t1) ++p;
    const Piece& piece = pieces[p];
    const double s = (t - piece.t0) / (piece.t1 - piece.t0);
    Eigen::Vector3d w = Eigen::Vector3d::Zero();
    if (piece.kind == 0) {
      w = rest_turn +
          0.03 * Eigen::Vector3d(std::sin(3.1 * t), std::sin(2.3 * t + 1), std::sin(1.7 * t + 2));
    } else if (piece.kind == 1) {
      w = s * piece.b + throw_spikes * Eigen::Vector3d(gauss(random), gauss(random), gauss(random));
    } else if (piece.kind == 2) {
      w = body.axes * rk4(body.moments, piece.a, t - piece.t0, flight_drag);
    } else {
      w = (1.0 - s) * piece.a + 6.0 * Eigen::Vector3d(gauss(random), gauss(random), gauss(random));
    }
    rec.t.push_back(t);
    rec.omega.push_back(w + rec.bias +
                        noise * Eigen::Vector3d(gauss(random), gauss(random), gauss(random)));
    t += (1.0 + 0.1 * uniform(random)) / rate;
  }
  return rec;
}

enum class Dialect { comma, tab, semicolon };

/// `rec` as phyphox's `Raw Data.csv` in `dialect` (with the Absolute column), in scientific
/// notation.
inline std::string raw_data_csv(const SyntheticRecording& rec, Dialect dialect) {
  const char sep = dialect == Dialect::comma ? ',' : dialect == Dialect::tab ? '\t' : ';';
  const char* names[] = {"Time (s)", "Gyroscope x (rad/s)", "Gyroscope y (rad/s)",
                         "Gyroscope z (rad/s)", "Absolute (rad/s)"};
  std::ostringstream out;
  for (int c = 0; c < 5; ++c) out << (c ? std::string(1, sep) : "") << '"' << names[c] << '"';
  out << '\n';
  char cell[64];
  for (std::size_t i = 0; i < rec.t.size(); ++i) {
    const double values[] = {rec.t[i], rec.omega[i][0], rec.omega[i][1], rec.omega[i][2],
                             rec.omega[i].norm()};
    for (int c = 0; c < 5; ++c) {
      std::snprintf(cell, sizeof cell, "%.9E", values[c]);
      std::string text = cell;
      if (dialect == Dialect::semicolon)
        for (char& ch : text)
          if (ch == '.') ch = ',';
      out << (c ? std::string(1, sep) : "") << text;
    }
    out << '\n';
  }
  return out.str();
}

/// phyphox's `meta/time.csv` for `rec`: START, then PAUSE and START at each pause.
inline std::string time_csv(const SyntheticRecording& rec) {
  std::ostringstream out;
  out << "\"event\",\"experiment time\",\"system time\",\"system time text\"\n";
  out << "\"START\",0.000000000E0,1.739522102E9,\"2025-02-14 09:35:02.000 UTC+01:00\"\n";
  for (double pause : rec.pauses) {
    char cell[64];
    std::snprintf(cell, sizeof cell, "%.9E", pause);
    out << "\"PAUSE\"," << cell << ",1.739522200E9,\"2025-02-14 09:36:40.000 UTC+01:00\"\n";
    out << "\"START\"," << cell << ",1.739522300E9,\"2025-02-14 09:38:20.000 UTC+01:00\"\n";
  }
  return out.str();
}

/// Writes `rec` as a phyphox export folder `dir` (Raw Data.csv, meta/time.csv, meta/device.csv).
inline void write_export(const std::filesystem::path& dir, const SyntheticRecording& rec,
                         Dialect dialect) {
  std::filesystem::create_directories(dir / "meta");
  std::ofstream(dir / "Raw Data.csv", std::ios::binary) << raw_data_csv(rec, dialect);
  std::ofstream(dir / "meta" / "time.csv", std::ios::binary) << time_csv(rec);
  std::ofstream(dir / "meta" / "device.csv", std::ios::binary)
      << "\"property\",\"value\"\n\"deviceModel\",\"synthetic\"\n";
}

/// The three bodies of the tests. A phone alone: a 7 × 15 × 0.8 cm slab, principal axes the
/// phone's (y smallest, x intermediate, z largest).
inline SyntheticBody phone_alone() {
  const double a = 7.0, b = 15.0, c = 0.8;
  SyntheticBody body;
  body.moments = Eigen::Vector3d(a * a + c * c, b * b + c * c, a * a + b * b);  // y, x, z
  body.axes.col(0) = Eigen::Vector3d::UnitY();
  body.axes.col(1) = Eigen::Vector3d::UnitX();
  body.axes.col(2) = -Eigen::Vector3d::UnitZ();
  return body;
}

/// A phone taped askew on a book: moments 1 : 1.6 : 2.3, axes turned 20° about (1, 2, 3).
inline SyntheticBody phone_on_book() {
  SyntheticBody body;
  body.moments = Eigen::Vector3d(1.0, 1.6, 2.3);
  body.axes = Eigen::AngleAxisd(20.0 * M_PI / 180.0, Eigen::Vector3d(1, 2, 3).normalized())
                  .toRotationMatrix();
  return body;
}

/// A racquet-like body: a small moment about the handle, two nearly equal (0.9 and 1).
inline SyntheticBody racquet() {
  SyntheticBody body;
  body.moments = Eigen::Vector3d(0.1, 0.9, 1.0);
  body.axes = Eigen::AngleAxisd(10.0 * M_PI / 180.0, Eigen::Vector3d(0, 1, 1).normalized())
                  .toRotationMatrix();
  return body;
}

/// `synthetic` as the reader would give it (its times, ω and pauses), named `name` with the
/// source "<name>.csv", not yet pooled (its bias unmeasured).
inline GyroRecording as_read(const SyntheticRecording& synthetic,
                             const std::string& name = "synthetic") {
  GyroRecording recording;
  recording.name = name;
  recording.source = name + ".csv";
  recording.t = synthetic.t;
  recording.omega = synthetic.omega;
  recording.pauses = synthetic.pauses;
  return recording;
}

/// `synthetic` as the finder and the fit take it: as read, a pool of one (pool_recordings).
inline GyroRecording as_recording(const SyntheticRecording& synthetic,
                                  const std::string& name = "synthetic") {
  return pool_recordings({as_read(synthetic, name)});
}

/// ω of `recording` at time `at` (within its samples): a cubic Hermite curve through the samples
/// with each one's slope from its neighbours and their own times.
inline Eigen::Vector3d interpolated(const GyroRecording& recording, double at) {
  const std::vector<double>& t = recording.t;
  const std::vector<Eigen::Vector3d>& w = recording.omega;
  const std::size_t n = t.size();
  std::size_t i = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), at) - t.begin());
  i = std::clamp<std::size_t>(i, 1, n - 1) - 1;  // at in [t[i], t[i + 1]]
  const auto slope = [&](std::size_t k) -> Eigen::Vector3d {
    const std::size_t a = k == 0 ? 0 : k - 1, b = std::min(n - 1, k + 1);
    return (w[b] - w[a]) / (t[b] - t[a]);
  };
  const double h = t[i + 1] - t[i], s = (at - t[i]) / h;
  const double h00 = 2 * s * s * s - 3 * s * s + 1, h10 = s * s * s - 2 * s * s + s;
  const double h01 = -2 * s * s * s + 3 * s * s, h11 = s * s * s - s * s;
  return h00 * w[i] + h10 * h * slope(i) + h01 * w[i + 1] + h11 * h * slope(i + 1);
}

}  // namespace bookspin::fit::test
