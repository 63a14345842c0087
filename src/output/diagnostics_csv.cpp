#include "output/diagnostics_csv.hpp"

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

const std::string& diagnostics_csv_header() {
  static const std::string header =
      "frame,t,omega_x,omega_y,omega_z,L_x,L_y,L_z,energy_kinetic,energy_potential,"
      "energy_total,cos_x_L,cos_y_L,cos_z_L,strain_max,orthogonality_error,quaternion_norm,"
      "cos_smallest_L,cos_intermediate_L,cos_largest_L";
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
