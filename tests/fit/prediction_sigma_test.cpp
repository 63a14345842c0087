// A predicted half period's σ against an independent propagation (docs/phone-lab.md,
// "Prediction intervals"): each term is its input's σ times the derivative of T/2 with respect to
// that input, the derivative taken here by central differences of T/2 itself (motion_half_period
// over physics::DampedExactRotation, not the σ's own code), on a noise-free toss whose fitted
// values are the truth; each term vanishes with its input's σ, scales with it, and the whole
// scales with the recording's clock (stamps × a, ω ÷ a: T/2 and every σ × a); the held drag
// rate is the other tosses' inverse-variance mean.
#include "fit/prediction_sigma.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <vector>

#include "fit/half_period.hpp"
#include "physics/damped_exact.hpp"

namespace bookspin::fit {
namespace {

using physics::DragLaw;

/// A toss sampled at 100 Hz for 1.5 s (times × `a`), its ω the exact damped motion's (÷ `a`),
/// every component of each sample moved by ±`noise` in turn (the fitted motion's residual).
struct Case {
  Eigen::Vector3d moments{0.45, 0.72, 1.0};
  Eigen::Matrix3d axes;
  Eigen::Vector3d w0;  ///< rad/s, phone frame
  double rate = 0.12;  ///< 1/s, linear law
  double a = 1.0;      ///< the clock's scale
  TossData d;
  Parameters p;
  SolveOptions options;

  explicit Case(double scale = 1.0, double noise = 0.0) : a(scale) {
    axes = Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    w0 = axes * Eigen::Vector3d(0.9, 13.0, 1.1) / a;
    rate /= a;
    for (int i = 0; i <= 150; ++i) {
      const double tau = 0.01 * i * a;
      d.tau.push_back(tau);
      const double sign = i % 2 ? 1.0 : -1.0;
      d.omega.push_back(omega(moments, w0, rate, tau) + sign * noise / a * Eigen::Vector3d::Ones());
    }
    d.samples = static_cast<int>(d.tau.size());
    p.R0 = axes;
    p.log_ratios = {std::log(moments[0]), std::log(moments[1])};
    p.omega0 = {{w0[0], w0[1], w0[2], rate}};
    options.body_fixed = options.moments_fixed = options.rates_fixed = true;
    options.drag = DragLaw::linear;
    options.window = 0.3 * a;
  }
  Eigen::Vector3d omega(const Eigen::Vector3d& m, const Eigen::Vector3d& w, double r,
                        double tau) const {
    const physics::DampedExactRotation motion(m, axes.transpose() * w, {DragLaw::linear, r},
                                              physics::ExactParts::omega_only);
    return axes * motion.omega_body(tau);
  }
  /// T/2 over the toss's times, straight from the public motion and motion_half_period.
  double half(const Eigen::Vector3d& m, const Eigen::Vector3d& w, double r) const {
    const physics::DampedExactRotation motion(m, axes.transpose() * w, {DragLaw::linear, r},
                                              physics::ExactParts::omega_only);
    const std::optional<double> h = motion_half_period(motion, axes, d.tau);
    EXPECT_TRUE(h.has_value());
    return h.value_or(0.0);
  }
  double half() const { return half(moments, w0, rate); }
  /// ∂(T/2)/∂x by central differences with step `h`, for x the moment i (0, 1), ω0's phone
  /// component c (2, 3, 4) or the drag rate (5).
  double derivative(int x, double h) const {
    Eigen::Vector3d m_lo = moments, m_hi = moments, w_lo = w0, w_hi = w0;
    double r_lo = rate, r_hi = rate;
    if (x < 2) m_lo[x] -= h, m_hi[x] += h;
    if (x >= 2 && x < 5) w_lo[x - 2] -= h, w_hi[x - 2] += h;
    if (x == 5) r_lo -= h, r_hi += h;
    return (half(m_hi, w_hi, r_hi) - half(m_lo, w_lo, r_lo)) / (2.0 * h);
  }
  PredictionSigma sigma(const PredictionInputs& inputs) const {
    const std::optional<PredictionSigma> s = prediction_sigma(d, p, p, options, inputs, half());
    EXPECT_TRUE(s.has_value());
    return s.value_or(PredictionSigma{});
  }
};

PredictionInputs inputs_of(const Eigen::Vector3d& ratio, const Eigen::Vector3d& bias, double rate,
                           double a = 1.0) {
  PredictionInputs in;
  in.drag = DragLaw::linear;
  in.ratio_sigma = ratio;
  in.bias_sigma = bias / a;
  in.rate_sigma = rate / a;
  return in;
}

const Eigen::Vector3d kRatioSigma{0.004, 0.006, 0.0};
const Eigen::Vector3d kBiasSigma{0.012, 0.02, 0.015};
constexpr double kRateSigma = 0.015;

/// The terms a linear propagation gives: σ_x |∂(T/2)/∂x| per input, in quadrature per term.
struct Expected {
  double omega0, body, rate;
};
Expected linear_terms(const Case& c, const Eigen::Vector3d& ratio, const Eigen::Vector3d& omega0,
                      double rate) {
  Expected e{};
  for (int i = 0; i < 2; ++i) e.body += std::pow(ratio[i] * c.derivative(i, 0.25 * ratio[i]), 2);
  for (int k = 0; k < 3; ++k)
    e.omega0 += std::pow(omega0[k] * c.derivative(2 + k, 0.25 * omega0[k]), 2);
  e.body = std::sqrt(e.body), e.omega0 = std::sqrt(e.omega0);
  e.rate = std::abs(rate * c.derivative(5, 0.25 * rate));
  return e;
}

TEST(PredictionSigma, EachTermIsItsInputsSigmaTimesTheHalfPeriodsDerivative) {
  const Case c;
  const PredictionSigma s = c.sigma(inputs_of(kRatioSigma, kBiasSigma, kRateSigma));
  // Noise-free: ω0's σ is the bias's alone.
  const Expected e = linear_terms(c, kRatioSigma, kBiasSigma, kRateSigma);
  ASSERT_GT(e.omega0, 1e-4);
  ASSERT_GT(e.body, 1e-4);
  ASSERT_GT(e.rate, 1e-5);
  EXPECT_NEAR(s.omega0, e.omega0, 0.05 * e.omega0);
  EXPECT_NEAR(s.body, e.body, 0.05 * e.body);
  EXPECT_NEAR(s.rate, e.rate, 0.05 * e.rate);
  // The window's fit of a noise-free toss moves nothing.
  EXPECT_LT(s.placement, 0.01 * s.total());
  EXPECT_NEAR(s.total(),
              std::sqrt(e.omega0 * e.omega0 + e.body * e.body + e.rate * e.rate +
                        s.placement * s.placement),
              0.05 * s.total());
}

TEST(PredictionSigma, OmegaScatterIsTwiceTheWindowsResidualOverRootN) {
  // Each component's residual ±ε over the window's n samples, no bias's σ: ω0's σ per component
  // 2ε/√n (docs/phone-lab.md, "Prediction intervals").
  const double noise = 0.05;
  const Case c(1.0, noise);
  int n = 0;
  for (double tau : c.d.tau) n += tau <= c.options.window;
  const double per = 2.0 * noise / std::sqrt(static_cast<double>(n));
  const PredictionSigma s = c.sigma(inputs_of(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), 0));
  const Expected e = linear_terms(c, Eigen::Vector3d::Zero(), Eigen::Vector3d::Constant(per), 0);
  EXPECT_NEAR(s.omega0, e.omega0, 0.05 * e.omega0);
  EXPECT_EQ(s.body, 0.0);
  EXPECT_EQ(s.rate, 0.0);
  // With the bias's σ as well: the two in quadrature per component.
  const PredictionSigma both = c.sigma(inputs_of(Eigen::Vector3d::Zero(), kBiasSigma, 0));
  const Eigen::Vector3d combined = (kBiasSigma.array().square() + per * per).sqrt().matrix();
  const Expected e2 = linear_terms(c, Eigen::Vector3d::Zero(), combined, 0);
  EXPECT_NEAR(both.omega0, e2.omega0, 0.05 * e2.omega0);
}

TEST(PredictionSigma, EachTermVanishesWithItsInputAndScalesWithItsSigma) {
  const Case c;
  const PredictionSigma all = c.sigma(inputs_of(kRatioSigma, kBiasSigma, kRateSigma));
  // Zeroed one at a time: that term 0, the others as they were.
  const PredictionSigma no_body =
      c.sigma(inputs_of(Eigen::Vector3d::Zero(), kBiasSigma, kRateSigma));
  const PredictionSigma no_bias =
      c.sigma(inputs_of(kRatioSigma, Eigen::Vector3d::Zero(), kRateSigma));
  const PredictionSigma no_rate = c.sigma(inputs_of(kRatioSigma, kBiasSigma, 0.0));
  EXPECT_EQ(no_body.body, 0.0);
  EXPECT_LT(no_bias.omega0, 1e-6 * all.omega0);
  EXPECT_EQ(no_rate.rate, 0.0);
  EXPECT_DOUBLE_EQ(no_body.omega0, all.omega0);
  EXPECT_DOUBLE_EQ(no_body.rate, all.rate);
  EXPECT_DOUBLE_EQ(no_bias.body, all.body);
  EXPECT_DOUBLE_EQ(no_rate.omega0, all.omega0);
  // Each input's share of the variance: what is left of the total without it.
  for (const PredictionSigma* without : {&no_body, &no_bias, &no_rate})
    EXPECT_LT(without->total(), all.total());
  EXPECT_NEAR(all.total() * all.total() - no_rate.total() * no_rate.total(), all.rate * all.rate,
              1e-9 * all.total() * all.total());
  EXPECT_NEAR(all.total() * all.total() - no_body.total() * no_body.total(), all.body * all.body,
              1e-9 * all.total() * all.total());
  // Each ratio alone, then both: in quadrature.
  const PredictionSigma first =
      c.sigma(inputs_of({kRatioSigma[0], 0, 0}, Eigen::Vector3d::Zero(), 0));
  const PredictionSigma second =
      c.sigma(inputs_of({0, kRatioSigma[1], 0}, Eigen::Vector3d::Zero(), 0));
  EXPECT_GT(first.body, 0.0);
  EXPECT_GT(second.body, 0.0);
  EXPECT_NEAR(all.body, std::hypot(first.body, second.body), 1e-9 * all.body);
  // Each bias component alone, then all three: in quadrature.
  double components2 = 0.0;
  for (int k = 0; k < 3; ++k) {
    const PredictionSigma one =
        c.sigma(inputs_of(Eigen::Vector3d::Zero(), kBiasSigma[k] * Eigen::Vector3d::Unit(k), 0));
    EXPECT_GT(one.omega0, 0.0) << k;
    components2 += one.omega0 * one.omega0;
  }
  EXPECT_NEAR(all.omega0, std::sqrt(components2), 1e-6 * all.omega0);
  // Every σ × 2: each term × 2 (to the curvature of T/2 over ±2σ).
  const PredictionSigma twice =
      c.sigma(inputs_of(2.0 * kRatioSigma, 2.0 * kBiasSigma, 2.0 * kRateSigma));
  EXPECT_NEAR(twice.omega0, 2.0 * all.omega0, 0.03 * all.omega0);
  EXPECT_NEAR(twice.body, 2.0 * all.body, 0.03 * all.body);
  EXPECT_NEAR(twice.rate, 2.0 * all.rate, 0.03 * all.rate);
}

TEST(PredictionSigma, ATossOnAScaledClockScalesTheHalfPeriodAndEveryTerm) {
  // Stamps × a, ω ÷ a (rates and their σ ÷ a, the window × a): the same toss in other units of
  // time. T/2 and each propagated term × a (the window's placement, moved by a fixed 0.05 s, is
  // not a relation of the clock).
  const Case one(1.0, 0.03);
  const PredictionSigma s1 = one.sigma(inputs_of(kRatioSigma, kBiasSigma, kRateSigma));
  for (const double a : {0.5, 3.0}) {
    const Case c(a, 0.03);
    EXPECT_NEAR(c.half(), a * one.half(), 1e-9 * a * one.half()) << a;
    const PredictionSigma s = c.sigma(inputs_of(kRatioSigma, kBiasSigma, kRateSigma, a));
    EXPECT_NEAR(s.omega0, a * s1.omega0, 1e-6 * a * s1.omega0) << a;
    EXPECT_NEAR(s.body, a * s1.body, 1e-6 * a * s1.body) << a;
    EXPECT_NEAR(s.rate, a * s1.rate, 1e-6 * a * s1.rate) << a;
  }
}

TEST(PredictionSigma, ThePredictionCarriesThePropagatedSigma) {
  // predict_half_period fits the window itself (the truth, on a noise-free toss): its T/2 and
  // its propagated σ are the independent ones.
  const Case c;
  const PredictionInputs in = inputs_of(kRatioSigma, kBiasSigma, kRateSigma);
  Parameters body = c.p;
  body.omega0 = {{c.w0[0] * 1.02, c.w0[1] * 0.99, c.w0[2] * 1.03, c.rate}};
  const Prediction prediction = predict_half_period(c.d, body, c.options, in);
  ASSERT_TRUE(prediction.propagated_half && prediction.propagated_sigma) << prediction.withheld;
  EXPECT_NEAR(*prediction.propagated_half, c.half(), 1e-6 * c.half());
  const Expected e = linear_terms(c, kRatioSigma, kBiasSigma, kRateSigma);
  const double independent = std::sqrt(e.omega0 * e.omega0 + e.body * e.body + e.rate * e.rate);
  EXPECT_NEAR(*prediction.propagated_sigma, independent, 0.05 * independent);
  if (prediction.sigma) {
    EXPECT_EQ(*prediction.sigma, *prediction.propagated_sigma);
  }
}

TEST(PredictionSigma, TheTotalIsEveryTermInQuadratureThePlacementsToo) {
  // A noisy toss (seeded Gaussian, 0.08 rad/s): the window moved 0.05 s later fits another ω0,
  // so the placement term is not 0 (the difference of the two T/2). predict_half_period's
  // propagated σ is then the four terms of the same fit (solved here as it solves it) in
  // quadrature.
  Case c;
  std::mt19937 random(11);
  std::normal_distribution<double> gauss(0.0, 0.08);
  for (Eigen::Vector3d& w : c.d.omega)
    w += Eigen::Vector3d(gauss(random), gauss(random), gauss(random));
  const PredictionInputs in = inputs_of(kRatioSigma, kBiasSigma, kRateSigma);
  Parameters start = c.p;
  start.omega0 = {{c.d.omega[0][0], c.d.omega[0][1], c.d.omega[0][2], c.rate}};
  Parameters fitted = start;
  ASSERT_TRUE(solve({c.d}, fitted, c.options).usable);
  const physics::DampedExactRotation motion(
      fitted.moments(),
      fitted.axes().transpose() *
          Eigen::Vector3d(fitted.omega0[0][0], fitted.omega0[0][1], fitted.omega0[0][2]),
      {DragLaw::linear, fitted.omega0[0][3]}, physics::ExactParts::omega_only);
  const std::optional<double> half = motion_half_period(motion, fitted.axes(), c.d.tau);
  ASSERT_TRUE(half.has_value());
  const std::optional<PredictionSigma> s =
      prediction_sigma(c.d, fitted, start, c.options, in, *half);
  ASSERT_TRUE(s.has_value());
  EXPECT_GT(s->placement, 1e-3 * s->total());
  // The placement: T/2 from the window moved 50 ms later (docs/phone-lab.md), its samples
  // before 0.05 s left out, fitted from the same start, against T/2.
  TossData later;
  for (std::size_t i = 0; i < c.d.tau.size(); ++i)
    if (c.d.tau[i] >= 0.05) later.tau.push_back(c.d.tau[i]), later.omega.push_back(c.d.omega[i]);
  later.samples = static_cast<int>(later.tau.size());
  SolveOptions moved = c.options;
  moved.window += 0.05;
  Parameters again = start;
  ASSERT_TRUE(solve({later}, again, moved).usable);
  const physics::DampedExactRotation other(
      again.moments(),
      again.axes().transpose() *
          Eigen::Vector3d(again.omega0[0][0], again.omega0[0][1], again.omega0[0][2]),
      {DragLaw::linear, again.omega0[0][3]}, physics::ExactParts::omega_only);
  const std::optional<double> half_later = motion_half_period(other, again.axes(), c.d.tau);
  ASSERT_TRUE(half_later.has_value());
  EXPECT_NEAR(s->placement, std::abs(*half_later - *half), 1e-6 * *half);
  for (const double term : {s->omega0, s->placement, s->body, s->rate}) EXPECT_GT(term, 0.0);
  const double quadrature = std::sqrt(s->omega0 * s->omega0 + s->placement * s->placement +
                                      s->body * s->body + s->rate * s->rate);
  EXPECT_NEAR(s->total(), quadrature, 1e-12 * quadrature);
  const Prediction prediction = predict_half_period(c.d, start, c.options, in);
  ASSERT_TRUE(prediction.propagated_half && prediction.propagated_sigma) << prediction.withheld;
  EXPECT_NEAR(*prediction.propagated_half, *half, 1e-9 * *half);
  EXPECT_NEAR(*prediction.propagated_sigma, quadrature, 1e-9 * quadrature);
}

// The bias's σ a prediction takes from its recording (docs/phone-lab.md): the still rest's
// standard error plus its drift, linear in the standard error (a σ, not a variance); with no rest
// the flights' fitted σ as it is; with neither 0.
TEST(PredictionSigma, TheBiasSigmaIsTheRestsStandardErrorPlusItsDrift) {
  const Eigen::Vector3d se(0.001, 0.004, 0.0025);
  for (const double k : {1.0, 3.0, 10.0}) {
    RecordingPart part;
    part.rest.samples = 200;
    part.rest.standard_error = k * se;
    const Eigen::Vector3d sigma = bias_sigma(part);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(sigma[c], k * se[c] + 0.002, 1e-15) << k << " " << c;
    RecordingPart flights;
    flights.bias_fitted_sigma = k * se;
    EXPECT_LT((bias_sigma(flights) - k * se).norm(), 1e-15) << k;
  }
  EXPECT_EQ(bias_sigma(RecordingPart{}), Eigen::Vector3d::Zero());
}

/// The held drag rate (held_rate) against the inverse-variance mean written out here: each other
/// toss weighted by 1/c, c its rate's variance in their joint fit (covariances), its σ from theirs;
/// with σ_j = k√c_j (each toss's σ its own fit's) the textbook k/√Σ(1/c_j).
TEST(HeldRate, IsTheInverseVarianceMeanOfTheOtherTossesRates) {
  const Case c;
  // Three tosses of the case's body, 0.4, 0.8 and 1.5 s long (their rates' variances unequal).
  const std::vector<Eigen::Vector3d> principal = {
      {0.9, 13.0, 1.1}, {-1.2, 11.0, 1.4}, {0.7, -12.0, -0.9}};
  const std::vector<double> rates = {0.10, 0.25, 0.16}, lengths = {0.4, 0.8, 1.5};
  std::vector<TossData> rest;
  Parameters fold = c.p;
  fold.omega0.clear();
  for (std::size_t j = 0; j < 3; ++j) {
    TossData d;
    const Eigen::Vector3d w = c.axes * principal[j];
    for (int i = 0; 0.01 * i <= lengths[j] + 1e-9; ++i) {
      d.tau.push_back(0.01 * i);
      // A residual of ±0.05 rad/s: a fit with a finite σ.
      d.omega.push_back(c.omega(c.moments, w, rates[j], 0.01 * i) +
                        (i % 2 ? 0.05 : -0.05) * Eigen::Vector3d::Ones());
    }
    d.samples = static_cast<int>(d.tau.size());
    rest.push_back(d);
    fold.omega0.push_back({w[0], w[1], w[2], rates[j]});
  }
  const std::optional<Covariances> cov =
      covariances(rest, fold, true, std::vector<bool>(fold.e.size(), false), DragLaw::linear);
  ASSERT_TRUE(cov.has_value());
  double inverse = 0.0, weighted = 0.0;
  std::vector<double> variance;
  for (std::size_t j = 0; j < 3; ++j) {
    variance.push_back(cov->omega0[j](3, 3));
    inverse += 1.0 / variance[j], weighted += rates[j] / variance[j];
  }
  ASSERT_GT(std::max({variance[0], variance[1], variance[2]}),
            2.0 * std::min({variance[0], variance[1], variance[2]}));
  for (const double k : {1.0, 3.0}) {
    std::vector<std::optional<double>> sigmas;
    for (double v : variance) sigmas.push_back(k * std::sqrt(v));
    const HeldRate held = held_rate(rest, fold, true, DragLaw::linear, sigmas);
    EXPECT_NEAR(held.rate, weighted / inverse, 1e-9) << k;
    EXPECT_NEAR(held.sigma, k / std::sqrt(inverse), 1e-9 * k / std::sqrt(inverse)) << k;
  }
  // One toss: its own rate and σ.
  const HeldRate one = held_rate({rest[1]},
                                 [&] {
                                   Parameters p = fold;
                                   p.omega0 = {fold.omega0[1]};
                                   return p;
                                 }(),
                                 true, DragLaw::linear, {0.03});
  EXPECT_NEAR(one.rate, rates[1], 1e-12);
  EXPECT_NEAR(one.sigma, 0.03, 1e-12);
  // No drag law: none held.
  const HeldRate none = held_rate(rest, fold, true, DragLaw::none, {0.1, 0.1, 0.1});
  EXPECT_EQ(none.rate, 0.0);
  EXPECT_EQ(none.sigma, 0.0);
}

/// The σ of the log moment ratios of a body fitted on `n` tosses alike (the case's body, each ω0
/// the case's with its components' signs turned, so that each toss tells as much), by the
/// least-squares covariance of that fit alone.
Eigen::Vector2d fitted_ratio_sigma(int n) {
  const Case c;
  const Eigen::Vector3d principal(0.9, 13.0, 1.1);
  std::vector<TossData> data;
  Parameters body = c.p;
  body.omega0.clear();
  for (int j = 0; j < n; ++j) {
    const Eigen::Vector3d signs(j % 2 ? -1.0 : 1.0, j % 4 < 2 ? 1.0 : -1.0, j % 8 < 4 ? 1 : -1);
    const Eigen::Vector3d w = c.axes * principal.cwiseProduct(signs);
    TossData d;
    for (int i = 0; i <= 100; ++i) {
      d.tau.push_back(0.01 * i);
      d.omega.push_back(c.omega(c.moments, w, c.rate, 0.01 * i) +
                        (i % 3 ? 0.03 : -0.06) * Eigen::Vector3d::Ones());
    }
    d.samples = static_cast<int>(d.tau.size());
    data.push_back(d);
    body.omega0.push_back({w[0], w[1], w[2], c.rate});
  }
  const std::optional<Covariances> cov =
      covariances(data, body, false, std::vector<bool>(body.e.size(), false), DragLaw::linear);
  EXPECT_TRUE(cov.has_value());
  if (!cov) return Eigen::Vector2d::Zero();
  return {std::sqrt(cov->body(0, 0)), std::sqrt(cov->body(1, 1))};
}

TEST(HeldOutRatioSigma, IsTheSigmaOfTheBodyFittedOnTheOtherTossesAlone) {
  // The held-out body rests on `seconds` of the `all` s of flight: its σ is the joint fit's
  // scaled as a fit on that share alone would give it, larger the less flight it rests on.
  // Measured: within 7 % from 8 tosses down to 4; with 2 or 1 the body is worse determined than
  // the square root says (0.0085 against 0.012, 0.0094 against 0.15: two tosses' ω0 span fewer
  // directions), so there only the direction is asserted; the calibration on the other tosses
  // widens what is left (docs/phone-lab.md, "Prediction intervals").
  const Eigen::Vector2d joint = fitted_ratio_sigma(8);
  double last = 0.0;
  for (const int n : {8, 6, 4, 2, 1}) {
    SCOPED_TRACE(n);
    const Eigen::Vector2d alone = fitted_ratio_sigma(n);
    const Eigen::Vector3d held =
        held_out_ratio_sigma(Eigen::Vector3d(joint[0], joint[1], 0.0), 8.0, 1.0 * n);
    for (int i = 0; i < 2; ++i) {
      if (n >= 4) {
        EXPECT_NEAR(held[i] / alone[i], 1.0, 0.1) << "ratio " << i;
      }
      EXPECT_GE(held[i], joint[i]);
    }
    EXPECT_GE(held[0], last);
    if (n < 8) {
      EXPECT_GT(held[0], last);
    }
    last = held[0];
  }
  // No flight to rest on, or all of it: the joint σ as it is.
  const Eigen::Vector3d s(0.01, 0.02, 0.0);
  EXPECT_EQ(held_out_ratio_sigma(s, 8.0, 0.0), s);
  EXPECT_EQ(held_out_ratio_sigma(s, 8.0, 8.0), s);
}

}  // namespace
}  // namespace bookspin::fit
