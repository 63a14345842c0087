// scene::key_words: every numeric scene key in words, as a sweep's axes and header name it.
#include "scene/key_label.hpp"

#include <gtest/gtest.h>

#include <set>
#include <stdexcept>

#include "scene/limits.hpp"

namespace bookspin::scene {
namespace {

// Every key of the limits table has words of its own: none left as the key, none shared.
TEST(KeyLabel, EveryNumericKeyHasItsOwnWords) {
  std::set<std::string> seen;
  for (const Limit& limit : kLimits) {
    const KeyWords w = key_words(limit.key);
    EXPECT_FALSE(w.words.empty()) << limit.key;
    EXPECT_EQ(w.words.find('.'), std::string::npos) << limit.key << ": " << w.words;
    EXPECT_TRUE(seen.insert(w.words).second) << limit.key << " shares '" << w.words << "'";
  }
}

TEST(KeyLabel, TheWordsLeadTheUnitFollowsAndTheKeyComesLast) {
  EXPECT_EQ(key_label("time.dt"), "time step dt (time units)");
  EXPECT_EQ(key_caption("time.dt"), "time step dt (time units) \u00b7 time.dt");
  // A count has no unit.
  EXPECT_EQ(key_label("model.normalize_every"), "steps between normalizations");
  EXPECT_EQ(key_caption("model.normalize_every"),
            "steps between normalizations \u00b7 model.normalize_every");
}

// A vector key's component is named by its axis, x y z for [0] [1] [2], before the frame.
TEST(KeyLabel, AComponentIsNamedByItsAxis) {
  EXPECT_EQ(key_words("initial.angular_velocity[0]").words, "ω0 x, body frame");
  EXPECT_EQ(key_label("initial.angular_velocity[1]"), "ω0 y, body frame (rad per time unit)");
  EXPECT_EQ(key_words("book.size[2]").words, "book size z");
  EXPECT_EQ(key_caption("initial.angular_velocity[2]"),
            "ω0 z, body frame (rad per time unit) \u00b7 initial.angular_velocity[2]");
}

TEST(KeyLabel, AKeyThatIsNoNumericKeyIsRefused) {
  EXPECT_THROW(key_words("model.kind"), std::invalid_argument);
  EXPECT_THROW(key_words("time.dtt"), std::invalid_argument);
  EXPECT_THROW(key_words("initial.angular_velocity[3]"), std::invalid_argument);
  EXPECT_THROW(key_words(""), std::invalid_argument);
}

}  // namespace
}  // namespace bookspin::scene
