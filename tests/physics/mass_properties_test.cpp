// Mass properties of closed triangle meshes (docs/physics.md §11) against closed forms:
// boxes, regular-polygon prisms, two disjoint boxes, each also rotated and translated.
#include "physics/mass_properties.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

namespace bookspin::physics {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

constexpr double kRelative = 1e-9;

struct Mesh {
  Eigen::Matrix3Xd vertices;
  Eigen::Matrix3Xi triangles;
};

/// Appends the triangles (a, b, c) and (a, c, d) of the quad a b c d (counter-clockwise
/// seen from outside).
void add_quad(std::vector<Eigen::Vector3i>& out, int a, int b, int c, int d) {
  out.emplace_back(a, b, c);
  out.emplace_back(a, c, d);
}

Eigen::Matrix3Xi to_matrix(const std::vector<Eigen::Vector3i>& triangles) {
  Eigen::Matrix3Xi m(3, static_cast<Eigen::Index>(triangles.size()));
  for (std::size_t i = 0; i < triangles.size(); ++i)
    m.col(static_cast<Eigen::Index>(i)) = triangles[i];
  return m;
}

/// A solid box of edge lengths `size`, centred at `centre`, axis-aligned, wound outward.
/// Vertex i has x = +, y = +, z = + where bit 0, 1, 2 of i is set.
Mesh box(const Vector3d& size, const Vector3d& centre = Vector3d::Zero()) {
  Mesh m;
  m.vertices.resize(3, 8);
  for (int i = 0; i < 8; ++i) {
    const Vector3d sign((i & 1) ? 1 : -1, (i & 2) ? 1 : -1, (i & 4) ? 1 : -1);
    m.vertices.col(i) = centre + 0.5 * sign.cwiseProduct(size);
  }
  std::vector<Eigen::Vector3i> t;
  add_quad(t, 0, 4, 6, 2);  // −x
  add_quad(t, 1, 3, 7, 5);  // +x
  add_quad(t, 0, 1, 5, 4);  // −y
  add_quad(t, 2, 6, 7, 3);  // +y
  add_quad(t, 0, 2, 3, 1);  // −z
  add_quad(t, 4, 5, 7, 6);  // +z
  m.triangles = to_matrix(t);
  return m;
}

/// A right prism over the regular n-gon of circumradius r, height h along z, centred at
/// the origin; caps fanned from their centres.
Mesh prism(int n, double r, double h) {
  Mesh m;
  m.vertices.resize(3, 2 * n + 2);
  for (int i = 0; i < n; ++i) {
    const double phi = 2.0 * std::numbers::pi * i / n;
    m.vertices.col(i) = Vector3d(r * std::cos(phi), r * std::sin(phi), -h / 2);
    m.vertices.col(n + i) = Vector3d(r * std::cos(phi), r * std::sin(phi), h / 2);
  }
  m.vertices.col(2 * n) = Vector3d(0, 0, -h / 2);
  m.vertices.col(2 * n + 1) = Vector3d(0, 0, h / 2);
  std::vector<Eigen::Vector3i> t;
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    t.emplace_back(2 * n, j, i);              // bottom, facing −z
    t.emplace_back(2 * n + 1, n + i, n + j);  // top, facing +z
    add_quad(t, i, j, n + j, n + i);          // side, facing outward
  }
  m.triangles = to_matrix(t);
  return m;
}

/// Both meshes as one (two shells).
Mesh combined(const Mesh& a, const Mesh& b) {
  Mesh m;
  m.vertices.resize(3, a.vertices.cols() + b.vertices.cols());
  m.vertices << a.vertices, b.vertices;
  m.triangles.resize(3, a.triangles.cols() + b.triangles.cols());
  m.triangles << a.triangles, (b.triangles.array() + static_cast<int>(a.vertices.cols())).matrix();
  return m;
}

Mesh moved(Mesh m, const Matrix3d& R, const Vector3d& t) {
  m.vertices = (R * m.vertices).colwise() + t;
  return m;
}

Mesh reversed(Mesh m) {
  m.triangles.row(1).swap(m.triangles.row(2));
  return m;
}

/// A rotation with no zero entries, so every product of inertia of a rotated box is nonzero.
Matrix3d some_rotation() {
  return Eigen::AngleAxisd(0.7, Vector3d(1, 2, 3).normalized()).toRotationMatrix();
}
const Vector3d kShift(3.0, -2.0, 5.0);

/// Inertia of a solid box about its centre, its axes: I_x = m/12 (b² + c²) …
Matrix3d box_inertia(double mass, const Vector3d& s) {
  return (mass / 12.0) * Vector3d(s.y() * s.y() + s.z() * s.z(), s.x() * s.x() + s.z() * s.z(),
                                  s.x() * s.x() + s.y() * s.y())
                             .asDiagonal();
}

/// Parallel-axis theorem: the inertia of a point mass m at offset d, m (|d|² 1 − d dᵀ).
Matrix3d point_inertia(double mass, const Vector3d& d) {
  return mass * (d.squaredNorm() * Matrix3d::Identity() - d * d.transpose());
}

MassProperties properties_of(const Mesh& m, double density = 1.0) {
  const MassPropertiesResult r = mass_properties(m.vertices, m.triangles, density);
  EXPECT_TRUE(r.ok()) << r.error;
  return r.properties;
}

std::string error_of(const Mesh& m) { return mass_properties(m.vertices, m.triangles).error; }

void expect_close(double actual, double expected, const char* what) {
  EXPECT_NEAR(actual, expected, kRelative * std::abs(expected)) << what;
}

void expect_close(const Eigen::MatrixXd& actual, const Eigen::MatrixXd& expected, double scale,
                  const char* what) {
  EXPECT_LE((actual - expected).norm(), kRelative * scale) << what << "\nactual\n"
                                                           << actual << "\nexpected\n"
                                                           << expected;
}

/// Volume, mass, centre and inertia as expected; the principal frame diagonalizes I_body,
/// is right-handed and its moments ascend.
void expect_properties(const MassProperties& p, double volume, double mass, const Vector3d& com,
                       const Matrix3d& I_body) {
  expect_close(p.volume, volume, "volume");
  expect_close(p.mass, mass, "mass");
  expect_close(p.center_of_mass, com, com.norm() + std::cbrt(volume), "centre of mass");
  expect_close(p.I_body, I_body, I_body.norm(), "I_body");
  const Eigen::Vector3d moments = Eigen::SelfAdjointEigenSolver<Matrix3d>(I_body).eigenvalues();
  expect_close(p.principal_moments, moments, I_body.norm(), "principal moments");
  EXPECT_LE(p.principal_moments(0), p.principal_moments(1));
  EXPECT_LE(p.principal_moments(1), p.principal_moments(2));
  expect_close(p.principal_axes * p.principal_axes.transpose(), Matrix3d::Identity(), 1.0,
               "axes orthonormal");
  EXPECT_NEAR(p.principal_axes.determinant(), 1.0, 1e-12) << "right-handed";
  expect_close(p.principal_axes * p.I_body * p.principal_axes.transpose(),
               Matrix3d(p.principal_moments.asDiagonal()), I_body.norm(), "axes diagonalize");
}

TEST(MassProperties, BoxMatchesTheSolidCuboid) {
  const Vector3d size(1.878, 2.9085, 0.5);
  const double density = 2.5;
  const double volume = size.prod();
  const MassProperties p = properties_of(box(size), density);
  expect_properties(p, volume, density * volume, Vector3d::Zero(),
                    box_inertia(density * volume, size));
  EXPECT_EQ(p.shells, 1);
  EXPECT_TRUE(p.warnings.empty());
  // Ascending: y (smallest), x, z; the axes are the box's, rows ± e_y, ± e_x, ± e_z.
  EXPECT_NEAR(std::abs(p.principal_axes(0, 1)), 1.0, 1e-12);
  EXPECT_NEAR(std::abs(p.principal_axes(1, 0)), 1.0, 1e-12);
  EXPECT_NEAR(std::abs(p.principal_axes(2, 2)), 1.0, 1e-12);
}

// Rotating the body by R turns its inertia into R I Rᵀ: nonzero products of inertia, each
// with the sign the minus convention gives (I_xy = −∫xy).
TEST(MassProperties, RotatedAndTranslatedBoxTransformsAsRIRt) {
  const Vector3d size(1.0, 2.0, 3.0);
  const Matrix3d R = some_rotation();
  const MassProperties p = properties_of(moved(box(size), R, kShift));
  const double volume = size.prod();
  const Matrix3d expected = R * box_inertia(volume, size) * R.transpose();
  expect_properties(p, volume, volume, kShift, expected);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (i != j) {
        EXPECT_GT(std::abs(expected(i, j)), 0.05) << "a real off-diagonal test";
      }
    }
  }
  // The principal axes are the box's edges, turned by R: column k of R for box axis k.
  // Box moments, ascending: x (2²+3²), y (1²+3²), z (1²+2²) → order z, y, x.
  const int order[3] = {2, 1, 0};
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(std::abs(p.principal_axes.row(i).dot(R.col(order[i]))), 1.0, 1e-9) << i;
}

// The principal frame's signs are the documented ones (mass_properties.hpp): rows 0 and 1
// with their largest-magnitude component positive, row 2 = row 0 × row 1. Twenty random
// turns of a box with three different sides: each row is ± the turned box edge, the sign
// chosen here from the rule.
TEST(MassProperties, PrincipalAxesOfRotatedBoxesAreTheTurnedEdgesWithTheDocumentedSigns) {
  const Vector3d size(1.0, 2.0, 3.0);
  const int order[3] = {2, 1, 0};  // ascending moments: z, y, x
  std::mt19937_64 engine(99);
  std::normal_distribution<double> normal;
  int flipped = 0;
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::Quaterniond q(normal(engine), normal(engine), normal(engine), normal(engine));
    const Matrix3d R = q.normalized().toRotationMatrix();
    const MassProperties p = properties_of(moved(box(size), R, kShift));
    Matrix3d expected;
    for (int i = 0; i < 2; ++i) {
      Vector3d axis = R.col(order[i]);
      Eigen::Index largest = 0;
      axis.cwiseAbs().maxCoeff(&largest);
      if (axis[largest] < 0.0) {
        axis = -axis;
        ++flipped;
      }
      expected.row(i) = axis.transpose();
    }
    expected.row(2) = expected.row(0).cross(expected.row(1));
    EXPECT_LE((p.principal_axes - expected).cwiseAbs().maxCoeff(), 1e-9)
        << "trial " << trial << "\nactual\n"
        << p.principal_axes << "\nexpected\n"
        << expected;
  }
  EXPECT_GT(flipped, 5);  // the rule was exercised both ways
}

// An independent check of one off-diagonal sign: a box stretched along x = y in the xy plane
// has mass where xy > 0, so ∫xy > 0 and I_xy < 0.
TEST(MassProperties, ProductOfInertiaEntersWithAMinusSign) {
  const Matrix3d R = Eigen::AngleAxisd(std::numbers::pi / 4, Vector3d::UnitZ()).toRotationMatrix();
  const MassProperties p = properties_of(moved(box(Vector3d(4, 1, 1)), R, Vector3d::Zero()));
  // ∫xy over the stretched box: (m/12)(a² − b²)/2 for a 45° turn, m = 4.
  expect_close(p.I_body(0, 1), -(4.0 / 12.0) * (16.0 - 1.0) / 2.0, "I_xy");
  expect_close(p.I_body(1, 0), p.I_body(0, 1), "symmetric");
}

// The prism over a regular n-gon of circumradius r: polygon area A = (n/2) r² sin θ,
// polar moment J = A r² (2 + cos θ)/6 (θ = 2π/n, one triangle per side from the centre), so
// I_z = m r² (2 + cos θ)/6 and I_x = I_y = m r² (2 + cos θ)/12 + m h²/12.
TEST(MassProperties, PolygonalPrismMatchesItsExactInertiaAndTendsToTheCylinder) {
  const double r = 0.8, h = 2.5;
  for (const int n : {3, 7, 64, 720}) {
    const double theta = 2.0 * std::numbers::pi / n;
    const double area = 0.5 * n * r * r * std::sin(theta);
    const double mass = area * h;
    const double in_plane = mass * r * r * (2.0 + std::cos(theta)) / 12.0;
    const Matrix3d I =
        Vector3d(in_plane + mass * h * h / 12.0, in_plane + mass * h * h / 12.0, 2.0 * in_plane)
            .asDiagonal();
    SCOPED_TRACE(n);
    expect_properties(properties_of(prism(n, r, h)), area * h, mass, Vector3d::Zero(), I);
    const Matrix3d R = some_rotation();
    expect_properties(properties_of(moved(prism(n, r, h), R, kShift)), area * h, mass, kShift,
                      R * I * R.transpose());
  }
  // The cylinder: I_z = m r²/2 within the polygon's error 1 − cos θ ≈ θ²/2.
  const MassProperties fine = properties_of(prism(720, r, h));
  const double theta = 2.0 * std::numbers::pi / 720;
  EXPECT_NEAR(fine.I_body(2, 2) / (fine.mass * r * r / 2.0), 1.0, theta * theta);
  EXPECT_NEAR(fine.volume / (std::numbers::pi * r * r * h), 1.0, theta * theta);
}

// Two disjoint boxes: two shells that add up; the inertia about the common centre of mass by
// the parallel-axis theorem, by hand.
TEST(MassProperties, TwoDisjointBoxesAddUpByTheParallelAxisTheorem) {
  const Vector3d s1(1.0, 2.0, 3.0), c1(-2.0, 0.5, 0.0);
  const Vector3d s2(0.5, 0.5, 4.0), c2(3.0, 1.0, -1.0);
  const double m1 = s1.prod(), m2 = s2.prod();
  const Vector3d com = (m1 * c1 + m2 * c2) / (m1 + m2);
  const Matrix3d I = box_inertia(m1, s1) + point_inertia(m1, c1 - com) + box_inertia(m2, s2) +
                     point_inertia(m2, c2 - com);
  const Mesh two = combined(box(s1, c1), box(s2, c2));
  const MassProperties p = properties_of(two);
  EXPECT_EQ(p.shells, 2);
  expect_properties(p, m1 + m2, m1 + m2, com, I);
  EXPECT_NE(I(0, 2), 0.0);  // the offsets couple x and z

  const Matrix3d R = some_rotation();
  expect_properties(properties_of(moved(two, R, kShift)), m1 + m2, m1 + m2, R * com + kShift,
                    R * I * R.transpose());
}

TEST(MassProperties, InwardWoundBoxIsTurnedAroundWithAWarning) {
  const Vector3d size(1.0, 2.0, 3.0);
  const MassProperties p = properties_of(moved(reversed(box(size)), some_rotation(), kShift));
  const Matrix3d R = some_rotation();
  expect_properties(p, size.prod(), size.prod(), kShift,
                    R * box_inertia(size.prod(), size) * R.transpose());
  ASSERT_EQ(p.warnings.size(), 1u);
  EXPECT_EQ(
      p.warnings[0],
      "the mesh is wound inward (negative volume) and lies inside no other shell; turned around");
}

TEST(MassProperties, OnlyTheInwardShellIsTurnedAround) {
  const Mesh two =
      combined(box(Vector3d(1, 1, 1)), reversed(box(Vector3d(1, 2, 1), Vector3d(5, 0, 0))));
  const MassProperties p = properties_of(two);
  expect_close(p.volume, 3.0, "volume");
  ASSERT_EQ(p.warnings.size(), 1u);
  EXPECT_EQ(p.warnings[0],
            "shell 2 of 2 is wound inward (negative volume) and lies inside no other shell; turned "
            "around");
}

TEST(MassProperties, WithMassScalesMassAndInertiaOnly) {
  const Vector3d size(1.0, 2.0, 3.0);
  const MassProperties p = with_mass(properties_of(box(size, kShift)), 12.0);
  expect_properties(p, 6.0, 12.0, kShift, box_inertia(12.0, size));
}

// One quad removed: its four outer edges are now used by one triangle each (the diagonal
// went with both triangles).
TEST(MassProperties, OpenBoxIsRejectedWithItsBoundaryEdgeCount) {
  Mesh open = box(Vector3d(1, 2, 3));
  open.triangles.conservativeResize(3, open.triangles.cols() - 2);
  EXPECT_EQ(error_of(open), "open mesh: 4 boundary edges");
}

TEST(MassProperties, OneFlippedTriangleIsInconsistentWinding) {
  Mesh m = box(Vector3d(1, 2, 3));
  m.triangles.col(5).tail<2>().reverseInPlace();
  EXPECT_EQ(error_of(m),
            "inconsistent winding: 3 edges run the same way in both of their triangles");
}

TEST(MassProperties, ThreeTrianglesOnOneEdgeAreNonManifold) {
  Mesh m = combined(box(Vector3d(1, 1, 1)), box(Vector3d(1, 1, 1), Vector3d(1, 1, 0)));
  // Weld the second box's edge x = y = 0.5 onto the first's: that edge now has four
  // triangles.
  for (Eigen::Index v = 8; v < 16; ++v) {
    for (Eigen::Index u = 0; u < 8; ++u) {
      if (m.vertices.col(v) == m.vertices.col(u))
        m.triangles =
            (m.triangles.array() == static_cast<int>(v)).select(static_cast<int>(u), m.triangles);
    }
  }
  EXPECT_EQ(error_of(m), "non-manifold mesh: 1 edges shared by more than two triangles");
}

// A triangle, both sides: closed (every edge twice, opposite ways) but flat.
TEST(MassProperties, FlatClosedSheetHasZeroVolume) {
  Mesh m;
  m.vertices.resize(3, 3);
  m.vertices << 0, 1, 0, 0, 0, 1, 2, 2, 2;
  m.triangles.resize(3, 2);
  m.triangles << 0, 0, 1, 2, 2, 1;
  EXPECT_EQ(error_of(m), "zero volume: the mesh encloses no space");
}

TEST(MassProperties, NaNVertexIsRejected) {
  Mesh m = box(Vector3d(1, 2, 3));
  m.vertices(0, 3) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(error_of(m), "non-finite vertex coordinate (vertex 4)");
}

TEST(MassProperties, EmptyMeshIsRejected) {
  EXPECT_EQ(error_of(Mesh{Eigen::Matrix3Xd(3, 0), Eigen::Matrix3Xi(3, 0)}),
            "empty mesh: no triangles");
  Mesh degenerate = box(Vector3d(1, 1, 1));
  degenerate.triangles.row(1) = degenerate.triangles.row(0);  // every triangle repeats a vertex
  EXPECT_EQ(error_of(degenerate), "empty mesh: no triangles");
}

}  // namespace
}  // namespace bookspin::physics
