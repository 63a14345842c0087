#include "physics/body.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "physics/mass_properties.hpp"
#include "physics/names.hpp"

namespace bookspin::physics {

namespace {

constexpr std::array<std::pair<BodyShape, std::string_view>, 5> kShapeNames{{
    {BodyShape::book, "book"},
    {BodyShape::t_handle, "t-handle"},
    {BodyShape::tennis_racket, "tennis-racket"},
    {BodyShape::phone, "phone"},
    {BodyShape::mesh, "mesh"},
}};

constexpr std::array<BodyShape, kShapeNames.size()> kShapes = [] {
  std::array<BodyShape, kShapeNames.size()> shapes{};
  for (std::size_t i = 0; i < shapes.size(); ++i) shapes[i] = kShapeNames[i].first;
  return shapes;
}();

}  // namespace

std::span<const BodyShape> body_shapes() { return kShapes; }

std::string_view to_string(BodyShape shape) {
  for (const auto& [value, name] : kShapeNames)
    if (value == shape) return name;
  return "?";
}

bool parse_body_shape(std::string_view text, BodyShape& out) {
  for (const auto& [value, name] : kShapeNames) {
    if (name == text) {
      out = value;
      return true;
    }
  }
  return false;
}

Body book_body(const Book& book) {
  Body body;
  body.shape = BodyShape::book;
  body.cage = book;
  body.moments = book.principal_moments();
  body.volume = book.size.prod();
  return body;
}

std::array<int, 3> principal_order(const Eigen::Vector3d& moments) {
  std::array<int, 3> order{0, 1, 2};
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return moments[a] < moments[b]; });
  return order;
}

int distinct_moments(const Eigen::Vector3d& moments) {
  const std::array<int, 3> o = principal_order(moments);
  const auto same = [&](int a, int b) {
    return moments[b] - moments[a] <= 1e-12 * std::abs(moments[b]);
  };
  return 1 + (same(o[0], o[1]) ? 0 : 1) + (same(o[1], o[2]) ? 0 : 1);
}

BodyResult body_from_mesh(const Eigen::Matrix3Xd& vertices, const Eigen::Matrix3Xi& triangles,
                          double mass, double scale, const Eigen::Matrix3Xf& face_colours,
                          bool smooth, BodyShape shape) {
  BodyResult result;
  if (!(std::isfinite(mass) && mass > 0.0)) {
    result.error = "mass must be finite and positive";
    return result;
  }
  if (!(std::isfinite(scale) && scale > 0.0)) {
    result.error = "scale must be finite and positive";
    return result;
  }
  if (face_colours.cols() != 0 && face_colours.cols() != triangles.cols()) {
    result.error = "face colours: " + std::to_string(face_colours.cols()) + " for " +
                   std::to_string(triangles.cols()) + " triangles";
    return result;
  }
  const Eigen::Matrix3Xd scaled = scale * vertices;
  const MassPropertiesResult props = mass_properties(scaled, triangles, 1.0);
  if (!props.ok()) {
    result.error = props.error;
    return result;
  }
  const MassProperties p = with_mass(props.properties, mass);
  if (const std::string range = range_error(p); !range.empty()) {
    result.error = range;
    return result;
  }
  result.warnings = p.warnings;
  Body& body = result.body;
  body.shape = shape;
  body.moments = p.principal_moments;
  body.volume = p.volume;
  body.principal_axes = p.principal_axes;
  // Row i of principal_axes is axis i in mesh coordinates: x' = A (x − c).
  body.vertices = p.principal_axes * (scaled.colwise() - p.center_of_mass);
  body.triangles = triangles;
  // mass_properties turns around a shell wound inward on its own (a cavity keeps its inward
  // winding, which faces out of the solid); do the same here so that drawing sees the
  // solid's outside.
  for (const int t : p.turned_triangles) std::swap(body.triangles(1, t), body.triangles(2, t));
  if (face_colours.cols() == triangles.cols()) {
    body.face_colours = face_colours;
  } else {
    body.face_colours = Eigen::Matrix3Xf::Constant(3, triangles.cols(), 0.6f);
  }
  body.smooth = smooth;
  const Eigen::Vector3d extent = body.vertices.cwiseAbs().rowwise().maxCoeff();
  body.cage.size = 2.0 * extent;
  body.cage.mass = mass;
  return result;
}

}  // namespace bookspin::physics
