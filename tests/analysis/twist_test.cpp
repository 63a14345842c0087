// The twist about L over one body-frame period (docs/physics.md §19): Montgomery's closed
// form against a symmetric top worked by hand, and the twist measured from a run's
// orientations against the closed form.
#include "analysis/twist.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "analysis/measures.hpp"
#include "scene/scene.hpp"

namespace bookspin::analysis {
namespace {

constexpr double kPi = std::numbers::pi;

/// |a − b| as angles: the shorter way round.
double angle_gap(double a, double b) { return std::abs(wrap_angle(a - b)); }

/// A symmetric top with moments (I⊥, I⊥, I3) spun at ω = (ω⊥, 0, ω3): L_b keeps its angle ϑ0
/// to the symmetry axis (cos ϑ0 = I3 ω3/|L|) and turns about it at (I3 − I⊥) ω3/I⊥ (body
/// frame), so the period is T = 2π I⊥/(|I3 − I⊥| |ω3|) and Ω = ±2π(1 − cos ϑ0), counter-
/// clockwise (+) about the pole when I3 > I⊥. In the world the body turns about L at |L|/I⊥
/// while spinning about its axis by ∓2π per period, so R(T) turns by |L|·T/I⊥ about L.
struct SymmetricTop {
  double I_perp, I3, omega_perp, omega3;
  double L() const { return std::hypot(I_perp * omega_perp, I3 * omega3); }
  double period() const { return 2 * kPi * I_perp / (std::abs(I3 - I_perp) * std::abs(omega3)); }
  double solid_angle() const {
    const double cos0 = std::abs(I3 * omega3) / L();
    return (I3 > I_perp ? 1.0 : -1.0) * 2 * kPi * (1 - cos0);
  }
  double twist() const { return wrap_angle(L() * period() / I_perp); }
};

TEST(Twist, ClosedFormOfTheSymmetricTopByHand) {
  // Oblate (symmetry axis z, the largest moment) and prolate (symmetry axis x, the smallest):
  // L_b circles the pole counterclockwise in one, clockwise in the other.
  const SymmetricTop oblate{1.0, 1.7, 0.4, 0.9};
  const physics::ExactRotation flat({1.0, 1.0, 1.7}, {0.4, 0.0, 0.9});
  ASSERT_NEAR(flat.period(), oblate.period(), 1e-12 * oblate.period());
  EXPECT_NEAR(*polhode_solid_angle(flat), oblate.solid_angle(), 1e-10);
  EXPECT_NEAR(angle_gap(*twist_exact(flat), oblate.twist()), 0.0, 1e-9);

  const SymmetricTop prolate{2.0, 0.6, 0.5, -0.8};  // spin mostly about the thin axis x
  const physics::ExactRotation rod({0.6, 2.0, 2.0}, {-0.8, 0.0, 0.5});
  ASSERT_NEAR(rod.period(), prolate.period(), 1e-12 * prolate.period());
  EXPECT_NEAR(*polhode_solid_angle(rod), prolate.solid_angle(), 1e-10);
  EXPECT_NEAR(angle_gap(*twist_exact(rod), prolate.twist()), 0.0, 1e-9);
}

// The twist is an angle in (−π, π] (docs/physics.md §19), and the tops above turn by more
// than π about L in a period: the oblate top by |L|·T/I⊥ = 15.7720 rad (2.51 turns), whose
// nearest angle is 15.7720 − 3·2π = −3.0775; the prolate by 6.2228 rad, nearest −0.0604.
// Compared here without wrapping either side, against the whole turns counted by hand.
TEST(Twist, ClosedFormBeyondPiIsTheNearestAngle) {
  const SymmetricTop oblate{1.0, 1.7, 0.4, 0.9};
  const double oblate_turn = oblate.L() * oblate.period() / oblate.I_perp;
  ASSERT_NEAR(oblate_turn, 15.7720, 1e-4);
  const double oblate_twist =
      *twist_exact(physics::ExactRotation({1.0, 1.0, 1.7}, {0.4, 0.0, 0.9}));
  EXPECT_NEAR(oblate_twist, oblate_turn - 3 * 2 * kPi, 1e-9);
  EXPECT_NEAR(oblate_twist, -3.0775, 1e-4);

  const SymmetricTop prolate{2.0, 0.6, 0.5, -0.8};
  const double prolate_turn = prolate.L() * prolate.period() / prolate.I_perp;
  ASSERT_NEAR(prolate_turn, 6.2228, 1e-4);
  const double prolate_twist =
      *twist_exact(physics::ExactRotation({0.6, 2.0, 2.0}, {-0.8, 0.0, 0.5}));
  EXPECT_NEAR(prolate_twist, prolate_turn - 2 * kPi, 1e-9);

  // wrap_angle itself: to the nearest angle either way round, π kept and −π made π.
  EXPECT_DOUBLE_EQ(wrap_angle(4.0), 4.0 - 2 * kPi);
  EXPECT_DOUBLE_EQ(wrap_angle(-4.0), 2 * kPi - 4.0);
  EXPECT_DOUBLE_EQ(wrap_angle(15.0), 15.0 - 2 * 2 * kPi);
  EXPECT_DOUBLE_EQ(wrap_angle(-15.0), 2 * 2 * kPi - 15.0);
  EXPECT_DOUBLE_EQ(wrap_angle(1.0), 1.0);
  EXPECT_EQ(wrap_angle(kPi), kPi);
  EXPECT_EQ(wrap_angle(-kPi), kPi);
}

TEST(Twist, EmptyWithoutAPeriod) {
  EXPECT_FALSE(twist_exact(physics::ExactRotation({1.0, 2.0, 3.0}, {0.0, 0.0, 1.0})));
  EXPECT_FALSE(twist_exact(physics::ExactRotation({1.0, 2.0, 3.0}, {0.0, 0.5, 0.0})));
}

/// The scene `text` with the exact model, run for `length` time units at `dt`.
RunMeasures exact_run(const std::string& text, double length, double dt) {
  char time[160];
  std::snprintf(time, sizeof time, "\n[time]\ndt = %.17g\nsteps_per_frame = 1\nduration = %.17g\n",
                dt, length);
  return measure_run(scene::parse_scene_text(text + time, "twist.toml", {"model.kind=\"exact\""}));
}

// The twist measured from the exact model's R(t) (van Zon & Schofield's precession, §8) and
// Montgomery's 2E·T/|L| − Ω (the solid angle by quadrature of the exact polhode) are two
// independent computations of one angle.
TEST(Twist, MeasuredOnTheExactModelIsTheClosedForm) {
  struct Case {
    const char* name;
    std::string text;
    double length;  ///< a little over one period T
    double dt;      ///< the scene's step: 1/60 for the book, the clip's 0.002 for the racket
  };
  const Case cases[] = {
      {"book, jiggled x spin (T = 442)", "[initial]\njiggle = 0.001\nseed = 7\n", 460.0,
       1.0 / 60.0},
      {"tennis racket, tilted off its intermediate axis (T = 2.12)",
       "[body]\nshape = \"tennis-racket\"\n[initial]\nangular_velocity = [1.5, 6.0, 0.3]\n", 3.0,
       0.002},
      {"symmetric book (a = b), spun off its axis (T = 14.2)",
       "[book]\nsize = [2.0, 2.0, 0.5]\n[initial]\nangular_velocity = [0.3, 0.1, 0.5]\n", 20.0,
       1.0 / 60.0},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const RunMeasures m = exact_run(c.text, c.length, c.dt);
    ASSERT_TRUE(m.twist);
    ASSERT_TRUE(m.twist_exact);
    EXPECT_LT(angle_gap(*m.twist, *m.twist_exact), 1e-8)
        << "measured " << *m.twist << ", closed form " << *m.twist_exact;
    // Not a coincidence of a trivial angle: each twist is well away from 0 and π.
    EXPECT_GT(std::abs(std::sin(*m.twist_exact)), 0.05);
  }
}

TEST(Twist, EmptyBeforeTheFirstPeriodEnds) {
  const RunMeasures m = exact_run("[initial]\njiggle = 0.001\nseed = 7\n", 100.0, 1.0 / 60.0);
  EXPECT_FALSE(m.twist);
  EXPECT_TRUE(m.twist_exact);
}

}  // namespace
}  // namespace bookspin::analysis
