#include "charts/poinsot_view.hpp"

#include <algorithm>
#include <stdexcept>

#include "charts/sphere_view.hpp"
#include "physics/poinsot.hpp"

namespace bookspin::charts {

overlay::PoinsotSpec poinsot_spec(const Eigen::Vector3d& moments, const DiagnosticsHistory& h) {
  if (h.orientation.empty() || h.orientation.size() != h.angular_momentum.size())
    throw std::invalid_argument("poinsot_spec: a history with one orientation per sample");
  const physics::PoinsotState first =
      physics::poinsot_state(moments, h.orientation.front(), h.angular_momentum.front());
  const physics::PoinsotState now =
      physics::poinsot_state(moments, h.orientation.back(), h.angular_momentum.back());
  overlay::PoinsotSpec spec;
  spec.normal = now.normal;
  spec.plane_distance = now.plane_distance;
  spec.semi_axes = now.rotation * now.semi_axes.asDiagonal();
  spec.contact = now.contact;
  for (const Eigen::Vector3d& p :
       physics::polhode_on_ellipsoid(moments, first.rotation.transpose() * first.normal))
    spec.polhode.push_back(now.rotation * p);
  spec.herpolhode.reserve(h.orientation.size());
  for (std::size_t i = 0; i < h.orientation.size(); ++i)
    spec.herpolhode.push_back(
        physics::poinsot_state(moments, h.orientation[i], h.angular_momentum[i]).contact);
  const physics::HerpolhodeBounds bounds =
      physics::herpolhode_bounds(moments, h.angular_momentum.front().norm(), first.energy);
  spec.plane_radius = std::max(1.25 * bounds.max, 0.5 * now.semi_axes.maxCoeff());
  // The view's azimuth: world x seen across L (world y where L is along x).
  Eigen::Vector3d across = Eigen::Vector3d::UnitX() - spec.normal.x() * spec.normal;
  if (across.norm() < 0.3) across = Eigen::Vector3d::UnitY() - spec.normal.y() * spec.normal;
  spec.across = across.normalized();
  return spec;
}

PixelRect poinsot_rect(int width, int height, const PixelRect* panel_column) {
  if (panel_column) return split_for_sphere(*panel_column).first;
  const PixelRect sphere = sphere_rect(width, height, width);
  return {width - sphere.x - sphere.width, sphere.y, sphere.width, sphere.height};
}

}  // namespace bookspin::charts
