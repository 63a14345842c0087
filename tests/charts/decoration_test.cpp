// The twist line of a clip's caption (render.caption_twist, docs/physics.md §19): its numbers
// are the run's twist over one body-frame period and Montgomery's closed form, computed here
// again from the scene with the twist functions, and its text keeps them apart.
#include "charts/decoration.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "analysis/twist.hpp"
#include "engines/models.hpp"
#include "physics/exact_model.hpp"

namespace bookspin::charts {
namespace {

/// "−1.234" (U+2212) or "1.234" → the number.
double parse_angle(std::string text) {
  const std::string minus = "\u2212";
  if (text.rfind(minus, 0) == 0) text.replace(0, minus.size(), "-");
  return std::stod(text);
}

/// The two numbers of "twist per period: measured A rad, closed form B rad".
std::pair<double, double> numbers_of(const std::string& line) {
  const std::string head = "twist per period: measured ", middle = " rad, closed form ";
  EXPECT_EQ(line.rfind(head, 0), 0u) << line;
  const auto split = line.find(middle);
  EXPECT_NE(split, std::string::npos) << line;
  const std::string measured = line.substr(head.size(), split - head.size());
  const std::string rest = line.substr(split + middle.size());
  EXPECT_EQ(rest.substr(rest.size() - 4), " rad") << line;
  return {parse_angle(measured), parse_angle(rest.substr(0, rest.size() - 4))};
}

TEST(TwistCaption, TennisRacketLineHoldsTheMeasuredAndTheClosedFormTwist) {
  const scene::Scene scene =
      scene::parse_scene(std::string(BOOKSPIN_SOURCE_DIR) + "/scenes/tennis-racket.toml");
  ASSERT_TRUE(scene.render.caption_twist);
  const FrameDecorator decorator(scene);
  ASSERT_TRUE(decorator.twist_caption().has_value());
  const auto [measured, closed_form] = numbers_of(*decorator.twist_caption());

  // The closed form from the exact motion of the same initial state.
  physics::ExactModel reference(scene.body);
  reference.reset(scene.initial);
  const auto exact = analysis::twist_exact(reference.rotation());
  ASSERT_TRUE(exact.has_value());
  // The measured twist: the scene's model stepped by dt until one body-frame period is done.
  auto sim = engines::make_model(scene.body, scene.model);
  sim->reset(scene.initial);
  analysis::TwistMeter meter(*analysis::twist_pole(reference.rotation()));
  for (long long n = 0; !meter.done() && n < 100000; ++n) {
    if (n > 0) sim->step(scene.dt);
    const physics::Diagnostics d = sim->diagnostics();
    meter.observe(static_cast<double>(n) * scene.dt, sim->orientation(), d.omega_body, d.L);
  }
  ASSERT_TRUE(meter.twist().has_value()) << "the racket's run ends no period";

  EXPECT_NEAR(measured, *meter.twist(), 0.0005);  // printed to 3 decimals
  EXPECT_NEAR(closed_form, *exact, 0.0005);
  // The period is longer than the 2.4-unit clip: the line is measured past its end.
  EXPECT_GT(reference.rotation().period(), (scene.frames - 1) * scene.steps_per_frame * scene.dt);
  // RK4 at dt = 0.002 follows the exact twist closely.
  EXPECT_NEAR(*meter.twist(), *exact, 1e-3);
}

TEST(TwistCaption, LineNamesEachNumberWithItsSignAndNoneForAMissingOne) {
  EXPECT_EQ(twist_line({1.5, -0.25}),
            "twist per period: measured 1.500 rad, closed form \u22120.250 rad");
  EXPECT_EQ(twist_line({-2.0004, 3.0}),
            "twist per period: measured \u22122.000 rad, closed form 3.000 rad");
  // Rounds to zero: no minus sign; a missing or non-finite number is "none".
  EXPECT_EQ(twist_line({-0.0001, std::nullopt}),
            "twist per period: measured 0.000 rad, closed form none");
  EXPECT_EQ(twist_line({std::numeric_limits<double>::quiet_NaN(), 1.0}),
            "twist per period: measured none, closed form 1.000 rad");
}

TEST(TwistCaption, CaptionShowsTheTwistBelowTheModelLineOnlyWhenGiven) {
  const scene::Scene scene =
      scene::parse_scene(std::string(BOOKSPIN_SOURCE_DIR) + "/scenes/tennis-racket.toml");
  const auto plain = caption_for(scene, 1.0, std::nullopt);
  const auto with = caption_for(scene, 1.0, std::nullopt, std::string("twist line"));
  ASSERT_EQ(with.size(), plain.size() + 1);
  EXPECT_EQ(with[1].text, plain[1].text);  // the model line
  EXPECT_EQ(with[2].text, "twist line");
  EXPECT_EQ(with.back().text, plain.back().text);  // the time stays last
}

}  // namespace
}  // namespace bookspin::charts
