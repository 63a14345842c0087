// The lattice that fills a closed body (docs/physics.md §13): the one-cell book, the
// inertia's convergence to the mesh's, the surface embedding.
#include "physics/lattice.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "lattice_shapes.hpp"
#include "physics/book.hpp"

namespace bookspin::physics {
namespace {

using testing::box_surface;
using testing::cylinder_surface;
using testing::principal;
using testing::Surface;
using testing::t_surface;

Surface book_surface() {
  const Book book;
  return box_surface(-0.5 * book.size, 0.5 * book.size);
}

// n = 1 on a box is the paper's particle book: its 8 corners, M/8 each, 28 springs of
// stiffness factor 1 in corner-pair order, all bit for bit.
TEST(Lattice, OneCellBoxIsTheParticleBook) {
  const Book book;
  const Surface s = book_surface();
  const Lattice lat = build_lattice(s.vertices, s.triangles, book.mass, 1);
  ASSERT_EQ(lat.particles(), 8);
  ASSERT_EQ(lat.spring_count(), 28);
  const Corners corners = book.body_corners();
  for (int p = 0; p < 8; ++p) {
    EXPECT_EQ(lat.mass[p], book.mass / 8.0);
    for (int d = 0; d < 3; ++d) EXPECT_EQ(lat.rest(d, p), corners(d, p)) << p << " " << d;
  }
  int s_index = 0;
  for (int i = 0; i < 8; ++i)
    for (int j = i + 1; j < 8; ++j, ++s_index) {
      EXPECT_EQ(lat.springs(0, s_index), i);
      EXPECT_EQ(lat.springs(1, s_index), j);
      EXPECT_EQ(lat.stiffness[s_index], 1.0);
      EXPECT_EQ(lat.rest_length[s_index], (corners.col(i) - corners.col(j)).norm());
    }
  // Corner masses: 3× the solid's inertia (docs/physics.md §2), sorted ascending.
  Eigen::Vector3d three = 3.0 * book.principal_moments();
  std::sort(three.data(), three.data() + 3);
  EXPECT_LE((lat.principal_moments - three).cwiseAbs().maxCoeff(), 1e-12 * three.maxCoeff());
}

// An interior spring is the sum of the cells that share it: on a 2×2×2 cube the edge
// through the middle belongs to 4 cells, a face diagonal in a middle plane to 2, a body
// diagonal to 1; each cell adds f/n = 1/2.
TEST(Lattice, SharedSpringsAddTheirCells) {
  const Surface s = box_surface({0, 0, 0}, {1, 1, 1});
  const Lattice lat = build_lattice(s.vertices, s.triangles, 1.0, 2);
  ASSERT_EQ(lat.particles(), 27);
  // 27 nodes: 54 edges, 3·(2·... ) counted directly from the rule instead:
  // edges 3·2·9 = 54, face diagonals 3 planes-orientations · 2 · (2·2 cells) · 3 layers = 72,
  // body diagonals 4 · 8 = 32.
  EXPECT_EQ(lat.spring_count(), 54 + 72 + 32);
  const auto find = [&](int i, int j) {
    for (int sp = 0; sp < lat.spring_count(); ++sp)
      if (lat.springs(0, sp) == i && lat.springs(1, sp) == j) return lat.stiffness[sp];
    return -1.0;
  };
  // Node (i, j, k) is particle i + 3j + 9k.
  EXPECT_DOUBLE_EQ(find(4, 13), 4 * 0.5);   // (1,1,0)–(1,1,1): edge of 4 cells
  EXPECT_DOUBLE_EQ(find(0, 1), 0.5);        // (0,0,0)–(1,0,0): outer edge, 1 cell
  EXPECT_DOUBLE_EQ(find(10, 12), 0.5 * 2);  // (1,0,1)–(0,1,1): face diagonal of 2 cells
  EXPECT_DOUBLE_EQ(find(1, 3), 0.5);        // (1,0,0)–(0,1,0): on the surface, 1 cell
  EXPECT_DOUBLE_EQ(find(0, 13), 0.5);       // body diagonal
  EXPECT_DOUBLE_EQ(lat.mass.sum(), 1.0);
  EXPECT_DOUBLE_EQ(lat.mass[13], 8.0 / 64.0);  // the middle node: 8 cells of 1/8 each /8
  EXPECT_DOUBLE_EQ(lat.mass[0], 1.0 / 64.0);
}

struct Row {
  int n;
  double error;  ///< largest relative error of the principal moments
};

std::vector<Row> convergence(const char* name, const Surface& body, double mass,
                             std::initializer_list<int> ns) {
  MassProperties props;
  const Surface s = principal(body, mass, props);
  std::vector<Row> rows;
  std::printf("%s: mesh principal moments %.6f %.6f %.6f\n", name, props.principal_moments[0],
              props.principal_moments[1], props.principal_moments[2]);
  for (int n : ns) {
    const Lattice lat = build_lattice(s.vertices, s.triangles, mass, n);
    const Eigen::Vector3d rel =
        (lat.principal_moments - props.principal_moments).cwiseQuotient(props.principal_moments);
    const double error = rel.cwiseAbs().maxCoeff();
    std::printf(
        "  n=%2d cells %6d particles %6d springs %7d  moments %.6f %.6f %.6f  "
        "rel err %+.4f %+.4f %+.4f  volume err %+.5f  com %.1e\n",
        n, lat.cells_kept, lat.particles(), lat.spring_count(), lat.principal_moments[0],
        lat.principal_moments[1], lat.principal_moments[2], rel[0], rel[1], rel[2],
        lat.volume / props.volume - 1.0, lat.center_of_mass.norm());
    EXPECT_NEAR(lat.total_mass, mass, 1e-12 * mass);
    rows.push_back({n, error});
  }
  return rows;
}

// The lattice's inertia tends to the mesh's as the cells shrink (O(h²): docs/physics.md
// §13). A box the grid divides exactly is the trapezoid rule per axis: the corner masses
// add M h_d²/6 to the second moment along each axis d, so the moments are exactly
// I_solid + (M/6)(h_j² + h_k²).
TEST(Lattice, BoxInertiaConverges) {
  const Eigen::Vector3d size(2.0, 1.0, 0.5);
  const double M = 3.0;
  const auto rows =
      convergence("box 2 x 1 x 0.5", box_surface({0, 0, 0}, size), M, {2, 4, 8, 16, 24, 32});
  for (std::size_t r = 1; r < rows.size(); ++r) EXPECT_LT(rows[r].error, rows[r - 1].error);
  for (int n : {2, 8, 24}) {
    const Surface s = box_surface(-0.5 * size, 0.5 * size);
    const Lattice lat = build_lattice(s.vertices, s.triangles, M, n);
    const Eigen::Vector3d h2 = lat.cell_size.cwiseProduct(lat.cell_size);
    const Eigen::Vector3d sq = size.cwiseProduct(size);
    for (int d = 0; d < 3; ++d) {
      const int j = (d + 1) % 3, k = (d + 2) % 3;
      const double expected = M / 12.0 * (sq[j] + sq[k]) + M / 6.0 * (h2[j] + h2[k]);
      EXPECT_NEAR(lat.inertia(d, d), expected, 1e-12 * expected) << "n = " << n << " axis " << d;
    }
  }
}

TEST(Lattice, CylinderInertiaConverges) {
  const auto rows = convergence("cylinder r 0.5 h 2 (48 sides)", cylinder_surface(0.5, 2.0, 48),
                                2.0, {4, 8, 16, 24, 32});
  for (std::size_t r = 1; r < rows.size(); ++r) EXPECT_LT(rows[r].error, rows[r - 1].error);
  EXPECT_LT(rows[3].error, 0.03);  // n = 24
}

TEST(Lattice, TShapeInertiaConvergesWithin2PercentAt24) {
  const auto rows = convergence("T (two boxes)", t_surface(), 1.0, {4, 8, 12, 16, 24, 32, 48});
  for (std::size_t r = 1; r < rows.size(); ++r) EXPECT_LT(rows[r].error, rows[r - 1].error);
  EXPECT_LT(rows[4].error, 0.02);  // n = 24 = kDefaultLatticeCells
  static_assert(kDefaultLatticeCells == 24, "the assertion above is about the default");
}

// One closed shell with the same T outline gives the same lattice as the two touching
// boxes, and an inward-wound shell counts as outward.
TEST(Lattice, ShellsAndWindingDoNotChangeTheFill) {
  const Surface t = t_surface();
  Surface flipped = t;
  flipped.triangles.row(1).swap(flipped.triangles.row(2));
  const Lattice a = build_lattice(t.vertices, t.triangles, 1.0, 12);
  const Lattice b = build_lattice(flipped.vertices, flipped.triangles, 1.0, 12);
  EXPECT_EQ(a.particles(), b.particles());
  EXPECT_EQ(a.spring_count(), b.spring_count());
  EXPECT_EQ((a.mass - b.mass).cwiseAbs().maxCoeff(), 0.0);
  // Unwelded (every triangle with its own three vertices, as a mesh with per-face normals
  // comes): the same fill.
  // Moved off the origin, so that some faces' cones from the origin have negative volume.
  MassProperties props;
  Surface centred = testing::principal(t, 1.0, props);
  centred.vertices.colwise() += Eigen::Vector3d(0.3, -0.2, 5.0);
  Surface loose;
  loose.vertices.resize(3, 3 * centred.triangles.cols());
  loose.triangles.resize(3, centred.triangles.cols());
  for (Eigen::Index tri = 0; tri < centred.triangles.cols(); ++tri)
    for (int e = 0; e < 3; ++e) {
      loose.vertices.col(3 * tri + e) = centred.vertices.col(centred.triangles(e, tri));
      loose.triangles(e, tri) = static_cast<int>(3 * tri + e);
    }
  const Lattice c = build_lattice(centred.vertices, centred.triangles, 1.0, 12);
  const Lattice d = build_lattice(loose.vertices, loose.triangles, 1.0, 12);
  EXPECT_EQ(c.particles(), d.particles());
  EXPECT_LE((c.mass - d.mass).cwiseAbs().maxCoeff(), 1e-15);
}

// Overlapping shells add up (as in mass_properties): a box given twice weighs the same per
// particle as one box, since the mass is shared out by filled samples.
TEST(Lattice, OverlappingShellsAddUp) {
  const Surface one = box_surface({0, 0, 0}, {1, 2, 1});
  const Surface two = testing::join(one, box_surface({0, 0, 0}, {1, 1, 1}));
  const Lattice a = build_lattice(two.vertices, two.triangles, 3.0, 4);
  // The lower half holds twice the density: its centre of mass moves down from y = 1.
  EXPECT_NEAR(a.center_of_mass.y(), (1.0 * 2.0 + 0.5 * 1.0) / 3.0, 0.1);
  EXPECT_LT(a.center_of_mass.y(), 0.9);
}

// At rest the embedded surface is the surface, vertex by vertex (trilinear interpolation
// reproduces any affine field, here the identity).
TEST(Lattice, EmbeddedSurfaceAtRestIsTheSurface) {
  MassProperties props;
  for (const Surface& body : {t_surface(), cylinder_surface(0.5, 2.0, 48), book_surface()}) {
    const Surface s = principal(body, 1.0, props);
    for (int n : {1, 3, 8, 24}) {
      const Lattice lat = build_lattice(s.vertices, s.triangles, 1.0, n);
      const Eigen::Matrix3Xd out = lat.embed_surface(lat.rest);
      EXPECT_LE((out - s.vertices).cwiseAbs().maxCoeff(), 1e-12) << "n = " << n;
      // Rigid motions are carried exactly too (affine fields).
      const Eigen::Matrix3d R =
          Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
      const Eigen::Vector3d shift(0.3, -1.0, 2.0);
      const Eigen::Matrix3Xd moved = lat.embed_surface((R * lat.rest).colwise() + shift);
      EXPECT_LE((moved - ((R * s.vertices).colwise() + shift)).cwiseAbs().maxCoeff(), 1e-12);
    }
  }
}

TEST(Lattice, BadInputIsRejected) {
  const Surface s = box_surface({0, 0, 0}, {1, 1, 1});
  EXPECT_THROW(build_lattice(s.vertices, s.triangles, 1.0, 0), std::invalid_argument);
  EXPECT_THROW(build_lattice(s.vertices, s.triangles, 1.0, kMaxLatticeCells + 1),
               std::invalid_argument);
  EXPECT_THROW(build_lattice(s.vertices, s.triangles, 0.0, 4), std::invalid_argument);
  EXPECT_THROW(build_lattice(s.vertices, Eigen::Matrix3Xi(3, 0), 1.0, 4), std::invalid_argument);
  Eigen::Matrix3Xd nan = s.vertices;
  nan(0, 0) = std::nan("");
  EXPECT_THROW(build_lattice(nan, s.triangles, 1.0, 4), std::invalid_argument);
  const Lattice lat = build_lattice(s.vertices, s.triangles, 1.0, 2);
  EXPECT_THROW(lat.embed_surface(Eigen::Matrix3Xd(3, 5)), std::invalid_argument);
  // The finest lattice allowed is built: 64³ cells, 65³ particles.
  EXPECT_EQ(build_lattice(s.vertices, s.triangles, 1.0, kMaxLatticeCells).particles(),
            (kMaxLatticeCells + 1) * (kMaxLatticeCells + 1) * (kMaxLatticeCells + 1));
}

}  // namespace
}  // namespace bookspin::physics
