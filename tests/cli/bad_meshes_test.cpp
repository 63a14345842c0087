// The catalogue of bad meshes in tests/bad_meshes/: NAME.<ext> (the mesh passed to
// `bookspin inertia`) and NAME.expected (the exact error line after "bookspin: error: ", with
// {MESH} for the path passed). Every case must exit with status 2, print exactly that one
// line on stderr and nothing on stdout. The cases are listed at run time.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>

#include "support/catalogue.hpp"
#include "support/cli_runner.hpp"

namespace bookspin::cli {
namespace {

using namespace bookspin::test;  // the shared runner (tests/support)

namespace fs = std::filesystem;

constexpr std::size_t kMinimumCases = 10;

std::vector<CatalogueCase> load_meshes() {
  return load_catalogue(
      "bad_meshes",
      [](const fs::path& p) { return p.extension() != ".expected" && p.extension() != ".md"; },
      [](const fs::path& mesh) {
        return Placeholders{{"{MESH}", mesh.string()}};
      });
}

/// Status 2, exactly the expected line on stderr, nothing on stdout (with --json too: the
/// error must not leave half an object behind).
void expect_rejected(const fs::path& mesh, const std::string& expected) {
  for (const char* json : {"", " --json"}) {
    const SplitResult r = run_bookspin_split("inertia " + quoted(mesh) + json);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_EQ(r.err, expected);
    EXPECT_EQ(r.out, "");
  }
}

class BadMeshInertia : public ::testing::TestWithParam<CatalogueCase> {};

TEST_P(BadMeshInertia, ExitsTwoWithTheExactLineAndPrintsNothing) {
  expect_rejected(GetParam().file, GetParam().expected);
}

INSTANTIATE_TEST_SUITE_P(Catalogue, BadMeshInertia, ::testing::ValuesIn(load_meshes()),
                         case_test_name);

TEST(BadMeshCatalogue, HasItsCasesEachWithItsExpectedLineAndSmall) {
  const auto cases = load_meshes();
  expect_complete(cases, kMinimumCases);
  for (const auto& c : cases) EXPECT_LT(fs::file_size(c.file), 2048u) << c.name;
}

TEST(BadMeshCatalogue, EveryExpectedFileHasItsMesh) {
  const auto cases = load_meshes();
  for (const auto& entry :
       fs::directory_iterator((fs::path(BOOKSPIN_SOURCE_DIR) / "tests" / "bad_meshes"))) {
    if (entry.path().extension() != ".expected") continue;
    const auto stem = entry.path().stem().string();
    EXPECT_TRUE(std::any_of(cases.begin(), cases.end(), [&](const CatalogueCase& c) {
      return c.name == stem;
    })) << entry.path();
  }
}

// The cases below need a path that cannot be a committed file.

TEST(BadMeshFiles, MissingFileIsRejected) {
  const fs::path mesh =
      (fs::path(BOOKSPIN_SOURCE_DIR) / "tests" / "bad_meshes") / "no-such-mesh.obj";
  expect_rejected(mesh, "bookspin: error: " + mesh.string() + ": mesh file not found\n");
}

TEST(BadMeshFiles, DirectoryIsRejected) {
  expect_rejected(
      (fs::path(BOOKSPIN_SOURCE_DIR) / "tests" / "bad_meshes"),
      "bookspin: error: " + (fs::path(BOOKSPIN_SOURCE_DIR) / "tests" / "bad_meshes").string() +
          ": is a directory, not a mesh file\n");
}

}  // namespace
}  // namespace bookspin::cli
