#include "output/diagnostics_csv.hpp"

#include <Eigen/Geometry>
#include <charconv>

#include "output/output_dir.hpp"

namespace bookspin::output {

namespace {

void append_number(std::string& out, double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.push_back(',');
  out.append(buffer, result.ptr);
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
  append_number(row, d.t);
  for (int i = 0; i < 3; ++i) append_number(row, d.omega_body[i]);
  for (int i = 0; i < 3; ++i) append_number(row, d.L[i]);
  append_number(row, d.energy_kinetic);
  append_number(row, d.energy_potential);
  append_number(row, d.energy_total);
  for (int i = 0; i < 3; ++i) append_number(row, d.cos_axis_L[i]);
  append_number(row, d.strain_max);
  append_number(row, d.orthogonality_error);
  append_number(row, d.quaternion_norm);
  for (int i = 0; i < 3; ++i) append_number(row, d.cos_principal_L[i]);
  const Eigen::Vector4d q = pose_quaternion(d.orientation);
  for (int i = 0; i < 4; ++i) append_number(row, q[i]);
  for (int i = 0; i < 3; ++i) append_number(row, d.center_of_mass[i]);
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
