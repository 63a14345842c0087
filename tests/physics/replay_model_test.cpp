// The replayed motion (docs/physics.md §20) against closed forms and independent integrations:
// a constant ω against the rotation about a fixed axis, one Magnus step of a linear ω against
// RK4 with tiny steps, an exact torque-free motion sampled like a gyroscope against
// ExactRotation's own orientation, and the simulator's pose and diagnostics.
#include "physics/replay_model.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "physics/presets.hpp"
#include "physics/shape.hpp"

namespace bookspin::physics {
namespace {

/// The angle of the rotation A·Bᵀ (radians): how far apart two orientations are.
double angle_between(const Eigen::Matrix3d& A, const Eigen::Matrix3d& B) {
  return Eigen::AngleAxisd(A * B.transpose()).angle();
}

/// Times from 0 to `end` whose steps are `h` each ± 30 % (seeded): a gyroscope's jitter.
std::vector<double> uneven_times(double end, double h, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(0.7, 1.3);
  std::vector<double> t{0.0};
  while (t.back() < end) t.push_back(t.back() + h * jitter(rng));
  return t;
}

TEST(OmegaReplay, ConstantOmegaIsTheRotationAboutAFixedAxis) {
  // R(t) = exp(t[ω]×) = the rotation by |ω| t about ω (closed form); the Magnus step of a
  // constant ω is that rotation exactly, so only round-off (a few 1e-16 a step) separates them.
  const Eigen::Vector3d w(3.0, -17.0, 5.0);
  const std::vector<double> t = uneven_times(1.5, 0.01, 7);
  std::vector<Eigen::Vector3d> omega(t.size(), w);
  std::vector<double> shifted = t;
  for (double& ti : shifted) ti += 4.25;  // the recording's clock: R(t[0]) = I regardless
  const OmegaReplay replay(shifted, omega);
  for (double tau : {0.0, 0.0033, 0.5, 0.777, 1.2345, t.back(), t.back() + 0.3}) {
    const Eigen::Matrix3d closed = Eigen::AngleAxisd(w.norm() * tau, w.normalized()).matrix();
    EXPECT_LT(angle_between(replay.orientation(tau), closed), 1e-12) << tau;
    EXPECT_LT((replay.omega(tau) - w).norm(), 1e-12) << tau;
  }
}

/// One step of dR/dt = R[ω]× for ω going linearly from `w0` to `w1` over `h`, integrated
/// independently by classical RK4 with `n` substeps.
Eigen::Matrix3d rk4_linear_omega(const Eigen::Vector3d& w0, const Eigen::Vector3d& w1, double h,
                                 int n) {
  const auto rate = [&](const Eigen::Matrix3d& R, double s) -> Eigen::Matrix3d {
    return R * cross_matrix(w0 + (w1 - w0) * (s / h));
  };
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  const double k = h / n;
  for (int i = 0; i < n; ++i) {
    const double s = i * k;
    const Eigen::Matrix3d k1 = rate(R, s), k2 = rate(R + 0.5 * k * k1, s + 0.5 * k),
                          k3 = rate(R + 0.5 * k * k2, s + 0.5 * k), k4 = rate(R + k * k3, s + k);
    R += k / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  }
  return R;
}

TEST(OmegaReplay, OneStepOfALinearOmegaIsFourthOrder) {
  // ω(t) = ω0 + (ω1 − ω0) t/h over one step, integrated independently by RK4 with 20000
  // substeps (its error ~ (|ω| h/20000)⁴ · |ω| h, below 1e-15). The Magnus step keeps the
  // integral of ω and the commutator term (h²/12)|ω0 × ω1| (≈ 6e-3 rad here); what it drops
  // (the third Magnus term on) is O(h⁵): ~1 % of the kept term at |ω| h ≈ 0.3, and 32 times
  // smaller for each halving of h (ω's slope kept). Without the commutator term, or with its
  // sign wrong, the error would be the size of the term itself.
  const Eigen::Vector3d w0(2.0, 25.0, 1.0), slope(-1667.0, -417.0, 417.0);  // rad/s, rad/s²
  std::vector<double> errors;
  for (double h : {0.012, 0.006, 0.003}) {
    const Eigen::Vector3d w1 = w0 + slope * h;
    const Eigen::Matrix3d R = rk4_linear_omega(w0, w1, h, 20000);
    const Eigen::Vector3d theta = OmegaReplay::step_rotation(w0, w1, h);
    const Eigen::Matrix3d magnus = Eigen::AngleAxisd(theta.norm(), theta.normalized()).matrix();
    const double commutator = h * h / 12.0 * w0.cross(w1).norm();
    errors.push_back(angle_between(magnus, R));
    EXPECT_LT(errors.back(), 0.02 * commutator) << "h = " << h;
    // The replay takes the same step between two samples.
    const OmegaReplay replay({0.0, h}, {w0, w1});
    EXPECT_LT(angle_between(replay.orientation(h), magnus), 1e-14);
  }
  EXPECT_GT(errors[0] / errors[1], 24.0) << errors[0] << ", " << errors[1];
  EXPECT_GT(errors[1] / errors[2], 24.0) << errors[1] << ", " << errors[2];
}

TEST(OmegaReplay, BetweenTwoSamplesTheStepEndsAtOmegaOfThatTime) {
  // Between samples i and i + 1 the replay turns R_i by the Magnus step from ω_i to ω(t) (ω
  // linear between them), not to ω_{i+1}: checked at 40 % and 80 % of the interval against RK4
  // of the linear ω over [t_i, t], to the Magnus step's own O(h⁵).
  const Eigen::Vector3d w0(2.0, 25.0, 1.0), slope(-1667.0, -417.0, 417.0);  // rad/s, rad/s²
  const double h = 0.006;
  const OmegaReplay replay({0.0, h, 2 * h}, {w0, w0 + slope * h, w0 + 2.0 * slope * h});
  for (double t : {0.4 * h, 0.8 * h, 1.4 * h}) {
    const double start = t > h ? h : 0.0;
    const Eigen::Vector3d w_start = w0 + slope * start, w_t = w0 + slope * t;
    const Eigen::Matrix3d R =
        replay.orientation(start) * rk4_linear_omega(w_start, w_t, t - start, 20000);
    const double commutator = (t - start) * (t - start) / 12.0 * w_start.cross(w_t).norm();
    EXPECT_LT(angle_between(replay.orientation(t), R), 0.02 * commutator + 1e-13) << "t = " << t;
  }
}

TEST(OmegaReplay, ASampledExactTossMatchesTheExactOrientation) {
  // A phone's moments (7 × 15 × 0.8 cm slab: 0.1812 : 0.8235 : 1) thrown about its intermediate
  // axis (principal y) at 18 rad/s: two flips in 1.3 s. ω sampled as a gyroscope does, every
  // h = 10 ms ± 30 %, and replayed. The replay's ω is the samples' linear interpolant, whose
  // integral over a step of length h_i misses the true one by the trapezoid rule's error
  // h_i³/12 · |ω̈| at most (Hairer, Nørsett & Wanner I, §II.1); the Magnus step's own error is
  // O(h⁵) (OneStepOfALinearOmegaIsFourthOrder). Each step's angle error carries on unchanged
  // (rotations keep lengths), so after time T the orientation is within
  //   Σ h_i³/12 · max|ω̈| ≤ T · h_max²/12 · max|ω̈|,
  // and a time between samples adds the partial step's ≤ h_max³ · max|ω̈| (its end value
  // interpolated: ≤ h²/8 · |ω̈| off, times h/2). max|ω̈| is taken from ExactRotation's analytic
  // ω̇ by differences on a fine grid. The bound is ~0.05 rad here; the replay does far better
  // (the errors of a periodic ω̈ mostly cancel), and the test asks for the bound.
  const Eigen::Vector3d moments(0.1812, 0.8235, 1.0);
  const Eigen::Vector3d omega0(1.0, 18.0, 1.2);
  const ExactRotation exact(moments, omega0);
  const double T = 1.3;
  const std::vector<double> t = uneven_times(T, 0.01, 11);
  std::vector<Eigen::Vector3d> omega;
  double h_max = 0.0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    omega.push_back(exact.omega_body(t[i]));
    if (i > 0) h_max = std::max(h_max, t[i] - t[i - 1]);
  }
  double omega_ddot = 0.0;
  const double d = 1e-5;
  for (double s = 0.0; s <= t.back(); s += 1e-3)
    omega_ddot = std::max(
        omega_ddot, ((exact.omega_dot_body(s + d) - exact.omega_dot_body(s - d)) / (2 * d)).norm());
  const double bound =
      t.back() * h_max * h_max / 12.0 * omega_ddot + h_max * h_max * h_max * omega_ddot;
  ASSERT_GT(exact.period(), 0.5);  // a flipping motion, not a steady spin
  ASSERT_LT(bound, 0.1);
  const OmegaReplay replay(t, omega);
  double worst = 0.0;
  for (double s = 0.0; s <= t.back(); s += 0.0037) {
    const double error = angle_between(replay.orientation(s), exact.orientation(s));
    worst = std::max(worst, error);
    EXPECT_LT(error, bound) << "t = " << s;
    // ω between samples is the linear interpolant: within h²/8 · max|ω̈| of the true ω.
    EXPECT_LT((replay.omega(s) - exact.omega_body(s)).norm(), h_max * h_max / 8.0 * omega_ddot)
        << "t = " << s;
  }
  // With a fourth of the step the bound, and the error, shrink by about 16 (second order).
  const std::vector<double> fine = uneven_times(T, 0.0025, 11);
  std::vector<Eigen::Vector3d> fine_omega;
  for (double s : fine) fine_omega.push_back(exact.omega_body(s));
  const OmegaReplay fine_replay(fine, fine_omega);
  double fine_worst = 0.0;
  for (double s = 0.0; s <= t.back(); s += 0.0037)
    fine_worst =
        std::max(fine_worst, angle_between(fine_replay.orientation(s), exact.orientation(s)));
  EXPECT_LT(fine_worst, worst / 8.0) << worst << " then " << fine_worst;
}

TEST(OmegaReplay, RejectsBadSamples) {
  const Eigen::Vector3d w(1, 2, 3);
  EXPECT_THROW(OmegaReplay({0.0}, {w}), std::invalid_argument);
  EXPECT_THROW(OmegaReplay({0.0, 0.0}, {w, w}), std::invalid_argument);
  EXPECT_THROW(OmegaReplay({0.0, 1.0}, {w, Eigen::Vector3d(NAN, 0, 0)}), std::invalid_argument);
  EXPECT_THROW(OmegaReplay({0.0, 1.0}, {w}), std::invalid_argument);
}

/// A rotation taking the principal axes askew (columns: the axes in the motion frame).
Eigen::Matrix3d askew_axes() {
  return (Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized()) *
          Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()))
      .matrix();
}

TEST(ExactInFrame, IsTheExactMotionToldInAnotherFrame) {
  // In the motion frame: R(0) = I, ω(0) = ω0, and the world L = R(t)·I·ω(t) fixed, with
  // I = A·diag(moments)·Aᵀ; ω(t) = A·ω_p(t) of the principal frame's exact motion.
  const Eigen::Matrix3d A = askew_axes();
  const Eigen::Vector3d moments(0.2, 0.8, 1.0), omega0(3.0, 15.0, -2.0);
  const ExactInFrame motion(A, moments, omega0);
  const ExactRotation principal(moments, A.transpose() * omega0);
  const Eigen::Matrix3d inertia = A * moments.asDiagonal() * A.transpose();
  EXPECT_LT(angle_between(motion.orientation(0.0), Eigen::Matrix3d::Identity()), 1e-12);
  EXPECT_LT((motion.omega(0.0) - omega0).norm(), 1e-12);
  const Eigen::Vector3d L0 = inertia * omega0;
  for (double t : {0.1, 0.45, 1.0, 2.3}) {
    const Eigen::Vector3d L = motion.orientation(t) * inertia * motion.omega(t);
    EXPECT_LT((L - L0).norm(), 1e-9 * L0.norm()) << t;
    EXPECT_LT((motion.omega(t) - A * principal.omega_body(t)).norm(), 1e-12) << t;
  }
}

TEST(ReplayModel, DrawsTheBodyPlacedInTheMotionFrame) {
  // The phone preset placed by its own built axes (Body::principal_axes) in a motion frame
  // turning at a constant ω: corners = R(t)·placement·cage, ω in the body frame placementᵀ·ω,
  // the energy ½ ω·I·ω with the motion frame's inertia, t = n·dt.
  const Body body = preset_body(BodyShape::phone);
  const Eigen::Matrix3d placement = body.principal_axes.transpose();
  const Eigen::Vector3d w(0.5, 12.0, -1.0);
  auto motion = std::make_shared<OmegaReplay>(std::vector<double>{0.0, 0.5, 2.0},
                                              std::vector<Eigen::Vector3d>{w, w, w});
  const Eigen::Matrix3d inertia =
      askew_axes() * Eigen::Vector3d(0.2, 0.8, 1.0).asDiagonal() * askew_axes().transpose();
  ReplayModel model(body, placement, inertia, motion);
  model.reset(InitialState{});
  for (int i = 0; i < 30; ++i) model.step(1.0 / 120);
  EXPECT_DOUBLE_EQ(model.time(), 30 * (1.0 / 120));
  const Eigen::Matrix3d R = Eigen::AngleAxisd(w.norm() * model.time(), w.normalized()).matrix();
  const Corners expected = R * placement * body.cage.body_corners();
  EXPECT_LT((model.corners() - expected).cwiseAbs().maxCoeff(), 1e-12);
  const Diagnostics d = model.pose().diagnostics;
  EXPECT_LT((d.omega_body - placement.transpose() * w).norm(), 1e-12);
  EXPECT_NEAR(d.energy_total, 0.5 * w.dot(inertia * w), 1e-12);
  EXPECT_LT((d.L - R * inertia * w).norm(), 1e-11);
  EXPECT_LT(d.strain_max, 1e-12);
  EXPECT_TRUE(model.finite());
  // The phone's built frame is the phone's: its long side (2.94) along y, the screen along z.
  const Eigen::Matrix3Xd built = placement * body.vertices;
  const Eigen::Vector3d extent = built.rowwise().maxCoeff() - built.rowwise().minCoeff();
  EXPECT_NEAR(extent.y(), 2.94, 1e-9);
  EXPECT_NEAR(extent.x(), 1.42, 1e-9);
  EXPECT_THROW(ReplayModel(body, 2.0 * placement, inertia, motion), std::invalid_argument);
}

}  // namespace
}  // namespace bookspin::physics
