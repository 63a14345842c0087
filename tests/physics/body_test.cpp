// The body as a parameter (docs/physics.md §12): presets, a mesh moved into its principal
// frame, the rigid and exact models of a non-book body, and cos_principal_L.
#include "physics/body.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "physics/exact_model.hpp"
#include "physics/lattice_model.hpp"
#include "physics/mass_properties.hpp"
#include "physics/presets.hpp"
#include "physics/shape.hpp"
#include "physics/simulator.hpp"
#include "support/flip_timer.hpp"

namespace bookspin::physics {
namespace {

/// The box [0, a]×[0, b]×[0, c] as 8 vertices and 12 outward triangles.
void box_mesh(const Eigen::Vector3d& size, Eigen::Matrix3Xd& vertices,
              Eigen::Matrix3Xi& triangles) {
  vertices.resize(3, 8);
  for (int p = 0; p < 8; ++p)
    for (int d = 0; d < 3; ++d) vertices(d, p) = ((p >> d) & 1) ? size[d] : 0.0;
  // Faces as corner quads (counter-clockwise seen from outside), bit d = axis d.
  const int quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  triangles.resize(3, 12);
  for (int f = 0; f < 6; ++f) {
    triangles.col(2 * f) << quads[f][0], quads[f][1], quads[f][2];
    triangles.col(2 * f + 1) << quads[f][0], quads[f][2], quads[f][3];
  }
}

TEST(Body, BookBodyIsTheBookWithItsMomentsAndNoSurface) {
  Book book;
  book.size = {1.0, 2.0, 3.0};
  book.mass = 5.0;
  const Body body = book_body(book);
  EXPECT_EQ(body.shape, BodyShape::book);
  EXPECT_EQ(body.cage.size, book.size);
  EXPECT_EQ(body.moments, book.principal_moments());
  EXPECT_EQ(body.vertices.cols(), 0);
  const std::array<int, 3> book_order = principal_order(Book{}.principal_moments());
  EXPECT_EQ(book_order, (std::array<int, 3>{1, 0, 2}));  // the default book: y, x, z
}

// A cube's moments m(a² + a²)/12 are one value; a 1 × 1 × 2 box's are two (the square's axis

// book_with_moments inverts the cuboid's moments: its box, integrated as a mesh by
// mass_properties (not the book's formula), has the moments asked for; the default book's
// moments give back its own sides; moments that break the triangle inequality, or a flat
// body's (I_x + I_y = I_z), give no box.
TEST(Body, BookWithMomentsHasThoseMomentsOrIsNone) {
  const Eigen::Vector3d wanted(0.8235, 0.1812, 1.0);  // a phone's: x intermediate, y smallest
  const std::optional<Book> book = book_with_moments(wanted, 2.5);
  ASSERT_TRUE(book.has_value());
  EXPECT_EQ(book->mass, 2.5);
  Eigen::Matrix3Xd vertices;
  Eigen::Matrix3Xi triangles;
  box_mesh(book->size, vertices, triangles);
  const MassPropertiesResult mass = mass_properties(vertices, triangles);
  ASSERT_TRUE(mass.ok()) << mass.error;
  const double density = 2.5 / mass.properties.volume;
  // The box is axis-aligned: its principal moments, ascending, are about y, x, z.
  const Eigen::Vector3d ascending = density * mass.properties.principal_moments;
  EXPECT_NEAR(ascending[0], wanted.y(), 1e-12);
  EXPECT_NEAR(ascending[1], wanted.x(), 1e-12);
  EXPECT_NEAR(ascending[2], wanted.z(), 1e-12);
  const Book original;
  const std::optional<Book> again = book_with_moments(original.principal_moments(), original.mass);
  ASSERT_TRUE(again.has_value());
  EXPECT_LT((again->size - original.size).norm(), 1e-12);
  EXPECT_FALSE(book_with_moments({0.2, 0.7, 1.0}, 1.0).has_value());    // 0.2 + 0.7 < 1
  EXPECT_FALSE(book_with_moments({0.25, 0.75, 1.0}, 1.0).has_value());  // flat: c = 0
  EXPECT_FALSE(book_with_moments({0.8, 0.2, 1.0}, 0.0).has_value());
}
// apart); the book's three differ. Within 1e-12 counts as equal, 1e-9 apart does not.
TEST(Body, DistinctMomentsCountsTheCubeTheSymmetricBodyAndTheBook) {
  Book cube;
  cube.size = {1.0, 1.0, 1.0};
  EXPECT_EQ(distinct_moments(cube.principal_moments()), 1);
  Book bar;
  bar.size = {1.0, 1.0, 2.0};
  EXPECT_EQ(distinct_moments(bar.principal_moments()), 2);
  EXPECT_EQ(distinct_moments(Book{}.principal_moments()), 3);
  EXPECT_EQ(distinct_moments({2.0, 2.0 * (1 + 1e-13), 2.0}), 1);
  EXPECT_EQ(distinct_moments({2.0, 2.0 * (1 + 1e-9), 2.0}), 2);
  EXPECT_EQ(distinct_moments({3.0, 1.0, 3.0}), 2);
}

TEST(Body, ShapeNamesRoundTrip) {
  for (BodyShape shape : {BodyShape::book, BodyShape::t_handle, BodyShape::tennis_racket,
                          BodyShape::phone, BodyShape::mesh}) {
    BodyShape parsed = BodyShape::book;
    EXPECT_TRUE(parse_body_shape(to_string(shape), parsed)) << to_string(shape);
    EXPECT_EQ(parsed, shape);
  }
  BodyShape parsed = BodyShape::phone;
  EXPECT_FALSE(parse_body_shape("wing-nut", parsed));
  EXPECT_EQ(parsed, BodyShape::phone);
}

TEST(Body, RotatedTranslatedBoxGoesToItsPrincipalFrame) {
  // Box 3 × 1 × 2, mass 2, scaled by 1.5, turned by an arbitrary rotation and moved.
  Eigen::Matrix3Xd box;
  Eigen::Matrix3Xi triangles;
  box_mesh({3.0, 1.0, 2.0}, box, triangles);
  const Eigen::Matrix3d turn =
      (Eigen::AngleAxisd(0.7, Eigen::Vector3d(1.0, 2.0, -0.5).normalized()) *
       Eigen::AngleAxisd(-1.9, Eigen::Vector3d(0.3, -1.0, 0.8).normalized()))
          .toRotationMatrix();
  const Eigen::Vector3d shift(4.0, -7.0, 2.5);
  const Eigen::Matrix3Xd vertices = (turn * box).colwise() + shift;
  const double mass = 2.0, scale = 1.5;
  const BodyResult result = body_from_mesh(vertices, triangles, mass, scale);
  ASSERT_TRUE(result.ok()) << result.error;
  const Body& body = result.body;
  EXPECT_TRUE(result.warnings.empty());
  EXPECT_EQ(body.shape, BodyShape::mesh);
  // Sides 4.5, 1.5, 3: I = M/12 (b² + c²) per axis, ascending about the longest side first.
  const double a = 4.5, b = 1.5, c = 3.0;
  const Eigen::Vector3d expected(mass / 12 * (b * b + c * c), mass / 12 * (a * a + b * b),
                                 mass / 12 * (a * a + c * c));
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(body.moments[i], expected[i], 1e-12 * expected[i]);
  // The surface: centre of mass at the origin, the box's sides along x (4.5), y (3), z (1.5).
  EXPECT_NEAR(body.vertices.rowwise().mean().norm(), 0.0, 1e-12);
  EXPECT_NEAR(body.cage.size.x(), a, 1e-12);
  EXPECT_NEAR(body.cage.size.y(), c, 1e-12);
  EXPECT_NEAR(body.cage.size.z(), b, 1e-12);
  EXPECT_EQ(body.cage.mass, mass);
  // The map from the input to the principal frame is a proper rotation (right-handed frame):
  // solve v' − v'0 = A (v − v0) over three independent edges.
  Eigen::Matrix3d from, to;
  for (int k = 0; k < 3; ++k) {
    from.col(k) = scale * (vertices.col(1 << k) - vertices.col(0));
    to.col(k) = body.vertices.col(1 << k) - body.vertices.col(0);
  }
  const Eigen::Matrix3d A = to * from.inverse();
  EXPECT_NEAR(A.determinant(), 1.0, 1e-12);
  EXPECT_LT((A.transpose() * A - Eigen::Matrix3d::Identity()).norm(), 1e-12);
  // Inertia of the moved surface is diagonal: the moments about x, y, z.
  const MassPropertiesResult moved = mass_properties(body.vertices, body.triangles);
  ASSERT_TRUE(moved.ok());
  const Eigen::Matrix3d I = with_mass(moved.properties, mass).I_body;
  EXPECT_LT((I - Eigen::Matrix3d(expected.asDiagonal())).norm(), 1e-12 * expected.norm());
  EXPECT_EQ(body.face_colours.cols(), triangles.cols());
}

TEST(Body, InwardMeshIsTurnedAroundWithAWarning) {
  Eigen::Matrix3Xd box;
  Eigen::Matrix3Xi triangles;
  box_mesh({1.0, 2.0, 3.0}, box, triangles);
  triangles.row(1).swap(triangles.row(2));
  const BodyResult result = body_from_mesh(box, triangles, 1.0, 1.0);
  ASSERT_TRUE(result.ok()) << result.error;
  EXPECT_EQ(result.warnings.size(), 1u);
  // The stored triangles face outwards again: positive signed volume.
  const MassPropertiesResult again = mass_properties(result.body.vertices, result.body.triangles);
  ASSERT_TRUE(again.ok());
  EXPECT_TRUE(again.properties.warnings.empty());
}

TEST(Body, BadInputGivesAnErrorNotAnException) {
  Eigen::Matrix3Xd box;
  Eigen::Matrix3Xi triangles;
  box_mesh({1.0, 2.0, 3.0}, box, triangles);
  EXPECT_NE(body_from_mesh(box, triangles, 0.0, 1.0).error, "");
  EXPECT_NE(body_from_mesh(box, triangles, 1.0, -1.0).error, "");
  EXPECT_NE(body_from_mesh(box, triangles, std::nan(""), 1.0).error, "");
  const Eigen::Matrix3Xi open = triangles.leftCols(10);
  EXPECT_EQ(body_from_mesh(box, open, 1.0, 1.0).error.rfind("open mesh", 0), 0u);
}

/// The preset moments at mass 1 and scale 1, as printed in docs/physics.md §12.
struct PresetCase {
  BodyShape shape;
  Eigen::Vector3d moments;
};

const std::vector<PresetCase>& preset_cases() {
  static const std::vector<PresetCase> cases{
      {BodyShape::t_handle, {0.208976837, 0.421269931, 0.594937591}},
      {BodyShape::tennis_racket, {0.0737260759, 0.587384713, 0.657657675}},
      {BodyShape::phone, {0.170315622, 0.728702617, 0.894606596}},
  };
  return cases;
}

TEST(Presets, AreClosedOutwardAndHaveTheDocumentedDistinctMoments) {
  for (const PresetCase& c : preset_cases()) {
    SCOPED_TRACE(std::string(to_string(c.shape)));
    const PresetMesh mesh = preset_mesh(c.shape);
    EXPECT_EQ(mesh.face_colours.cols(), mesh.triangles.cols());
    EXPECT_TRUE((mesh.face_colours.array() >= 0.0f).all() &&
                (mesh.face_colours.array() <= 1.0f).all());
    const MassPropertiesResult props = mass_properties(mesh.vertices, mesh.triangles);
    ASSERT_TRUE(props.ok()) << props.error;          // closed, consistently wound
    EXPECT_TRUE(props.properties.warnings.empty());  // every shell wound outwards
    const Body body = preset_body(c.shape);
    EXPECT_EQ(body.shape, c.shape);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(body.moments[i], c.moments[i], 1e-6 * c.moments[i]);
    // Clearly distinct: each moment at least 10% above the one before.
    EXPECT_GT(body.moments[1], 1.1 * body.moments[0]);
    EXPECT_GT(body.moments[2], 1.1 * body.moments[1]);
    // Comparable to the book (~2–3 length units), so the default camera frames it.
    EXPECT_GT(body.cage.size.maxCoeff(), 2.0);
    EXPECT_LT(body.cage.size.maxCoeff(), 3.5);
    // Mass and scale: I ∝ M·s².
    const Body heavy = preset_body(c.shape, 3.0, 2.0);
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(heavy.moments[i], 12.0 * body.moments[i], 1e-12 * heavy.moments[i]);
  }
  EXPECT_THROW(preset_mesh(BodyShape::book), std::invalid_argument);
  EXPECT_THROW(preset_mesh(BodyShape::mesh), std::invalid_argument);
  EXPECT_THROW(preset_body(BodyShape::phone, 0.0), std::invalid_argument);
}

/// Times at which cos_intermediate_L changes sign, by linear interpolation between samples.
std::vector<double> flip_times(Simulator& sim, double dt, double t_end) {
  test::FlipTimer timer;
  Diagnostics d = sim.diagnostics();
  timer.sample(d.t, d.cos_principal_L[1]);
  while (d.t < t_end) {
    sim.step(dt);
    d = sim.diagnostics();
    timer.sample(d.t, d.cos_principal_L[1]);
  }
  return timer.flips();
}

TEST(TwoModels, THandleSpunAboutItsIntermediateAxisFlipsWithTheExactTiming) {
  const Body body = preset_body(BodyShape::t_handle);
  InitialState initial;
  initial.omega0_body = {0.01, 2.0, 0.0};  // about the intermediate axis, slightly perturbed
  ExactModel exact_probe(body);
  exact_probe.reset(initial);
  const double flip_period = exact_probe.rotation().flip_period();
  ASSERT_TRUE(std::isfinite(flip_period));
  const double t_end = 4.6 * flip_period, dt = 1e-3;
  auto exact = make_simulator(body, {ModelKind::exact, Integrator::euler});
  exact->reset(initial);
  const std::vector<double> reference = flip_times(*exact, dt, t_end);
  ASSERT_GE(reference.size(), 4u);
  for (ModelKind kind : {ModelKind::rigid_matrix, ModelKind::rigid_quaternion}) {
    SCOPED_TRACE(std::string(to_string(kind)));
    auto rigid = make_simulator(body, {kind, Integrator::rk4});
    rigid->reset(initial);
    const std::vector<double> flips = flip_times(*rigid, dt, t_end);
    ASSERT_EQ(flips.size(), reference.size());
    for (std::size_t i = 0; i < flips.size(); ++i)
      EXPECT_NEAR(flips[i], reference[i], 1e-6 * reference[i]) << "flip " << i;
    // The corners are the cage's, turned: the rigid motion keeps every cage edge.
    EXPECT_LT(rigid->diagnostics().strain_max, 1e-9);
  }
}

TEST(TwoModels, SymmetricBodyAndSeparatrixStartStayFinite) {
  struct Case {
    const char* name;
    Eigen::Vector3d moments, omega0;
  };
  // Two equal moments (a symmetric top, either pair), and a start exactly on the separatrix:
  // moments 1, 4, 6 and ω0 = (2, 0, 1) give I3(I3 − I2) ω3² = I1(I2 − I1) ω1² = 12 exactly.
  const Case cases[] = {
      {"prolate", {1.0, 3.0, 3.0}, {0.2, 0.5, 0.3}},
      {"oblate", {2.0, 2.0, 3.0}, {0.4, 0.1, 0.5}},
      {"separatrix", {1.0, 4.0, 6.0}, {2.0, 0.0, 1.0}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    Body body;
    body.shape = BodyShape::mesh;
    body.moments = c.moments;
    body.cage.size = {1.0, 1.5, 2.0};
    body.cage.mass = 1.0;
    InitialState initial;
    initial.omega0_body = c.omega0;
    for (ModelKind kind :
         {ModelKind::exact, ModelKind::rigid_matrix, ModelKind::rigid_quaternion}) {
      SCOPED_TRACE(std::string(to_string(kind)));
      auto sim = make_simulator(
          body, {kind, kind == ModelKind::exact ? Integrator::euler : Integrator::rk4});
      sim->reset(initial);
      const double E0 = sim->diagnostics().energy_total;
      for (int n = 0; n < 400; ++n) sim->step(0.05);
      ASSERT_TRUE(sim->finite());
      const Diagnostics d = sim->diagnostics();
      EXPECT_TRUE(d.omega_body.allFinite() && d.cos_principal_L.allFinite() &&
                  d.cos_axis_L.allFinite() && std::isfinite(d.energy_total));
      EXPECT_TRUE(sim->corners().allFinite());
      // Exact: conserved to round-off; RK4 at this coarse step: slowly drifting.
      EXPECT_NEAR(d.energy_total, E0, (kind == ModelKind::exact ? 1e-12 : 1e-4) * E0);
    }
  }
}

TEST(Diagnostics, CosPrincipalLIsTheBooksYXZCosines) {
  InitialState initial;
  initial.jiggle = 1e-3;
  for (ModelKind kind : {ModelKind::particle, ModelKind::rigid_matrix, ModelKind::rigid_quaternion,
                         ModelKind::exact}) {
    SCOPED_TRACE(std::string(to_string(kind)));
    auto sim = make_simulator(Book{}, {kind, Integrator::euler});
    sim->reset(initial);
    for (int n = 0; n < 300; ++n) sim->step(1.0 / 60.0);
    const Diagnostics d = sim->diagnostics();
    EXPECT_EQ(d.cos_principal_L[0], d.cos_axis_L[1]);
    EXPECT_EQ(d.cos_principal_L[1], d.cos_axis_L[0]);
    EXPECT_EQ(d.cos_principal_L[2], d.cos_axis_L[2]);
    EXPECT_GT(std::abs(d.cos_principal_L[1]), 0.5);  // spun about x, the intermediate axis
  }
}

TEST(Diagnostics, PresetsPrincipalCosinesAreTheBodyAxes) {
  const Body body = preset_body(BodyShape::phone);
  InitialState initial;
  initial.omega0_body = {0.3, 0.0, 0.0};  // steady spin about the smallest axis
  auto sim = make_simulator(body, {ModelKind::exact, Integrator::euler});
  sim->reset(initial);
  sim->step(1.0);
  const Diagnostics d = sim->diagnostics();
  EXPECT_NEAR(d.cos_principal_L[0], 1.0, 1e-12);
  EXPECT_NEAR(d.cos_principal_L[1], 0.0, 1e-12);
  EXPECT_NEAR(d.cos_principal_L[2], 0.0, 1e-12);
  EXPECT_EQ(d.cos_principal_L, d.cos_axis_L);
}

// make_simulator(particle) of a mesh body is the lattice model of that body's surface at the
// asked resolution and the body's mass (docs/physics.md §13): the same particles, and the
// same motion step for step as a LatticeModel built here from build_lattice().
TEST(Models, ParticleModelOfANonBookBodyIsItsLattice) {
  const Body body = preset_body(BodyShape::t_handle);
  ModelConfig config{ModelKind::particle, Integrator::symplectic_euler};
  config.lattice_cells = 4;
  config.spring_constant = 1e3;
  const auto sim = make_simulator(body, config);
  const auto* lattice_model = dynamic_cast<const LatticeModel*>(sim.get());
  ASSERT_NE(lattice_model, nullptr);
  const Lattice expected = build_lattice(body.vertices, body.triangles, body.cage.mass, 4);
  EXPECT_EQ(lattice_model->lattice().cells_along_longest, 4);
  EXPECT_EQ(lattice_model->lattice().rest, expected.rest);
  EXPECT_EQ(lattice_model->lattice().mass, expected.mass);
  EXPECT_NEAR(lattice_model->lattice().total_mass, body.cage.mass, 1e-12 * body.cage.mass);
  LatticeModel reference(expected, body.moments, body.cage.body_corners(), config);
  const InitialState initial{Eigen::Vector3d(0.1, 2.0, 0.05), 1e-3, 5};
  sim->reset(initial);
  reference.reset(initial);
  for (int step = 0; step < 50; ++step) {
    sim->step(1e-3);
    reference.step(1e-3);
  }
  EXPECT_EQ(sim->corners(), reference.corners());
  EXPECT_EQ(sim->diagnostics().L, reference.diagnostics().L);
  // The lattice deforms its own surface: one world vertex per rest vertex.
  EXPECT_EQ(sim->pose().surface.cols(), body.vertices.cols());
}

}  // namespace
}  // namespace bookspin::physics
