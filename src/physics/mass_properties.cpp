#include "physics/mass_properties.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <numeric>
#include <string>
#include <unordered_map>
#include <vector>

namespace bookspin::physics {

namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

/// ∫1, ∫x and ∫x xᵀ over one solid, about a reference point (docs/physics.md §11).
struct Moments {
  double volume = 0.0;
  Vector3d first = Vector3d::Zero();
  Matrix3d second = Matrix3d::Zero();

  void add(const Moments& other) {
    volume += other.volume;
    first += other.first;
    second += other.second;
  }
  /// A shell wound inward integrates every quantity with the wrong sign.
  void turn_around() {
    volume = -volume;
    first = -first;
    second = -second;
  }
};

/// The signed tetrahedron (reference point, a, b, c), a b c relative to the reference:
/// V = a·(b×c)/6, ∫x = V (a+b+c)/4, ∫x xᵀ = V/20 (a aᵀ + b bᵀ + c cᵀ + s sᵀ), s = a+b+c
/// (Tonon 2004, eqs. for the canonical tetrahedron; docs/physics.md §11).
void add_tetrahedron(const Vector3d& a, const Vector3d& b, const Vector3d& c, Moments& m) {
  const double v = a.dot(b.cross(c)) / 6.0;
  const Vector3d s = a + b + c;
  m.volume += v;
  m.first += (v / 4.0) * s;
  m.second +=
      (v / 20.0) * (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
}

/// Union-find over vertex indices; a shell is a set of triangles linked by shared vertices.
class Components {
 public:
  explicit Components(Eigen::Index n) : parent_(static_cast<std::size_t>(n)) {
    std::iota(parent_.begin(), parent_.end(), 0);
  }
  int find(int v) {
    while (parent_[v] != v) v = parent_[v] = parent_[parent_[v]];
    return v;
  }
  void join(int a, int b) { parent_[find(a)] = find(b); }

 private:
  std::vector<int> parent_;
};

/// How often each undirected edge is used, in each direction.
struct EdgeUse {
  int forward = 0;   ///< low index → high index
  int backward = 0;  ///< high index → low index
};

/// "open mesh …", "non-manifold mesh …" or "inconsistent winding …", or empty when every
/// edge is shared by exactly two triangles that run along it in opposite directions (the
/// condition for the divergence theorem to see a closed, oriented surface).
std::string check_closed(const std::vector<Eigen::Vector3i>& triangles) {
  std::unordered_map<std::uint64_t, EdgeUse> edges;
  edges.reserve(triangles.size() * 3);
  for (const auto& t : triangles) {
    for (int k = 0; k < 3; ++k) {
      const int from = t[k];
      const int to = t[(k + 1) % 3];
      const auto low = static_cast<std::uint64_t>(std::min(from, to));
      const auto high = static_cast<std::uint64_t>(std::max(from, to));
      EdgeUse& use = edges[(low << 32) | high];
      (from < to ? use.forward : use.backward) += 1;
    }
  }
  long boundary = 0, crowded = 0, same_way = 0;
  for (const auto& [key, use] : edges) {
    const int count = use.forward + use.backward;
    if (count == 1) ++boundary;
    if (count > 2) ++crowded;
    if (count == 2 && use.forward != 1) ++same_way;
  }
  if (boundary > 0) return "open mesh: " + std::to_string(boundary) + " boundary edges";
  if (crowded > 0)
    return "non-manifold mesh: " + std::to_string(crowded) +
           " edges shared by more than two triangles";
  if (same_way > 0)
    return "inconsistent winding: " + std::to_string(same_way) +
           " edges run the same way in both of their triangles";
  return {};
}

std::string shell_name(int k, int shells) {
  return shells == 1 ? "the mesh"
                     : "shell " + std::to_string(k + 1) + " of " + std::to_string(shells);
}

/// The first vertex of shell `k`'s first triangle.
int first_vertex_of_shell(const std::vector<Eigen::Vector3i>& triangles,
                          const std::vector<int>& shell_of_triangle, int k) {
  for (std::size_t i = 0; i < triangles.size(); ++i)
    if (shell_of_triangle[i] == k) return triangles[i][0];
  return triangles[0][0];
}

/// The winding number of closed shell `j` about point `p`: the triangles' solid angles seen
/// from p (Van Oosterom & Strackee 1983) summed over 4π; ±1 inside (the sign of the shell's
/// winding), 0 outside (docs/physics.md §11, "Shells").
double winding_number(const Eigen::Matrix3Xd& vertices,
                      const std::vector<Eigen::Vector3i>& triangles,
                      const std::vector<int>& shell_of_triangle, int j, const Vector3d& p) {
  double total = 0.0;
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    if (shell_of_triangle[i] != j) continue;
    const Vector3d a = vertices.col(triangles[i][0]) - p;
    const Vector3d b = vertices.col(triangles[i][1]) - p;
    const Vector3d c = vertices.col(triangles[i][2]) - p;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    const double numerator = a.dot(b.cross(c));
    const double denominator = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
    total += 2.0 * std::atan2(numerator, denominator);
  }
  return total / (4.0 * M_PI);
}

}  // namespace

void principal_frame(const Matrix3d& I_body, Vector3d& moments, Matrix3d& axes) {
  const Eigen::SelfAdjointEigenSolver<Matrix3d> eigen(I_body);  // ascending eigenvalues
  moments = eigen.eigenvalues();
  axes = eigen.eigenvectors().transpose();  // columns → rows
  // Eigenvectors come with an arbitrary sign; fix it so the output is reproducible, then
  // make the frame right-handed with the third axis.
  for (int i = 0; i < 2; ++i) {
    Eigen::Index largest = 0;
    axes.row(i).cwiseAbs().maxCoeff(&largest);
    if (axes(i, largest) < 0.0) axes.row(i) *= -1.0;
  }
  axes.row(2) = axes.row(0).cross(axes.row(1)).normalized();
}

MassPropertiesResult mass_properties(const Eigen::Matrix3Xd& vertices,
                                     const Eigen::Matrix3Xi& triangles, double density) {
  MassPropertiesResult result;
  if (!(std::isfinite(density) && density > 0.0)) {
    result.error = "density must be a positive number";
    return result;
  }
  for (Eigen::Index v = 0; v < vertices.cols(); ++v) {
    if (!vertices.col(v).allFinite()) {
      result.error = "non-finite vertex coordinate (vertex " + std::to_string(v + 1) + ")";
      return result;
    }
  }
  // Triangles that repeat a vertex enclose nothing and would look like open edges.
  std::vector<Eigen::Vector3i> kept;
  std::vector<int> kept_index;  // column of `triangles` of each kept triangle
  long degenerate = 0;
  kept.reserve(static_cast<std::size_t>(triangles.cols()));
  for (Eigen::Index t = 0; t < triangles.cols(); ++t) {
    const Eigen::Vector3i tri = triangles.col(t);
    for (int k = 0; k < 3; ++k) {
      if (tri[k] < 0 || tri[k] >= vertices.cols()) {
        result.error = "triangle " + std::to_string(t + 1) + " refers to missing vertex " +
                       std::to_string(tri[k] + 1);
        return result;
      }
    }
    if (tri[0] != tri[1] && tri[1] != tri[2] && tri[2] != tri[0]) {
      kept.push_back(tri);
      kept_index.push_back(static_cast<int>(t));
    } else {
      ++degenerate;
    }
  }
  if (kept.empty()) {
    result.error = "empty mesh: no triangles";
    return result;
  }
  result.error = check_closed(kept);
  if (!result.ok()) return result;

  // Shells: number them in the order their first triangle appears.
  Components components(vertices.cols());
  for (const auto& t : kept) {
    components.join(t[0], t[1]);
    components.join(t[1], t[2]);
  }
  std::unordered_map<int, int> shell_of_root;
  std::vector<int> shell_of_triangle;
  shell_of_triangle.reserve(kept.size());
  for (const auto& t : kept) {
    const auto [it, added] =
        shell_of_root.emplace(components.find(t[0]), static_cast<int>(shell_of_root.size()));
    shell_of_triangle.push_back(it->second);
  }
  const int shells = static_cast<int>(shell_of_root.size());

  // About the bounding-box centre, so a mesh far from its origin keeps its digits.
  Vector3d low = vertices.col(kept[0][0]), high = low;
  for (const auto& t : kept) {
    for (int k = 0; k < 3; ++k) {
      low = low.cwiseMin(vertices.col(t[k]));
      high = high.cwiseMax(vertices.col(t[k]));
    }
  }
  const Vector3d reference = 0.5 * (low + high);
  std::vector<Moments> per_shell(static_cast<std::size_t>(shells));
  for (std::size_t i = 0; i < kept.size(); ++i) {
    const auto& t = kept[i];
    add_tetrahedron(vertices.col(t[0]) - reference, vertices.col(t[1]) - reference,
                    vertices.col(t[2]) - reference, per_shell[shell_of_triangle[i]]);
  }

  // Sizes outside this range would overflow or underflow the fifth powers of the length that
  // the second moments carry (docs/physics.md §11, "Range").
  const double extent = (high - low).maxCoeff();
  if (!(extent >= kMinExtent && extent <= kMaxExtent)) {
    char text[160];
    std::snprintf(text, sizeof text,
                  "mesh size out of range: the bounding box's longest side is %g, outside "
                  "[%g, %g]",
                  extent, kMinExtent, kMaxExtent);
    result.error = text;
    return result;
  }
  // A closed shell thinner than round-off relative to the mesh's size encloses nothing.
  const double tiny = 1e-12 * extent * extent * extent;
  for (int k = 0; k < shells; ++k) {
    const Moments& m = per_shell[static_cast<std::size_t>(k)];
    if (!(std::abs(m.volume) > tiny)) {
      result.error = "zero volume: " + shell_name(k, shells) + " encloses no space";
      return result;
    }
  }
  // Orientation by nesting: a shell wound inward that lies inside a shell wound outward is a
  // cavity and subtracts; one wound inward on its own is turned around, with a warning.
  std::vector<bool> turned(static_cast<std::size_t>(shells), false);
  Moments total;
  for (int k = 0; k < shells; ++k) {
    Moments& m = per_shell[static_cast<std::size_t>(k)];
    if (m.volume < 0.0) {
      const Vector3d probe = vertices.col(first_vertex_of_shell(kept, shell_of_triangle, k));
      bool cavity = false;
      for (int j = 0; j < shells && !cavity; ++j) {
        if (j == k || per_shell[static_cast<std::size_t>(j)].volume <= 0.0) continue;
        cavity = std::abs(winding_number(vertices, kept, shell_of_triangle, j, probe)) > 0.5;
      }
      if (!cavity) {
        m.turn_around();
        turned[static_cast<std::size_t>(k)] = true;
        result.properties.warnings.push_back(
            shell_name(k, shells) +
            " is wound inward (negative volume) and lies inside no "
            "other shell; turned around");
      }
    }
    total.add(m);
  }
  if (!(total.volume > tiny)) {
    result.error = "zero volume: the cavities take up the whole solid";
    return result;
  }
  for (std::size_t i = 0; i < kept.size(); ++i)
    if (turned[static_cast<std::size_t>(shell_of_triangle[i])])
      result.properties.turned_triangles.push_back(kept_index[i]);
  if (degenerate > 0)
    result.properties.warnings.push_back(
        std::to_string(degenerate) +
        " degenerate triangles skipped (two corners at one welded vertex)");

  MassProperties& p = result.properties;
  p.shells = shells;
  p.volume = total.volume;
  p.mass = density * total.volume;
  const Vector3d c = total.first / total.volume;  // centre of mass relative to the reference
  p.center_of_mass = reference + c;
  // Second moment about the centre of mass (parallel-axis theorem), then
  // I = tr(C) 1 − C: diagonal ∫(y²+z²), off-diagonal −∫xy.
  const Matrix3d C = density * total.second - p.mass * c * c.transpose();
  Matrix3d I = C.trace() * Matrix3d::Identity() - C;
  p.I_body = 0.5 * (I + I.transpose());
  principal_frame(p.I_body, p.principal_moments, p.principal_axes);
  result.error = range_error(p);
  return result;
}

MassProperties with_mass(MassProperties p, double mass) {
  const double factor = mass / p.mass;
  if (std::isfinite(factor) && factor > 0.0) {
    p.I_body *= factor;
    p.principal_moments *= factor;
  } else {  // a ratio beyond the double range: divide first
    p.I_body = (p.I_body / p.mass) * mass;
    p.principal_moments = (p.principal_moments / p.mass) * mass;
  }
  p.mass = mass;
  return p;
}

bool all_finite(const MassProperties& p) {
  return std::isfinite(p.volume) && std::isfinite(p.mass) && p.center_of_mass.allFinite() &&
         p.I_body.allFinite() && p.principal_moments.allFinite() && p.principal_axes.allFinite();
}

std::string range_error(const MassProperties& p) {
  if (!all_finite(p)) return kOverflow;
  const double smallest = std::numeric_limits<double>::min();
  if (!(p.mass >= smallest && p.principal_moments.minCoeff() >= smallest)) return kUnderflow;
  return "";
}

}  // namespace bookspin::physics
