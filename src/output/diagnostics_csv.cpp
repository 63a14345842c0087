#include "output/diagnostics_csv.hpp"

#include <Eigen/Geometry>
#include <optional>
#include <sstream>
#include <vector>

#include "common/csv_writer.hpp"
#include "common/errors.hpp"
#include "output/output_dir.hpp"

namespace bookspin::output {

namespace {

/// The CSV's columns, in order.
const std::vector<std::string>& columns() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    std::istringstream list(
        "frame t omega_x omega_y omega_z L_x L_y L_z energy_kinetic energy_potential energy_total "
        "cos_x_L cos_y_L cos_z_L strain_max orthogonality_error quaternion_norm cos_smallest_L "
        "cos_intermediate_L cos_largest_L q_w q_x q_y q_z com_x com_y com_z");
    for (std::string name; list >> name;) out.push_back(name);
    return out;
  }();
  return names;
}

/// "diagnostics CSV column NAME" for each column: what a non-finite number is reported as.
const std::vector<std::string>& column_labels() {
  static const std::vector<std::string> labels = [] {
    std::vector<std::string> out;
    for (const std::string& column : columns()) out.push_back("diagnostics CSV column " + column);
    return out;
  }();
  return labels;
}

}  // namespace

Eigen::Vector4d pose_quaternion(const Eigen::Matrix3d& orientation) {
  // Eigen's conversion (Shepperd's method, largest-diagonal branch) of the rotation matrix,
  // normalized; the sign is then fixed so that q_w >= 0 (docs/outputs.md).
  Eigen::Quaterniond q(orientation);
  q.normalize();
  Eigen::Vector4d wxyz(q.w(), q.x(), q.y(), q.z());
  if (wxyz[0] < 0.0) wxyz = -wxyz;
  for (int i = 0; i < 4; ++i) wxyz[i] += 0.0;  // no "-0" in the CSV
  return wxyz;
}

const std::string& diagnostics_csv_header() {
  static const std::string header = csv_row(columns());
  return header;
}

const std::vector<std::string>& diagnostics_columns() { return columns(); }

std::vector<std::optional<double>> diagnostics_values(int frame, const physics::Diagnostics& d) {
  std::vector<std::optional<double>> row;
  row.reserve(columns().size());
  // The cosines with L have no value when L = 0 (a body at rest): empty cells, not NaN
  // (docs/outputs.md).
  const bool at_rest = d.L.isZero(0.0);
  const auto cosine = [at_rest](double value) {
    return at_rest ? std::nullopt : std::optional<double>(value);
  };
  row.push_back(static_cast<double>(frame));
  row.push_back(d.t);
  for (int i = 0; i < 3; ++i) row.push_back(d.omega_body[i]);
  for (int i = 0; i < 3; ++i) row.push_back(d.L[i]);
  row.push_back(d.energy_kinetic);
  row.push_back(d.energy_potential);
  row.push_back(d.energy_total);
  for (int i = 0; i < 3; ++i) row.push_back(cosine(d.cos_axis_L[i]));
  row.push_back(d.strain_max);
  row.push_back(d.orthogonality_error);
  row.push_back(d.quaternion_norm);
  for (int i = 0; i < 3; ++i) row.push_back(cosine(d.cos_principal_L[i]));
  const Eigen::Vector4d q = pose_quaternion(d.orientation);
  for (int i = 0; i < 4; ++i) row.push_back(q[i]);
  for (int i = 0; i < 3; ++i) row.push_back(d.center_of_mass[i]);
  BOOKSPIN_ASSERT(row.size() == columns().size());
  return row;
}

std::string diagnostics_csv_row(int frame, const physics::Diagnostics& d) {
  const std::vector<std::optional<double>> values = diagnostics_values(frame, d);
  std::vector<std::string> cells{std::to_string(frame)};
  cells.reserve(values.size());
  // Each number checked finite under its column's name as it is spelled.
  for (std::size_t i = 1; i < values.size(); ++i)
    cells.push_back(finite_text(values[i], column_labels()[i]));
  return csv_row(cells);
}

namespace {

const std::filesystem::path& with_parent(const std::filesystem::path& path) {
  std::error_code ec;
  if (path.has_parent_path()) make_directories(path.parent_path(), ec);
  if (ec) throw_output_error("cannot create directory", path.parent_path(), ec.value());
  return path;
}

}  // namespace

DiagnosticsCsvFile::DiagnosticsCsvFile(const std::filesystem::path& path)
    : file_(with_parent(path)) {
  file_.stream() << diagnostics_csv_header() << '\n';
}

void DiagnosticsCsvFile::add(int frame, const physics::Diagnostics& d) {
  file_.stream() << diagnostics_csv_row(frame, d) << '\n';
}

}  // namespace bookspin::output
