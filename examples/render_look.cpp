// Pictures of the renderer for a person to look at, not a test (the render tests assert what
// can be measured: tests/render/). Writes 1280×720 PNGs into OUT_DIR: the book from its six
// sides and two three-quarter views with the L arrow and body axes, a stretched and sheared
// book (what an unnormalized rotation matrix gives), and generated surfaces drawn instead of
// the book (a T-shape, sheared too, a coarse torus flat, smooth and shaken, a grey torus
// flat and smooth), built with the render tests' own meshes (tests/render/surface_meshes.hpp).
//
//   build/examples/render_look /tmp/render_look
#include <Eigen/Geometry>
#include <filesystem>
#include <iostream>
#include <memory>
#include <random>
#include <string>

#include "output/png_writer.hpp"
#include "render/renderer.hpp"
#include "render_test_util.hpp"
#include "surface_meshes.hpp"

using namespace bookspin;
using namespace bookspin::render;

namespace {

struct View {
  const char* name;
  Eigen::Vector3d eye;
  bool markers;
};

/// The book from its sides and two three-quarter views, and the stretched book.
void write_book_looks(const std::filesystem::path& dir) {
  const double d = default_camera(default_bounding_radius, 1280, 720).eye.norm();
  const View views[] = {
      {"default", default_camera(default_bounding_radius, 1280, 720).eye, false},
      {"front_+z", {0, 0, d}, false},
      {"back_-z", {0, 0, -d}, false},
      {"spine_+x", {d, 0, 0}, false},
      {"pages_-x", {-d, 0, 0}, false},
      {"top_+y", {0, d, 0.001}, false},
      {"three_quarter_markers", Eigen::Vector3d(0.9, 0.6, 3.2).normalized() * d, true},
      {"back_three_quarter", Eigen::Vector3d(-1.4, -0.5, -2.6).normalized() * d, true},
  };
  for (const View& view : views) {
    RenderSettings settings;
    settings.camera.eye = view.eye;
    settings.show_angular_momentum = view.markers;
    settings.show_body_axes = view.markers;
    Renderer renderer(settings);
    FrameInput frame;
    const Eigen::Matrix3d tilt =
        view.markers
            ? Eigen::AngleAxisd(0.5, Eigen::Vector3d(1, 1, 0.3).normalized()).toRotationMatrix()
            : Eigen::Matrix3d::Identity();
    frame.corners = testing::default_book(tilt);
    frame.angular_momentum_direction = tilt * Eigen::Vector3d(1, 0.15, 0.05);
    output::write_png(dir / (std::string(view.name) + ".png"), renderer.render(frame), 1);
  }
  RenderSettings settings;
  settings.show_body_axes = true;
  Renderer renderer(settings);
  Eigen::Matrix3d stretch;
  stretch << 1.3, 0.4, 0.0, -0.2, 0.8, 0.1, 0.3, 0.0, 1.4;
  FrameInput frame;
  frame.corners = testing::default_book(stretch);
  output::write_png(dir / "stretched.png", renderer.render(frame), 1);
}

/// Generated surfaces instead of the book, lit as the book is.
void write_surface_looks(const std::filesystem::path& dir) {
  const testing::TestMesh t_shape = testing::t_shape();
  const testing::TestMesh torus = testing::torus(1.2, 0.45, 32, 16);  // coarse: facets show
  testing::TestMesh shaken = torus;  // every vertex moved on its own, as a vibrating lattice
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0.0, 0.06);
  for (Eigen::Index i = 0; i < shaken.positions.size(); ++i) shaken.positions(i) += noise(rng);
  const testing::TestMesh coarse = testing::torus(1.2, 0.45, 24, 12);
  auto t_colour = [](int t) {
    return t < 12 ? Eigen::Vector3f(0.75f, 0.18f, 0.08f) : Eigen::Vector3f(0.55f, 0.55f, 0.6f);
  };
  auto checker = [](int t) {
    return ((t / 2) / 16 + (t / 2) % 16) % 2 ? Eigen::Vector3f(0.8f, 0.3f, 0.1f)
                                             : Eigen::Vector3f(0.9f, 0.85f, 0.7f);
  };
  auto grey = [](int) { return Eigen::Vector3f::Constant(0.5f); };
  struct Look {
    std::string name;
    const testing::TestMesh* mesh;
    std::shared_ptr<const SurfaceTopology> topology;
    Eigen::Matrix3d map;  // applied to the mesh and its box (non-orthogonal: a sheared state)
  };
  const Eigen::Matrix3d turn =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(0.3, 1.0, 0.4).normalized()).toRotationMatrix();
  Eigen::Matrix3d shear = Eigen::Matrix3d::Identity();
  shear(0, 1) = 0.6;
  shear(2, 2) = 1.3;
  const Look looks[] = {
      {"t_shape", &t_shape, testing::topology_of(t_shape.triangles, t_colour), turn},
      {"t_shape_sheared", &t_shape, testing::topology_of(t_shape.triangles, t_colour),
       turn * shear},
      {"torus_flat", &torus, testing::topology_of(torus.triangles, checker, false), turn},
      {"torus_smooth", &torus, testing::topology_of(torus.triangles, checker, true), turn},
      {"torus_shaken_smooth", &shaken, testing::topology_of(torus.triangles, checker, true), turn},
      {"coarse_flat", &coarse, testing::topology_of(coarse.triangles, grey, false), turn},
      {"coarse_smooth", &coarse, testing::topology_of(coarse.triangles, grey, true), turn},
  };
  for (const Look& look : looks) {
    const Eigen::Vector3d low = look.mesh->positions.rowwise().minCoeff();
    const Eigen::Vector3d high = look.mesh->positions.rowwise().maxCoeff();
    const Eigen::Matrix<double, 3, 8> cage = look.map * testing::aligned_box(low, high);
    RenderSettings settings;
    settings.camera = default_camera(bounding_radius(cage), 1280, 720);
    settings.show_body_axes = true;
    settings.show_angular_momentum = true;
    Renderer renderer(settings);
    FrameInput frame;
    frame.corners = cage;
    frame.surface.topology = look.topology;
    frame.surface.positions = look.map * look.mesh->positions;
    frame.angular_momentum_direction = Eigen::Vector3d(0.2, 1.0, 0.3);
    output::write_png(dir / ("surface_" + look.name + ".png"), renderer.render(frame), 1);
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: render_look OUT_DIR\n";
    return 2;
  }
  try {
    const std::filesystem::path dir = argv[1];
    std::filesystem::create_directories(dir);
    write_book_looks(dir);
    write_surface_looks(dir);
    std::cout << "wrote the look images into " << dir.string() << '\n';
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "render_look: " << e.what() << '\n';
    return 1;
  }
}
