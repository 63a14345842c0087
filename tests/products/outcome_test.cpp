// make_cached, the check-make-record every cached product goes through: the outputs recorded
// relative to OUT, up to date the second time unless forced, the remake note naming the
// product, and a make stopped by a signal (Interrupted) leaving the earlier manifest as it was.
#include "products/outcome.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "output/manifest.hpp"
#include "support/cli_runner.hpp"
#include "support/scratch.hpp"

namespace bookspin::products {
namespace {

namespace fs = std::filesystem;

TEST(Outcome, MakesRecordsSkipsAndKeepsTheManifestWhenInterrupted) {
  test::ScratchDir dir;
  const fs::path out = dir / "out";
  CachedOutputs cached{"thing", out / "thing" / "manifest.json", "  \"manifest\": 1,\n", out};
  int makes = 0;
  const auto make = [&]() -> std::optional<Made> {
    ++makes;
    fs::create_directories(out / "sub");
    std::ofstream(out / "sub" / "a.txt") << "made " << makes;
    return Made{{out / "sub" / "a.txt"}};
  };
  Freshness freshness;
  std::vector<std::string> remade;
  freshness.on_remake = [&](const std::string& name, const std::string&) {
    remade.push_back(name);
  };
  EXPECT_EQ(make_cached(cached, freshness, make).outcome, Outcome::made);
  EXPECT_EQ(output::manifest_outputs(cached.manifest), (std::vector<std::string>{"sub/a.txt"}));
  EXPECT_EQ(make_cached(cached, freshness, make).outcome, Outcome::up_to_date);
  EXPECT_EQ(makes, 1);
  EXPECT_TRUE(remade.empty());

  freshness.force = true;
  EXPECT_EQ(make_cached(cached, freshness, make).outcome, Outcome::made);
  EXPECT_EQ(makes, 2);
  freshness.force = false;

  cached.head = "  \"manifest\": 1,\n  \"other\": 2,\n";  // another head: made again, and why
  EXPECT_EQ(make_cached(cached, freshness, make).outcome, Outcome::made);
  EXPECT_EQ(remade, (std::vector<std::string>{"thing"}));

  const std::string manifest = test::read_file(cached.manifest);
  cached.head = "  \"manifest\": 1,\n  \"other\": 3,\n";
  const CachedOutcome stopped =
      make_cached(cached, freshness, []() -> std::optional<Made> { throw Interrupted(15); });
  EXPECT_EQ(stopped.outcome, Outcome::interrupted);
  EXPECT_EQ(stopped.signal, 15);
  EXPECT_EQ(test::read_file(cached.manifest), manifest);
}

}  // namespace
}  // namespace bookspin::products
