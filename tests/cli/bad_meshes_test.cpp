// The catalogue of bad meshes in tests/bad_meshes/: NAME.<ext> (the mesh passed to
// `bookspin inertia`) and NAME.expected (the exact error line after "bookspin: error: ", with
// {MESH} for the path passed). Every case must exit with status 2, print exactly that one
// line on stderr and nothing on stdout. The cases are listed at run time.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>

#include "support/cli_runner.hpp"

namespace bookspin::cli {
namespace {

using namespace bookspin::test;  // the shared runner (tests/support)

namespace fs = std::filesystem;

constexpr std::size_t kMinimumCases = 10;

struct BadMesh {
  std::string name;      ///< file stem, e.g. "open"
  fs::path mesh;         ///< NAME.<ext>
  std::string expected;  ///< the full stderr, placeholder substituted
};
// gtest prints parameters into the names ctest registers; print a stable text, not bytes.
[[maybe_unused]] void PrintTo(const BadMesh& p, std::ostream* out) { *out << p.name; }

fs::path catalogue_dir() { return fs::path(BOOKSPIN_SOURCE_DIR) / "tests" / "bad_meshes"; }

std::string trim_line_end(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  return text;
}

/// The line bookspin must print for `mesh`, from NAME.expected.
std::string expected_line(const fs::path& expected_file, const fs::path& mesh) {
  std::string line = trim_line_end(read_file(expected_file));
  const std::string placeholder = "{MESH}";
  for (auto at = line.find(placeholder); at != std::string::npos; at = line.find(placeholder))
    line.replace(at, placeholder.size(), mesh.string());
  std::string out = "bookspin: error: ";
  return out.append(line).append("\n");
}

bool is_mesh_case(const fs::path& path) {
  const auto ext = path.extension();
  return ext != ".expected" && ext != ".md";
}

/// Every NAME.<ext> in the catalogue, sorted so test order is stable.
std::vector<BadMesh> load_catalogue() {
  std::vector<BadMesh> cases;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(catalogue_dir(), ec)) {
    if (!is_mesh_case(entry.path())) continue;
    BadMesh c;
    c.name = entry.path().stem().string();
    c.mesh = entry.path();
    const fs::path expected = fs::path(entry.path()).replace_extension(".expected");
    // A case without its .expected file gets an impossible line, so it fails loudly.
    c.expected = fs::exists(expected) ? expected_line(expected, c.mesh)
                                      : "(missing " + expected.string() + ")";
    cases.push_back(c);
  }
  std::sort(cases.begin(), cases.end(),
            [](const auto& a, const auto& b) { return a.name < b.name; });
  return cases;
}

/// GoogleTest names allow only letters, digits and '_'.
std::string test_name(const ::testing::TestParamInfo<BadMesh>& info) {
  std::string name = info.param.name;
  std::replace_if(
      name.begin(), name.end(), [](unsigned char ch) { return !std::isalnum(ch); }, '_');
  return name;
}

std::string quoted(const fs::path& path) {
  std::string out;
  return out.append("'").append(path.string()).append("'");
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

class BadMeshInertia : public ::testing::TestWithParam<BadMesh> {};

TEST_P(BadMeshInertia, ExitsTwoWithTheExactLineAndPrintsNothing) {
  expect_rejected(GetParam().mesh, GetParam().expected);
}

INSTANTIATE_TEST_SUITE_P(Catalogue, BadMeshInertia, ::testing::ValuesIn(load_catalogue()),
                         test_name);

TEST(BadMeshCatalogue, HasItsCasesEachWithItsExpectedLineAndSmall) {
  const auto cases = load_catalogue();
  EXPECT_GE(cases.size(), kMinimumCases);
  for (const auto& c : cases) {
    EXPECT_TRUE(fs::exists(fs::path(c.mesh).replace_extension(".expected"))) << c.name;
    EXPECT_LT(fs::file_size(c.mesh), 2048u) << c.name;
  }
}

TEST(BadMeshCatalogue, EveryExpectedFileHasItsMesh) {
  const auto cases = load_catalogue();
  for (const auto& entry : fs::directory_iterator(catalogue_dir())) {
    if (entry.path().extension() != ".expected") continue;
    const auto stem = entry.path().stem().string();
    EXPECT_TRUE(std::any_of(cases.begin(), cases.end(), [&](const BadMesh& c) {
      return c.name == stem;
    })) << entry.path();
  }
}

// The cases below need a path that cannot be a committed file.

TEST(BadMeshFiles, MissingFileIsRejected) {
  const fs::path mesh = catalogue_dir() / "no-such-mesh.obj";
  expect_rejected(mesh, "bookspin: error: " + mesh.string() + ": mesh file not found\n");
}

TEST(BadMeshFiles, DirectoryIsRejected) {
  expect_rejected(catalogue_dir(), "bookspin: error: " + catalogue_dir().string() +
                                       ": is a directory, not a mesh file\n");
}

}  // namespace
}  // namespace bookspin::cli
