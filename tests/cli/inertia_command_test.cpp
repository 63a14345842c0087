// `bookspin inertia` run as a program: its JSON against the solid cuboid's closed forms
// (docs/physics.md §11), --mass against --density, --scale, and the one-line errors.
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <map>
#include <vector>

#include "support/cli_runner.hpp"
#include "support/mesh_files.hpp"

namespace bookspin::cli {
namespace {

using namespace bookspin::test;  // the runner and the mesh writers (tests/support)

namespace fs = std::filesystem;

/// A JSON value as this test needs it: a number or a (nested) array of numbers.
struct Json {
  double number = 0.0;
  std::vector<Json> items;
  bool is_array = false;
};

/// Just enough JSON for the command's output: one object of numbers and arrays of them.
/// Any syntax error fails the test and leaves the rest unparsed.
class JsonReader {
 public:
  explicit JsonReader(const std::string& text) : text_(text) {}

  std::map<std::string, Json> object() {
    std::map<std::string, Json> out;
    expect('{');
    do {
      const std::string key = string();
      expect(':');
      out[key] = value();
    } while (accept(','));
    expect('}');
    skip_space();
    EXPECT_EQ(at_, text_.size()) << "text after the object: " << text_.substr(at_);
    return out;
  }

 private:
  Json value() {
    Json v;
    if (accept('[')) {
      v.is_array = true;
      do v.items.push_back(value());
      while (accept(','));
      expect(']');
      return v;
    }
    skip_space();
    const char* start = text_.c_str() + at_;
    char* end = nullptr;
    v.number = std::strtod(start, &end);
    EXPECT_NE(end, start) << "not a number at " << text_.substr(at_);
    at_ += static_cast<std::size_t>(end - start);
    return v;
  }
  std::string string() {
    expect('"');
    const auto close = text_.find('"', at_);
    std::string s = text_.substr(at_, close - at_);
    at_ = close + 1;
    return s;
  }
  void skip_space() {
    while (at_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[at_]))) ++at_;
  }
  bool accept(char ch) {
    skip_space();
    if (at_ < text_.size() && text_[at_] == ch) {
      ++at_;
      return true;
    }
    return false;
  }
  void expect(char ch) { EXPECT_TRUE(accept(ch)) << "expected '" << ch << "' at " << at_; }

  const std::string& text_;
  std::size_t at_ = 0;
};

std::vector<double> numbers(const Json& v) {
  std::vector<double> out;
  if (!v.is_array) return {v.number};
  for (const auto& item : v.items) {
    const auto inner = numbers(item);
    out.insert(out.end(), inner.begin(), inner.end());
  }
  return out;
}

/// Single-quoted for the shell. Built with append: GCC 12 warns falsely (-Wrestrict) on
/// "literal" + std::string.
std::string quoted(const fs::path& path) {
  std::string out;
  return out.append("'").append(path.string()).append("'");
}

/// Runs `bookspin inertia ARGS --json`, expects success and no stderr, returns the object.
std::map<std::string, Json> inertia_json(const std::string& args) {
  const SplitResult r = run_bookspin_split("inertia " + args + " --json");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << "one line: " << r.out;
  return JsonReader(r.out).object();
}

void expect_numbers(const Json& actual, const std::vector<double>& expected, double tolerance,
                    const std::string& key) {
  const std::vector<double> got = numbers(actual);
  ASSERT_EQ(got.size(), expected.size()) << key;
  for (std::size_t i = 0; i < got.size(); ++i)
    EXPECT_NEAR(got[i], expected[i], tolerance) << key << "[" << i << "]";
}

/// The box [0,a]×[0,b]×[0,c] at density ρ: V = abc, m = ρV, centre (a,b,c)/2,
/// I = m/12 diag(b²+c², a²+c², a²+b²); for 1×2×3 the moments ascend along z, y, x, so the
/// axes are e_z, e_y and e_z × e_y = −e_x.
void expect_box_1x2x3(const std::map<std::string, Json>& json, double mass, double s) {
  ASSERT_EQ(json.size(), 6u);
  const double a = s, b = 2 * s, c = 3 * s;
  const double tol = 1e-12 * mass * (a * a + b * b + c * c);
  expect_numbers(json.at("volume"), {a * b * c}, 1e-12 * a * b * c, "volume");
  expect_numbers(json.at("mass"), {mass}, 1e-12 * mass, "mass");
  expect_numbers(json.at("center_of_mass"), {a / 2, b / 2, c / 2}, 1e-12 * c, "center_of_mass");
  const double Ix = mass / 12 * (b * b + c * c), Iy = mass / 12 * (a * a + c * c),
               Iz = mass / 12 * (a * a + b * b);
  expect_numbers(json.at("inertia"), {Ix, 0, 0, 0, Iy, 0, 0, 0, Iz}, tol, "inertia");
  expect_numbers(json.at("principal_moments"), {Iz, Iy, Ix}, tol, "principal_moments");
  expect_numbers(json.at("principal_axes"), {0, 0, 1, 0, 1, 0, -1, 0, 0}, 1e-12, "principal_axes");
}

fs::path box_obj(const std::string& name, int skip_faces = 0) {
  const fs::path file = fresh_dir("inertia/" + name) / "box.obj";
  write_box_obj(file, {1.0f, 2.0f, 3.0f}, skip_faces);
  return file;
}

TEST(InertiaCommand, JsonOfABoxIsItsClosedForm) {
  expect_box_1x2x3(inertia_json(quoted(box_obj("json"))), 6.0, 1.0);
}

TEST(InertiaCommand, DensityAndScaleMultiply) {
  // Scale 2: V = 48; density 0.5: m = 24.
  expect_box_1x2x3(inertia_json(quoted(box_obj("scale")) + " --scale 2 --density 0.5"), 24.0, 2.0);
}

TEST(InertiaCommand, MassGivesTheSameBodyAsTheMatchingDensity) {
  const fs::path file = box_obj("mass");
  expect_box_1x2x3(inertia_json(quoted(file) + " --mass 12"), 12.0, 1.0);
  expect_box_1x2x3(inertia_json(quoted(file) + " --density 2"), 12.0, 1.0);
}

TEST(InertiaCommand, NumbersRoundTripAtFullPrecision) {
  // 0.1 has no short binary form: printed with too few digits it would not read back as
  // the same double.
  const auto json = inertia_json(quoted(box_obj("precision")) + " --mass 0.1");
  EXPECT_EQ(numbers(json.at("mass"))[0], 0.1);
  EXPECT_NEAR(numbers(json.at("inertia"))[0], 0.1 / 12 * 13, 1e-16);
}

TEST(InertiaCommand, TextReportNamesTheQuantities) {
  const SplitResult r = run_bookspin_split("inertia " + quoted(box_obj("text")));
  EXPECT_EQ(r.status, 0) << r.err;
  for (const char* word :
       {"volume             6\n", "mass               6\n", "centre of mass     0.5  1  1.5\n",
        "principal moments  2.5  5  6.5  (ascending)\n"})
    EXPECT_NE(r.out.find(word), std::string::npos) << word << " in\n" << r.out;
}

TEST(InertiaCommand, InwardWoundMeshWarnsAndStillReports) {
  const fs::path file = fresh_dir("inertia/inward") / "box.obj";
  {
    std::ofstream out(file);
    for (int i = 0; i < 8; ++i) {
      const Point p = box_corner(i, {1.0f, 2.0f, 3.0f});
      out << "v " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
    }
    for (const auto& q : box_quads())  // every face backwards
      out << "f " << q[3] + 1 << ' ' << q[2] + 1 << ' ' << q[1] + 1 << ' ' << q[0] + 1 << '\n';
  }
  const SplitResult r = run_bookspin_split("inertia " + quoted(file) + " --json");
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(r.err, "bookspin: warning: " + file.string() +
                       ": the mesh is wound inward (negative volume) and lies inside no other "
                       "shell; turned around\n");
  expect_box_1x2x3(JsonReader(r.out).object(), 6.0, 1.0);
}

TEST(InertiaCommand, OpenMeshExitsTwoWithOneLineAndNoOutput) {
  const fs::path file = box_obj("open", /*skip_faces=*/1);
  const SplitResult r = run_bookspin_split("inertia " + quoted(file) + " --json");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "bookspin: error: " + file.string() + ": open mesh: 4 boundary edges\n");
  EXPECT_EQ(r.out, "");
}

TEST(InertiaCommand, MassAndDensityTogetherAreAUsageError) {
  const SplitResult r =
      run_bookspin_split("inertia " + quoted(box_obj("both")) + " --mass 1 --density 1");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.err.rfind("bookspin: error: --mass excludes --density", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

TEST(InertiaCommand, NonPositiveMassIsAUsageError) {
  const SplitResult r = run_bookspin_split("inertia " + quoted(box_obj("neg")) + " --mass -1");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(r.out, "");
}

/// A mass that underflows to 0 is not a mass (docs/outputs.md, "Numbers").
TEST(InertiaCommand, MassThatUnderflowsIsBadInputNamingTheOptions) {
  const fs::path file = box_obj("tiny");
  const SplitResult r =
      run_bookspin_split("inertia " + quoted(file) + " --json --density 1e-300 --scale 1e-40");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.err, "bookspin: error: " + file.string() +
                       ": underflow: the mass or inertia is below the range of a double (from "
                       "--density 1e-300 and --scale 1e-40)\n");
}

}  // namespace
}  // namespace bookspin::cli
