#include "output/diagnostics_csv.hpp"

#include <Eigen/Geometry>
#include <optional>
#include <sstream>
#include <vector>

#include "output/finite_number.hpp"
#include "output/output_dir.hpp"

namespace bookspin::output {

namespace {

/// The CSV's column names, in order.
const std::vector<std::string>& column_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    std::stringstream header(diagnostics_csv_header());
    for (std::string name; std::getline(header, name, ',');)
      out.push_back("diagnostics CSV column " + name);
    return out;
  }();
  return names;
}

/// Appends ",value" for the next column (finite, or an internal error naming the column).
void append_number(std::string& out, std::size_t& column, double value) {
  out.push_back(',');
  out.append(finite_text(value, column_names()[column++]));
}

/// Appends ",value", or "," (an empty cell) for nullopt.
void append_cell(std::string& out, std::size_t& column, const std::optional<double>& value) {
  out.push_back(',');
  out.append(finite_text(value, column_names()[column++]));
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
  static const std::string header =
      "frame,t,omega_x,omega_y,omega_z,L_x,L_y,L_z,energy_kinetic,energy_potential,"
      "energy_total,cos_x_L,cos_y_L,cos_z_L,strain_max,orthogonality_error,quaternion_norm,"
      "cos_smallest_L,cos_intermediate_L,cos_largest_L,q_w,q_x,q_y,q_z,com_x,com_y,com_z";
  return header;
}

std::string diagnostics_csv_row(int frame, const physics::Diagnostics& d) {
  std::string row = std::to_string(frame);
  row.reserve(400);
  std::size_t column = 1;
  // The cosines with L have no value when L = 0 (a body at rest): empty cells, not NaN
  // (docs/outputs.md).
  const bool at_rest = d.L.isZero(0.0);
  const auto cosine = [at_rest](double value) {
    return at_rest ? std::nullopt : std::optional<double>(value);
  };
  append_number(row, column, d.t);
  for (int i = 0; i < 3; ++i) append_number(row, column, d.omega_body[i]);
  for (int i = 0; i < 3; ++i) append_number(row, column, d.L[i]);
  append_number(row, column, d.energy_kinetic);
  append_number(row, column, d.energy_potential);
  append_number(row, column, d.energy_total);
  for (int i = 0; i < 3; ++i) append_cell(row, column, cosine(d.cos_axis_L[i]));
  append_number(row, column, d.strain_max);
  append_number(row, column, d.orthogonality_error);
  append_number(row, column, d.quaternion_norm);
  for (int i = 0; i < 3; ++i) append_cell(row, column, cosine(d.cos_principal_L[i]));
  const Eigen::Vector4d q = pose_quaternion(d.orientation);
  for (int i = 0; i < 4; ++i) append_number(row, column, q[i]);
  for (int i = 0; i < 3; ++i) append_number(row, column, d.center_of_mass[i]);
  return row;
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
