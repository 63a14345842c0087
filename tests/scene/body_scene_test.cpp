// The [body] table, initial.spin_axis and model.lattice_cells (scenes/README.md,
// docs/physics.md §12).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "physics/presets.hpp"
#include "scene/scene.hpp"
#include "scene_text.hpp"
#include "support/scratch.hpp"

namespace bookspin::scene {
namespace {

namespace fs = std::filesystem;

using testing::error_of;
using testing::parse;

TEST(BodyKeys, DefaultIsTheBookAndBookKeysStillWork) {
  const Scene s = parse("[book]\nsize = [1.0, 2.0, 0.5]\nmass = 3.0\n");
  EXPECT_EQ(s.body.shape, physics::BodyShape::book);
  EXPECT_EQ(s.body.cage.size, Eigen::Vector3d(1.0, 2.0, 0.5));
  EXPECT_EQ(s.body.cage.size, s.body.cage.size);
  EXPECT_EQ(s.body.cage.mass, 3.0);
  EXPECT_EQ(s.body.moments, s.body.cage.principal_moments());
  const Scene plain = parse("[body]\nshape = \"book\"\n");
  EXPECT_EQ(plain.body.moments, physics::Book{}.principal_moments());
}

TEST(BodyKeys, PresetWithMassAndScale) {
  const Scene s = parse(
      "[model]\nkind = \"rigid-quaternion\"\n[body]\nshape = \"t-handle\"\nmass = 2.0\n"
      "scale = 0.5\n");
  EXPECT_EQ(s.body.shape, physics::BodyShape::t_handle);
  const physics::Body expected = physics::preset_body(physics::BodyShape::t_handle, 2.0, 0.5);
  EXPECT_EQ(s.body.moments, expected.moments);
  EXPECT_EQ(s.body.cage.size, expected.cage.size);  // the [book] keys describe the cage
  EXPECT_EQ(s.body.cage.mass, 2.0);
  EXPECT_GT(s.body.triangles.cols(), 0);
}

TEST(BodyKeys, MeshFileRelativeToTheScene) {
  const fs::path dir = test::fresh_dir("body_scene_test");
  fs::create_directories(dir / "meshes");
  {
    std::ofstream obj(dir / "meshes" / "box.obj");
    obj << "v 0 0 0\nv 1 0 0\nv 0 2 0\nv 1 2 0\nv 0 0 3\nv 1 0 3\nv 0 2 3\nv 1 2 3\n"
           "f 1 5 7 3\nf 2 4 8 6\nf 1 2 6 5\nf 3 7 8 4\nf 1 3 4 2\nf 5 6 8 7\n";
  }
  const fs::path scene = dir / "box.toml";
  {
    std::ofstream toml(scene);
    toml << "[model]\nkind = \"exact\"\n[body]\nshape = \"mesh\"\nmesh = \"meshes/box.obj\"\n"
            "mass = 12.0\nscale = 2.0\n";
  }
  const Scene s = parse_scene(scene);
  EXPECT_EQ(s.body.shape, physics::BodyShape::mesh);
  // Box 2 × 4 × 6 of mass 12: I = b² + c² … ascending: 16 + 36, 4 + 36, 4 + 16 → 20, 40, 52.
  EXPECT_NEAR(s.body.moments[0], 20.0, 1e-12);
  EXPECT_NEAR(s.body.moments[1], 40.0, 1e-12);
  EXPECT_NEAR(s.body.moments[2], 52.0, 1e-12);
  EXPECT_NEAR(s.body.cage.size.x(), 6.0, 1e-12);
  EXPECT_TRUE(s.warnings.empty());
  // The same box wound inwards: read, turned around, and the scene carries one warning.
  {
    std::ofstream obj(dir / "meshes" / "inward.obj");
    obj << "v 0 0 0\nv 1 0 0\nv 0 2 0\nv 1 2 0\nv 0 0 3\nv 1 0 3\nv 0 2 3\nv 1 2 3\n"
           "f 3 7 5 1\nf 6 8 4 2\nf 5 6 2 1\nf 4 8 7 3\nf 2 4 3 1\nf 7 8 6 5\n";
  }
  const Scene inward = parse_scene(scene, {"body.mesh=\"meshes/inward.obj\""});
  ASSERT_EQ(inward.warnings.size(), 1u);
  EXPECT_NE(inward.warnings[0].find("inward.obj: "), std::string::npos) << inward.warnings[0];
  EXPECT_TRUE(inward.body.moments.isApprox(s.body.moments, 1e-12));
  fs::remove_all(dir);
}

TEST(BodyKeys, ErrorsNameTheKey) {
  struct BadBody {
    const char* toml;
    const char* message;  ///< part of the one error line
  };
  const BadBody cases[] = {
      {"[body]\nshape = \"cube\"\n", "body.shape: unknown shape 'cube'"},
      {"[model]\nkind = \"exact\"\n[body]\nshape = \"mesh\"\n",
       "body.shape: 'mesh' needs body.mesh"},
      {"[model]\nkind = \"exact\"\n[body]\nshape = \"phone\"\nmesh = \"a.obj\"\n",
       "body.mesh: only with"},
      {"[model]\nkind = \"exact\"\n[body]\nshape = \"phone\"\n[book]\nsize = [1, 1, 1]\n",
       "book.size: [book] keys describe the book"},
      {"[body]\nmass = 2.0\n", "body.mass: not used by the book"},
      {"[model]\nkind = \"exact\"\n[body]\nshape = \"phone\"\nmass = 0\n", "body.mass: must be"},
      {"[model]\nkind = \"exact\"\n[body]\nshape = \"mesh\"\nmesh = \"nope.stl\"\n",
       "body.mesh: nope.stl: "},
  };
  for (const BadBody& c : cases) {
    const std::string error = error_of(c.toml);
    EXPECT_NE(error.find(c.message), std::string::npos) << c.toml << "gave: " << error;
  }
}

TEST(BodyKeys, LatticeCellsAreForBodiesOtherThanTheBook) {
  // The book is one cell (docs/physics.md §13): a finer lattice of it is refused, a preset
  // takes any count up to the limit.
  EXPECT_NE(error_of("[model]\nlattice_cells = 4\n").find("model.lattice_cells: "),
            std::string::npos);
  EXPECT_EQ(parse("[model]\nlattice_cells = 1\n").model.lattice_cells, 1);
  EXPECT_EQ(
      parse("[body]\nshape = \"t-handle\"\n[model]\nlattice_cells = 12\n").model.lattice_cells, 12);
}

TEST(SpinAxis, SetsOmegaAlongThePrincipalAxis) {
  // The book: intermediate = x, smallest = y, largest = z.
  const Scene book = parse("[initial]\nspin_axis = \"intermediate\"\nspin_rate = 0.5\n");
  EXPECT_EQ(book.initial.omega0_body, Eigen::Vector3d(0.5, 0.0, 0.0));
  const Scene small = parse("[initial]\nspin_axis = \"smallest\"\nspin_rate = -2\n");
  EXPECT_EQ(small.initial.omega0_body, Eigen::Vector3d(0.0, -2.0, 0.0));
  const Scene large = parse("[initial]\nspin_axis = \"largest\"\nspin_rate = 1.5\n");
  EXPECT_EQ(large.initial.omega0_body, Eigen::Vector3d(0.0, 0.0, 1.5));
  // A preset: x, y, z.
  const Scene t = parse(
      "[model]\nkind = \"exact\"\n[body]\nshape = \"t-handle\"\n[initial]\nspin_axis = "
      "\"intermediate\"\nspin_rate = 3\n");
  EXPECT_EQ(t.initial.omega0_body, Eigen::Vector3d(0.0, 3.0, 0.0));
}

TEST(SpinAxis, Errors) {
  EXPECT_NE(error_of("[initial]\nangular_velocity = [1, 0, 0]\nspin_axis = \"largest\"\n"
                     "spin_rate = 1\n")
                .find("initial.spin_axis: give either"),
            std::string::npos);
  EXPECT_NE(error_of("[initial]\nspin_axis = \"middle\"\nspin_rate = 1\n")
                .find("initial.spin_axis: unknown axis 'middle'"),
            std::string::npos);
  EXPECT_NE(error_of("[initial]\nspin_axis = \"largest\"\n").find("needs initial.spin_rate"),
            std::string::npos);
  EXPECT_NE(error_of("[initial]\nspin_rate = 1\n").find("initial.spin_rate: only with"),
            std::string::npos);
}

TEST(LatticeCells, ReadAndRangeChecked) {
  EXPECT_EQ(parse("[body]\nshape = \"phone\"\n[model]\nlattice_cells = 12\n").model.lattice_cells,
            12);
  EXPECT_EQ(parse("[model]\nkind = \"particle\"\n").model.lattice_cells, 0);
  EXPECT_NE(error_of("[model]\nlattice_cells = 65\n").find("model.lattice_cells: must be"),
            std::string::npos);
  EXPECT_NE(error_of("[model]\nlattice_cells = -1\n").find("model.lattice_cells: must be"),
            std::string::npos);
}

}  // namespace
}  // namespace bookspin::scene
