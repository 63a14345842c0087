// Mass properties of real mesh files at every size from 1e-6 to 1e6: files written here, read
// through mesh::load_mesh, integrated by physics::mass_properties, compared with closed forms
// worked out independently in this file (docs/physics.md §1 and §11).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"
#include "physics/mass_properties.hpp"
#include "support/cli_runner.hpp"
#include "support/mesh_files.hpp"

namespace bookspin::mesh {
namespace {

using namespace bookspin::test;
namespace fs = std::filesystem;

constexpr double kScales[] = {1e-6, 1e-3, 1.0, 1e3, 1e6};

/// The closed form a mesh is compared with: volume, centre of mass, principal moments
/// (ascending) at density 1.
struct ClosedForm {
  double volume;
  Eigen::Vector3d center;
  Eigen::Vector3d moments;
};

double relative(double got, double want) { return std::abs(got - want) / std::abs(want); }

void expect_matches(const physics::MassPropertiesResult& r, const ClosedForm& want,
                    double tolerance, const std::string& what) {
  ASSERT_TRUE(r.ok()) << what << ": " << r.error;
  const physics::MassProperties& p = r.properties;
  EXPECT_LE(relative(p.volume, want.volume), tolerance) << what << ": volume " << p.volume;
  const double size = std::cbrt(want.volume);
  EXPECT_LE((p.center_of_mass - want.center).norm() / size, tolerance)
      << what << ": centre " << p.center_of_mass.transpose();
  for (int i = 0; i < 3; ++i)
    EXPECT_LE(relative(p.principal_moments(i), want.moments(i)), tolerance)
        << what << ": moment " << i << " " << p.principal_moments(i) << " vs " << want.moments(i);
}

physics::MassPropertiesResult measure(const fs::path& file) {
  const TriangleMesh mesh = load_mesh(file);
  return physics::mass_properties(mesh.vertices, mesh.triangles, 1.0);
}

/// The solid box [0,a]×[0,b]×[0,c] (the float values the file holds): M = abc,
/// I = M/12 (b²+c², a²+c², a²+b²) (docs/physics.md §1).
ClosedForm box_form(const Point& size) {
  const double a = size[0], b = size[1], c = size[2], m = a * b * c;
  Eigen::Vector3d moments(m / 12 * (b * b + c * c), m / 12 * (a * a + c * c),
                          m / 12 * (a * a + b * b));
  std::sort(moments.begin(), moments.end());
  return {m, Eigen::Vector3d(a, b, c) / 2, moments};
}

/// OBJ of float vertices written with all their digits (they read back exactly).
void write_obj(const fs::path& path, const std::vector<Point>& vertices,
               const std::vector<std::array<int, 3>>& triangles) {
  std::ofstream out(path);
  out << std::setprecision(9);
  for (const Point& p : vertices) out << "v " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  for (const auto& t : triangles)
    out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
}

TEST(MassAtScale, BoxesFromObjAndBinaryStlMatchTheClosedFormAtEveryScale) {
  const fs::path dir = fresh_dir("mesh/mass-at-scale-box");
  for (const double s : kScales) {
    // 1, 2, 3 times a power of ten: short decimals that the OBJ writer prints exactly.
    const Point size{static_cast<float>(1 * s), static_cast<float>(2 * s),
                     static_cast<float>(3 * s)};
    const ClosedForm want = box_form(size);
    const fs::path obj = dir / ("box-" + std::to_string(&s - kScales) + ".obj");
    write_box_obj(obj, size);
    expect_matches(measure(obj), want, 1e-6, "OBJ box at " + std::to_string(s));
    const fs::path stl = dir / ("box-" + std::to_string(&s - kScales) + ".stl");
    write_bytes(stl, box_binary_stl(size));
    expect_matches(measure(stl), want, 1e-6, "binary STL box at " + std::to_string(s));
  }
}

/// A regular n-gon prism about the z axis: circumradius r, z from 0 to h, outward winding.
/// Its closed form (not the cylinder's): a polygon of n triangles (0, p_k, p_k+1) with
/// area A = n r² sin(2π/n) / 2 and ∫(x² + y²) dA = A r² (2 + cos(2π/n)) / 6 (a triangle
/// with a corner at the origin: area/6 (p·p + q·q + p·q)); by the n-fold symmetry
/// ∫x² = ∫y² = half of it. So M = A h, c = (0, 0, h/2), I_z = M r² (2 + cos θ)/6 and
/// I_x = I_y = M (r² (2 + cos θ)/12 + h²/12), θ = 2π/n.
ClosedForm prism_form(int n, double r, double h) {
  const double theta = 2 * M_PI / n;
  const double m = n * r * r * std::sin(theta) / 2 * h;
  const double polar = r * r * (2 + std::cos(theta)) / 6;
  Eigen::Vector3d moments(m * (polar / 2 + h * h / 12), m * (polar / 2 + h * h / 12), m * polar);
  std::sort(moments.begin(), moments.end());
  return {m, Eigen::Vector3d(0, 0, h / 2), moments};
}

void write_prism(const fs::path& path, int n, double r, double h) {
  std::vector<Point> v;
  for (int level = 0; level < 2; ++level)
    for (int k = 0; k < n; ++k)
      v.push_back({static_cast<float>(r * std::cos(2 * M_PI * k / n)),
                   static_cast<float>(r * std::sin(2 * M_PI * k / n)),
                   static_cast<float>(level * h)});
  const int bottom = static_cast<int>(v.size());
  v.push_back({0.0f, 0.0f, 0.0f});
  v.push_back({0.0f, 0.0f, static_cast<float>(h)});
  std::vector<std::array<int, 3>> t;
  for (int k = 0; k < n; ++k) {
    const int next = (k + 1) % n;
    t.push_back({bottom, next, k});              // bottom cap, facing −z
    t.push_back({bottom + 1, n + k, n + next});  // top cap, facing +z
    t.push_back({k, next, n + next});            // side
    t.push_back({k, n + next, n + k});
  }
  write_obj(path, v, t);
}

TEST(MassAtScale, CylinderPrismMatchesThePolygonalPrismClosedFormAtEveryScale) {
  const fs::path dir = fresh_dir("mesh/mass-at-scale-cylinder");
  constexpr int kSides = 96;
  for (const double s : kScales) {
    const fs::path file = dir / ("cylinder-" + std::to_string(&s - kScales) + ".obj");
    write_prism(file, kSides, 0.5 * s, 2.0 * s);
    // The file holds the corners rounded to float32: about 1e-7 relative.
    expect_matches(measure(file), prism_form(kSides, 0.5 * s, 2.0 * s), 1e-6,
                   "cylinder at " + std::to_string(s));
  }
}

/// The box [lo, hi]³ as 8 corners appended to `v` and 12 triangles, outward or inward.
void add_cube(std::vector<Point>& v, std::vector<std::array<int, 3>>& t, float lo, float hi,
              bool outward) {
  const int first = static_cast<int>(v.size());
  for (int i = 0; i < 8; ++i) {
    const Point c = box_corner(i, {1.0f, 1.0f, 1.0f});
    v.push_back({c[0] > 0 ? hi : lo, c[1] > 0 ? hi : lo, c[2] > 0 ? hi : lo});
  }
  for (const auto& tri : box_triangles()) {
    if (outward)
      t.push_back({first + tri[0], first + tri[1], first + tri[2]});
    else
      t.push_back({first + tri[0], first + tri[2], first + tri[1]});
  }
}

TEST(MassAtScale, CubeWithCubicCavitySubtractsTheCavityAtEveryScale) {
  const fs::path dir = fresh_dir("mesh/mass-at-scale-cavity");
  for (const double s : kScales) {
    // Outer cube [0, 3s]³ wound outward, cavity [s, 2s]³ wound inward: the hollow solid is
    // the outer cube minus the cavity, both centred at 1.5 s:
    // V = 27 s³ − s³, I = 27 s³ (18 s²)/12 − s³ (2 s²)/12 on each axis.
    const float a = static_cast<float>(s), b = static_cast<float>(2 * s),
                c = static_cast<float>(3 * s);
    std::vector<Point> v;
    std::vector<std::array<int, 3>> t;
    add_cube(v, t, 0.0f, c, true);
    add_cube(v, t, a, b, false);
    const fs::path file = dir / ("hollow-" + std::to_string(&s - kScales) + ".obj");
    write_obj(file, v, t);
    const double A = a, B = b, C = c;
    const double outer = C * C * C, inner = (B - A) * (B - A) * (B - A);
    const double moment = outer * (2 * C * C) / 12 - inner * (2 * (B - A) * (B - A)) / 12;
    const ClosedForm want{outer - inner, Eigen::Vector3d::Constant(C / 2),
                          Eigen::Vector3d::Constant(moment)};
    const physics::MassPropertiesResult r = measure(file);
    expect_matches(r, want, 1e-6, "hollow cube at " + std::to_string(s));
    EXPECT_TRUE(r.properties.warnings.empty())
        << "a cavity is not turned around: " << r.properties.warnings.front();
    EXPECT_TRUE(r.properties.turned_triangles.empty());
    EXPECT_EQ(r.properties.shells, 2);
  }
}

TEST(MassAtScale, AShellInsideOutOnItsOwnIsTurnedAroundWithAWarning) {
  // Two separate cubes side by side, the second wound inward: it lies inside no other shell,
  // so it is a solid the file wound the wrong way, not a cavity.
  std::vector<Point> v;
  std::vector<std::array<int, 3>> t;
  add_cube(v, t, 0.0f, 1.0f, true);
  add_cube(v, t, 2.0f, 3.0f, false);
  const fs::path file = fresh_dir("mesh/mass-inside-out") / "two.obj";
  write_obj(file, v, t);
  const physics::MassPropertiesResult r = measure(file);
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_NEAR(r.properties.volume, 2.0, 1e-12);
  EXPECT_NEAR(r.properties.center_of_mass.x(), 1.5, 1e-12);
  ASSERT_EQ(r.properties.warnings.size(), 1u);
  EXPECT_EQ(r.properties.warnings[0],
            "shell 2 of 2 is wound inward (negative volume) and lies inside no other shell; "
            "turned around");
  EXPECT_EQ(r.properties.turned_triangles.size(), 12u);
  EXPECT_EQ(r.properties.turned_triangles.front(), 12);
}

TEST(MassAtScale, DegenerateTrianglesAreReported) {
  // The box plus one triangle that repeats a corner: it encloses nothing and is skipped,
  // and the warning says so.
  std::vector<Point> v;
  std::vector<std::array<int, 3>> t;
  add_cube(v, t, 0.0f, 1.0f, true);
  t.push_back({0, 0, 1});
  const fs::path file = fresh_dir("mesh/mass-degenerate") / "box.obj";
  write_obj(file, v, t);
  const physics::MassPropertiesResult r = measure(file);
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_NEAR(r.properties.volume, 1.0, 1e-12);
  ASSERT_EQ(r.properties.warnings.size(), 1u);
  EXPECT_EQ(r.properties.warnings[0],
            "1 degenerate triangles skipped (two corners at one welded vertex)");
}

TEST(MassAtScale, CornersARoundingApartAreWeldedRelativeToTheSize) {
  // A box of side 1e-6 whose corner 7 is written twice, the second copy one float32 step
  // away: welded (2⁻²² of the size), so the surface closes.
  for (const double s : {1e-6, 1.0, 1e6}) {
    std::vector<Point> v;
    std::vector<std::array<int, 3>> t;
    add_cube(v, t, 0.0f, static_cast<float>(s), true);
    Point copy = v[7];
    copy[0] = std::nextafter(copy[0], 2 * copy[0]);
    v.push_back(copy);
    for (int k = 0; k < 3; ++k)
      if (t.back()[k] == 7) t.back()[k] = 8;
    const fs::path file = fresh_dir("mesh/mass-weld") / "box.obj";
    write_obj(file, v, t);
    const TriangleMesh mesh = load_mesh(file);
    EXPECT_EQ(mesh.vertices.cols(), 8) << "scale " << s;
    const physics::MassPropertiesResult r =
        physics::mass_properties(mesh.vertices, mesh.triangles, 1.0);
    ASSERT_TRUE(r.ok()) << "scale " << s << ": " << r.error;
    EXPECT_LE(relative(r.properties.volume, s * s * s), 1e-6);
  }
}

TEST(MassAtScale, SizesBeyondTheDoubleRangeAreAnErrorNotInfinity) {
  std::vector<Point> v;
  std::vector<std::array<int, 3>> t;
  add_cube(v, t, 0.0f, 1.0f, true);
  const fs::path file = fresh_dir("mesh/mass-range") / "box.obj";
  write_obj(file, v, t);
  const TriangleMesh huge = load_mesh(file, 1e200);
  const physics::MassPropertiesResult r =
      physics::mass_properties(huge.vertices, huge.triangles, 1.0);
  EXPECT_EQ(r.error,
            "mesh size out of range: the bounding box's longest side is 1e+200, outside "
            "[1e-50, 1e+50]");
  const TriangleMesh big = load_mesh(file, 1e40);
  const physics::MassPropertiesResult heavy =
      physics::mass_properties(big.vertices, big.triangles, 1e300);
  EXPECT_EQ(heavy.error, physics::kOverflow);
  const TriangleMesh unit = load_mesh(file, 0.5);
  const physics::MassPropertiesResult half =
      physics::mass_properties(unit.vertices, unit.triangles, 1.0);
  ASSERT_TRUE(half.ok());
  const physics::MassProperties p = physics::with_mass(half.properties, 1e308);
  EXPECT_TRUE(physics::all_finite(p));
  EXPECT_LE(relative(p.principal_moments(0), 1e308 * 0.5 / 12), 1e-12);
}

}  // namespace
}  // namespace bookspin::mesh
