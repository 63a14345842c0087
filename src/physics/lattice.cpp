#include "physics/lattice.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "physics/mass_properties.hpp"

namespace bookspin::physics {

namespace {

using Eigen::Vector3d;
using Eigen::Vector3i;

/// Sign of the edge function of the directed edge (a, b) at the point p in the xy plane,
/// never 0: the point is moved to p + (ε, ε²) for an infinitesimal ε (simulation of
/// simplicity, Edelsbrunner & Mücke 1990), so a column through an edge or a vertex is
/// counted in exactly one of the triangles around it. The edge is evaluated from its
/// lexicographically smaller end and the sign flipped for the other direction, so the two
/// triangles sharing an edge see the same bits, welded or not (docs/physics.md §13).
int edge_sign(const Vector3d& a, const Vector3d& b, double px, double py) {
  const bool flip = std::lexicographical_compare(b.data(), b.data() + 3, a.data(), a.data() + 3);
  const Vector3d& p = flip ? b : a;
  const Vector3d& q = flip ? a : b;
  const double ex = q.x() - p.x(), ey = q.y() - p.y();
  const double e = ex * (py - p.y()) - ey * (px - p.x());
  int sign = e > 0.0 ? 1 : e < 0.0 ? -1 : 0;
  if (sign == 0) sign = ey != 0.0 ? (ey > 0.0 ? -1 : 1) : (ex > 0.0 ? 1 : ex < 0.0 ? -1 : 0);
  return flip ? -sign : sign;
}

/// Union-find over vertices: the closed shells are the connected components.
int shell_root(std::vector<int>& parent, int v) {
  while (parent[v] != v) v = parent[v] = parent[parent[v]];
  return v;
}

/// +1 or −1 per triangle: the sign of its shell's signed volume (0 for a shell that
/// encloses nothing), so every shell counts as wound outward. Shells are connected through
/// shared vertices, and vertices at the same position count as one (an unwelded mesh).
std::vector<int> shell_signs(const Eigen::Matrix3Xd& vertices, const Eigen::Matrix3Xi& triangles) {
  std::vector<int> parent(vertices.cols());
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<int> order(vertices.cols());
  std::iota(order.begin(), order.end(), 0);
  auto less = [&](int a, int b) {
    return std::lexicographical_compare(vertices.col(a).data(), vertices.col(a).data() + 3,
                                        vertices.col(b).data(), vertices.col(b).data() + 3);
  };
  std::sort(order.begin(), order.end(), less);
  for (std::size_t v = 1; v < order.size(); ++v)
    if (!less(order[v - 1], order[v]))
      parent[shell_root(parent, order[v])] = shell_root(parent, order[v - 1]);
  for (Eigen::Index t = 0; t < triangles.cols(); ++t)
    for (int e = 1; e < 3; ++e)
      parent[shell_root(parent, triangles(e, t))] = shell_root(parent, triangles(0, t));
  std::vector<double> volume(vertices.cols(), 0.0);
  for (Eigen::Index t = 0; t < triangles.cols(); ++t) {
    const Vector3d a = vertices.col(triangles(0, t)), b = vertices.col(triangles(1, t)),
                   c = vertices.col(triangles(2, t));
    volume[shell_root(parent, triangles(0, t))] += a.dot(b.cross(c)) / 6.0;
  }
  std::vector<int> sign(triangles.cols());
  for (Eigen::Index t = 0; t < triangles.cols(); ++t) {
    const double v = volume[shell_root(parent, triangles(0, t))];
    sign[t] = v > 0.0 ? 1 : v < 0.0 ? -1 : 0;
  }
  return sign;
}

struct Crossing {
  int column;  ///< sample column along x within the row
  double z;
  int delta;  ///< change of the winding number above the crossing
};

/// What the body fills of each cell, cell index x + cells.x·(y + cells.y·z).
struct Fill {
  std::vector<double> volume;  ///< filled fraction of the cell (× winding number), in [0, 1]
  /// Per cell × 8 corners: ∫ N_c over the filled part / cell volume (N_c trilinear).
  std::vector<double> corner;
};

/// The filled part of every cell, integrated over an s×s grid of vertical columns per cell
/// (midpoint rule in x and y) and exactly along each column in z: the winding number along
/// a column changes at each surface crossing, and the stretches where it is positive are
/// integrated cell by cell (docs/physics.md §13).
Fill fill_cells(const Eigen::Matrix3Xd& vertices, const Eigen::Matrix3Xi& triangles,
                const Vector3d& origin, const Vector3d& h, const Vector3i& cells,
                const std::vector<double>& z_nodes, int s) {
  const std::vector<int> sign = shell_signs(vertices, triangles);
  const double step_x = h.x() / s, step_y = h.y() / s;
  const int columns_x = cells.x() * s, columns_y = cells.y() * s;
  // Triangles by the sample rows their xy box covers (±1 row).
  std::vector<std::vector<int>> rows(columns_y);
  std::vector<std::array<int, 2>> column_range(triangles.cols());
  for (Eigen::Index t = 0; t < triangles.cols(); ++t) {
    if (sign[t] == 0) continue;
    double x_lo = vertices(0, triangles(0, t)), x_hi = x_lo;
    double y_lo = vertices(1, triangles(0, t)), y_hi = y_lo;
    for (int e = 1; e < 3; ++e) {
      x_lo = std::min(x_lo, vertices(0, triangles(e, t)));
      x_hi = std::max(x_hi, vertices(0, triangles(e, t)));
      y_lo = std::min(y_lo, vertices(1, triangles(e, t)));
      y_hi = std::max(y_hi, vertices(1, triangles(e, t)));
    }
    // Sample i sits at origin + step (i + ½).
    column_range[t] = {
        std::max(0, static_cast<int>(std::floor((x_lo - origin.x()) / step_x)) - 1),
        std::min(columns_x - 1, static_cast<int>(std::ceil((x_hi - origin.x()) / step_x)))};
    const int j0 = std::max(0, static_cast<int>(std::floor((y_lo - origin.y()) / step_y)) - 1);
    const int j1 =
        std::min(columns_y - 1, static_cast<int>(std::ceil((y_hi - origin.y()) / step_y)));
    for (int j = j0; j <= j1; ++j) rows[j].push_back(static_cast<int>(t));
  }
  Fill fill;
  const std::size_t cell_count = static_cast<std::size_t>(cells.prod());
  fill.volume.assign(cell_count, 0.0);
  fill.corner.assign(8 * cell_count, 0.0);
  const double per_column = 1.0 / (static_cast<double>(s) * s);  // share of a cell's xy area
  std::vector<Crossing> crossings;
  for (int j = 0; j < columns_y; ++j) {
    const double py = origin.y() + step_y * (j + 0.5);
    crossings.clear();
    for (int t : rows[j]) {
      const std::array<int, 3> id{triangles(0, t), triangles(1, t), triangles(2, t)};
      const std::array<Vector3d, 3> v{vertices.col(id[0]), vertices.col(id[1]),
                                      vertices.col(id[2])};
      for (int i = column_range[t][0]; i <= column_range[t][1]; ++i) {
        const double px = origin.x() + step_x * (i + 0.5);
        const int s0 = edge_sign(v[0], v[1], px, py);
        const int s1 = edge_sign(v[1], v[2], px, py);
        const int s2 = edge_sign(v[2], v[0], px, py);
        if (s0 == 0 || s0 != s1 || s1 != s2) continue;
        // Height of the triangle's plane over the column (barycentric weights in xy).
        const double d = (v[1].x() - v[0].x()) * (v[2].y() - v[0].y()) -
                         (v[2].x() - v[0].x()) * (v[1].y() - v[0].y());
        double z = (v[0].z() + v[1].z() + v[2].z()) / 3.0;
        if (d != 0.0) {
          const double b1 =
              ((px - v[0].x()) * (v[2].y() - v[0].y()) - (v[2].x() - v[0].x()) * (py - v[0].y())) /
              d;
          const double b2 =
              ((v[1].x() - v[0].x()) * (py - v[0].y()) - (px - v[0].x()) * (v[1].y() - v[0].y())) /
              d;
          z = v[0].z() + b1 * (v[1].z() - v[0].z()) + b2 * (v[2].z() - v[0].z());
        }
        // Counter-clockwise seen from +z (s0 > 0): the outward normal points up, so going up
        // through it leaves the shell.
        crossings.push_back({i, z, -s0 * sign[t]});
      }
    }
    std::sort(crossings.begin(), crossings.end(), [](const Crossing& a, const Crossing& b) {
      return a.column != b.column ? a.column < b.column : a.z < b.z;
    });
    const double ty = ((j % s) + 0.5) / s;
    const std::int64_t row_cell = static_cast<std::int64_t>(cells.x()) * (j / s);
    for (std::size_t first = 0; first < crossings.size();) {
      std::size_t last = first;
      int total = 0;
      while (last < crossings.size() && crossings[last].column == crossings[first].column)
        total += crossings[last++].delta;
      // A column whose crossings do not sum to 0 met the surface at a round-off-degenerate
      // spot: it is left empty rather than filled to the top.
      if (total != 0) {
        first = last;
        continue;
      }
      const int i = crossings[first].column;
      const double tx = ((i % s) + 0.5) / s;
      const std::int64_t column_cell = row_cell + i / s;
      const std::array<double, 4> wxy{(1.0 - tx) * (1.0 - ty), tx * (1.0 - ty), (1.0 - tx) * ty,
                                      tx * ty};
      int winding = 0;
      for (std::size_t c = first; c + 1 < last; ++c) {
        winding += crossings[c].delta;
        if (winding <= 0) continue;
        const double za = crossings[c].z, zb = crossings[c + 1].z;
        if (!(zb > za)) continue;
        // The stretch [za, zb] cut by the cells along z.
        int k = static_cast<int>(std::upper_bound(z_nodes.begin(), z_nodes.end(), za) -
                                 z_nodes.begin()) -
                1;
        k = std::clamp(k, 0, cells.z() - 1);
        for (; k < cells.z() && z_nodes[k] < zb; ++k) {
          const double hz = z_nodes[k + 1] - z_nodes[k];
          const double ta = std::max(0.0, (za - z_nodes[k]) / hz);
          const double tb = std::min(1.0, (zb - z_nodes[k]) / hz);
          if (!(tb > ta)) continue;
          const double length = winding * (tb - ta);
          const double upper = winding * 0.5 * (tb * tb - ta * ta);  // ∫ t dt
          const double lower = length - upper;                       // ∫ (1 − t) dt
          const std::int64_t cell =
              column_cell + static_cast<std::int64_t>(cells.x()) * cells.y() * k;
          fill.volume[cell] += per_column * length;
          double* corner = &fill.corner[8 * cell];
          for (int q = 0; q < 4; ++q) {
            corner[q] += per_column * wxy[q] * lower;
            corner[q + 4] += per_column * wxy[q] * upper;
          }
        }
      }
      first = last;
    }
  }
  return fill;
}

void check_input(const Eigen::Matrix3Xd& vertices, const Eigen::Matrix3Xi& triangles, double mass,
                 int n) {
  if (n < 1 || n > kMaxLatticeCells)
    throw std::invalid_argument("lattice: cells along the longest side must be in [1, " +
                                std::to_string(kMaxLatticeCells) + "], got " + std::to_string(n));
  if (!std::isfinite(mass) || mass <= 0.0)
    throw std::invalid_argument("lattice: mass must be finite and positive");
  if (triangles.cols() == 0) throw std::invalid_argument("lattice: no triangles");
  if (!vertices.allFinite()) throw std::invalid_argument("lattice: non-finite vertex coordinate");
  if (triangles.size() > 0 && (triangles.minCoeff() < 0 || triangles.maxCoeff() >= vertices.cols()))
    throw std::invalid_argument("lattice: triangle refers to a missing vertex");
}

}  // namespace

Lattice build_lattice(const Eigen::Matrix3Xd& vertices, const Eigen::Matrix3Xi& triangles,
                      double mass, int cells_along_longest) {
  check_input(vertices, triangles, mass, cells_along_longest);
  const int n = cells_along_longest;
  Lattice lat;
  lat.cells_along_longest = n;
  const Vector3d lo = vertices.rowwise().minCoeff(), hi = vertices.rowwise().maxCoeff();
  const Vector3d extent = hi - lo;
  const double longest = extent.maxCoeff();
  if (!(extent.minCoeff() > 0.0)) throw std::invalid_argument("lattice: flat bounding box");
  for (int d = 0; d < 3; ++d)
    lat.cells[d] = std::max(1, static_cast<int>(std::lround(n * extent[d] / longest)));
  lat.origin = lo;
  lat.cell_size = extent.cwiseQuotient(lat.cells.cast<double>());
  const Vector3i& cells = lat.cells;

  auto coordinate = [&](int axis, int i) {
    return i == cells[axis] ? hi[axis] : lo[axis] + lat.cell_size[axis] * i;
  };
  std::vector<double> z_nodes(cells.z() + 1);
  for (int k = 0; k <= cells.z(); ++k) z_nodes[k] = coordinate(2, k);

  // Fill (docs/physics.md §13): s×s columns per cell, s a power of 2 (dyadic sample
  // positions, so a box that is one cell is filled to exactly 1).
  int s = 2;
  while (s * n < 1024) s *= 2;
  const Fill fill = fill_cells(vertices, triangles, lo, lat.cell_size, cells, z_nodes, s);
  // A cell is kept when it is filled at all; less than kMinFill of a cell is round-off of a
  // face lying on a cell boundary (docs/physics.md §13). kept() is its fraction, or 0.
  constexpr double kMinFill = 1e-9;
  auto kept = [&](std::int64_t cell) {
    const double f = fill.volume[cell];
    return f > kMinFill ? f : 0.0;
  };

  // Particles: the grid nodes at a corner of a kept cell, numbered in grid order (x fastest).
  const Vector3i nodes = cells + Vector3i::Ones();
  auto node_index = [&](int i, int j, int k) {
    return i +
           static_cast<std::int64_t>(nodes.x()) * (j + static_cast<std::int64_t>(nodes.y()) * k);
  };
  auto cell_index = [&](int i, int j, int k) {
    return i +
           static_cast<std::int64_t>(cells.x()) * (j + static_cast<std::int64_t>(cells.y()) * k);
  };
  // Masses (docs/physics.md §13): half of each cell's filled volume in equal parts to its 8
  // corners, half by the trilinear weights of where the filled part lies (exact first
  // moment); the equal half bounds every particle's mass below by the springs it feels.
  const double beta = 0.5;
  std::vector<double> node_weight(static_cast<std::size_t>(nodes.prod()), 0.0);
  std::vector<char> used(node_weight.size(), 0);
  double total_weight = 0.0, filled_cells = 0.0;
  for (int k = 0; k < cells.z(); ++k)
    for (int j = 0; j < cells.y(); ++j)
      for (int i = 0; i < cells.x(); ++i) {
        const double c = kept(cell_index(i, j, k));
        if (c == 0.0) continue;
        ++lat.cells_kept;
        filled_cells += c;
        const std::int64_t cell = cell_index(i, j, k);
        for (int corner = 0; corner < 8; ++corner) {
          const std::int64_t q =
              node_index(i + (corner & 1), j + ((corner >> 1) & 1), k + (corner >> 2));
          const double share = (1.0 - beta) * (c / 8.0) + beta * fill.corner[8 * cell + corner];
          node_weight[q] += share;
          total_weight += share;
          used[q] = 1;
        }
      }
  if (lat.cells_kept == 0) throw std::invalid_argument("lattice: the surface encloses nothing");
  lat.volume = filled_cells * lat.cell_size.prod();

  std::vector<int> particle(node_weight.size(), -1);
  int P = 0;
  for (std::size_t q = 0; q < node_weight.size(); ++q)
    if (used[q]) particle[q] = P++;
  lat.rest.resize(3, P);
  lat.mass.resize(P);
  for (int k = 0; k <= cells.z(); ++k)
    for (int j = 0; j <= cells.y(); ++j)
      for (int i = 0; i <= cells.x(); ++i) {
        const std::int64_t q = node_index(i, j, k);
        if (particle[q] < 0) continue;
        lat.rest.col(particle[q]) << coordinate(0, i), coordinate(1, j), coordinate(2, k);
        // Dyadic weights: the one-cell book gets exactly M/8.
        lat.mass[particle[q]] = mass * (node_weight[q] / total_weight);
      }

  // Springs: from each node to the 13 "forward" neighbours (offset later in grid order),
  // each summing f/n over the up to 4 kept cells holding both ends; visiting nodes in grid
  // order and offsets by grid distance gives springs sorted by (i, j).
  std::vector<Vector3i> offsets;
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const std::int64_t g = dx + nodes.x() * (dy + static_cast<std::int64_t>(nodes.y()) * dz);
        if (g > 0) offsets.emplace_back(dx, dy, dz);
      }
  std::sort(offsets.begin(), offsets.end(), [&](const Vector3i& a, const Vector3i& b) {
    return a.x() + nodes.x() * (a.y() + static_cast<std::int64_t>(nodes.y()) * a.z()) <
           b.x() + nodes.x() * (b.y() + static_cast<std::int64_t>(nodes.y()) * b.z());
  });
  std::vector<int> first, second;
  std::vector<double> stiffness;
  for (int k = 0; k <= cells.z(); ++k)
    for (int j = 0; j <= cells.y(); ++j)
      for (int i = 0; i <= cells.x(); ++i) {
        const int a = particle[node_index(i, j, k)];
        if (a < 0) continue;
        const Vector3i from(i, j, k);
        for (const Vector3i& d : offsets) {
          const Vector3i to = from + d;
          if ((to.array() < 0).any() || (to.array() > cells.array()).any()) continue;
          const int b = particle[node_index(to.x(), to.y(), to.z())];
          if (b < 0) continue;
          // Cells holding both ends: along an axis with d ≠ 0 the one between them, along
          // an axis with d = 0 the (up to) two on either side.
          std::array<std::array<int, 2>, 3> range{};
          std::array<int, 3> options{};
          for (int axis = 0; axis < 3; ++axis) {
            if (d[axis] != 0) {
              range[axis][0] = std::min(from[axis], to[axis]);
              options[axis] = 1;
            } else {
              int m = 0;
              if (from[axis] - 1 >= 0) range[axis][m++] = from[axis] - 1;
              if (from[axis] < cells[axis]) range[axis][m++] = from[axis];
              options[axis] = m;
            }
          }
          double f = 0.0;
          for (int oz = 0; oz < options[2]; ++oz)
            for (int oy = 0; oy < options[1]; ++oy)
              for (int ox = 0; ox < options[0]; ++ox)
                f += kept(cell_index(range[0][ox], range[1][oy], range[2][oz]));
          if (f == 0.0) continue;
          first.push_back(a);
          second.push_back(b);
          stiffness.push_back(f / n);
        }
      }
  const int S = static_cast<int>(first.size());
  lat.springs.resize(2, S);
  lat.rest_length.resize(S);
  lat.stiffness.resize(S);
  for (int sp = 0; sp < S; ++sp) {
    lat.springs(0, sp) = first[sp];
    lat.springs(1, sp) = second[sp];
    lat.rest_length[sp] = (lat.rest.col(first[sp]) - lat.rest.col(second[sp])).norm();
    lat.stiffness[sp] = stiffness[sp];
  }

  // Surface embedding: the cell holding each vertex, or the nearest kept cell.
  const Eigen::Index V = vertices.cols();
  lat.vertex_cell.resize(8, V);
  lat.vertex_coords.resize(3, V);
  for (Eigen::Index v = 0; v < V; ++v) {
    const Vector3d u = (vertices.col(v) - lo).cwiseQuotient(lat.cell_size);
    Vector3i home;
    for (int axis = 0; axis < 3; ++axis)
      home[axis] = std::clamp(static_cast<int>(std::floor(u[axis])), 0, cells[axis] - 1);
    Vector3i best = home;
    double best_distance = std::numeric_limits<double>::infinity();
    double best_count = -1.0;
    for (int radius = 1; best_count < 0.0; ++radius) {
      const Vector3i a = (home.array() - radius).max(0),
                     b = (home + Vector3i::Constant(radius)).cwiseMin(cells - Vector3i::Ones());
      for (int k = a.z(); k <= b.z(); ++k)
        for (int j = a.y(); j <= b.y(); ++j)
          for (int i = a.x(); i <= b.x(); ++i) {
            const double c = kept(cell_index(i, j, k));
            if (c == 0.0) continue;
            const Vector3d gap =
                (Vector3d(i, j, k) - u).cwiseMax(u - Vector3d(i + 1, j + 1, k + 1)).cwiseMax(0.0);
            const double distance = gap.squaredNorm();
            if (distance < best_distance || (distance == best_distance && c > best_count)) {
              best_distance = distance;
              best_count = c;
              best = Vector3i(i, j, k);
            }
          }
    }
    for (int corner = 0; corner < 8; ++corner)
      lat.vertex_cell(corner, v) = particle[node_index(
          best.x() + (corner & 1), best.y() + ((corner >> 1) & 1), best.z() + (corner >> 2))];
    const Vector3d cell_lo(coordinate(0, best.x()), coordinate(1, best.y()),
                           coordinate(2, best.z()));
    const Vector3d cell_hi(coordinate(0, best.x() + 1), coordinate(1, best.y() + 1),
                           coordinate(2, best.z() + 1));
    lat.vertex_coords.col(v) = (vertices.col(v) - cell_lo).cwiseQuotient(cell_hi - cell_lo);
  }

  // Mass properties of the particles at rest.
  lat.total_mass = lat.mass.sum();
  lat.center_of_mass = lat.rest * lat.mass / lat.total_mass;
  for (int p = 0; p < P; ++p) {
    const Vector3d r = lat.rest.col(p) - lat.center_of_mass;
    lat.inertia +=
        lat.mass[p] * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());
  }
  principal_frame(lat.inertia, lat.principal_moments, lat.principal_axes);
  return lat;
}

double max_angular_frequency(const Lattice& lattice, double k) {
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(lattice.particles());
  for (int s = 0; s < lattice.spring_count(); ++s) {
    sum[lattice.springs(0, s)] += k * lattice.stiffness[s];
    sum[lattice.springs(1, s)] += k * lattice.stiffness[s];
  }
  return std::sqrt(2.0 * sum.cwiseQuotient(lattice.mass).maxCoeff());
}

double max_damping_rate(const Lattice& lattice, double k) {
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(lattice.particles());
  for (int s = 0; s < lattice.spring_count(); ++s) {
    const int i = lattice.springs(0, s), j = lattice.springs(1, s);
    const double b =
        2.0 * std::sqrt(k * lattice.stiffness[s] * spring_mass(lattice.mass[i], lattice.mass[j]));
    sum[i] += b;
    sum[j] += b;
  }
  return 2.0 * sum.cwiseQuotient(lattice.mass).maxCoeff();
}

Eigen::Matrix3Xd Lattice::embed_surface(const Eigen::Matrix3Xd& x) const {
  if (x.cols() != rest.cols())
    throw std::invalid_argument("embed_surface: expected " + std::to_string(rest.cols()) +
                                " particle positions, got " + std::to_string(x.cols()));
  Eigen::Matrix3Xd out(3, vertex_cell.cols());
  for (Eigen::Index v = 0; v < vertex_cell.cols(); ++v) {
    const Vector3d u = vertex_coords.col(v);
    Vector3d sum = Vector3d::Zero();
    for (int corner = 0; corner < 8; ++corner) {
      const double w = ((corner & 1) ? u.x() : 1.0 - u.x()) * ((corner & 2) ? u.y() : 1.0 - u.y()) *
                       ((corner & 4) ? u.z() : 1.0 - u.z());
      sum += w * x.col(vertex_cell(corner, v));
    }
    out.col(v) = sum;
  }
  return out;
}

Eigen::Matrix3d best_fit_rotation(const Eigen::Matrix3Xd& current, const Eigen::Matrix3Xd& rest,
                                  const Eigen::VectorXd& weights) {
  const double total = weights.sum();
  const Vector3d c = current * weights / total, c0 = rest * weights / total;
  const Eigen::Matrix3d H =
      (current.colwise() - c) * weights.asDiagonal() * (rest.colwise() - c0).transpose();
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(H, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d fix = Eigen::Matrix3d::Identity();
  fix(2, 2) = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0.0 ? -1.0 : 1.0;
  return svd.matrixU() * fix * svd.matrixV().transpose();
}

}  // namespace bookspin::physics
