// numpy arrays in and out (docs/python.md): every array argument is read as float64 in C order
// (a list or another dtype is converted), its shape checked against the one documented; a wrong
// shape is bad input (bookspin.Error), named by the argument.
#include <string>

#include "bindings.hpp"
#include "common/errors.hpp"

namespace bookspin::python {

namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

std::string shape_text(const py::array& a) {
  std::string text = "(";
  for (py::ssize_t i = 0; i < a.ndim(); ++i) text += (i ? ", " : "") + std::to_string(a.shape(i));
  return text + (a.ndim() == 1 ? ",)" : ")");
}

std::string expected_text(long rows, long columns) {
  const std::string n = rows < 0 ? "N" : std::to_string(rows);
  return columns < 0 ? "(" + n + ",)" : "(" + n + ", " + std::to_string(columns) + ")";
}

/// `value` as a float64 array; InputError where it is not numbers.
Array as_array(const py::handle& value, const char* name) {
  Array a;
  try {
    a = Array::ensure(value);
  } catch (const py::error_already_set&) {
  }
  if (!a) {
    PyErr_Clear();
    throw InputError(std::string(name) + ": expected an array of numbers (float64), got " +
                     std::string(py::str(py::type::handle_of(value).attr("__name__"))));
  }
  return a;
}

std::vector<double> values_of(const Array& a) {
  return std::vector<double>(a.data(), a.data() + a.size());
}

}  // namespace

std::vector<double> vector_arg(const py::handle& value, const char* name, long n) {
  const Array a = as_array(value, name);
  if (a.ndim() != 1 || (n >= 0 && a.shape(0) != n))
    throw InputError(std::string(name) + ": expected shape " + expected_text(n, -1) + ", got " +
                     shape_text(a));
  return values_of(a);
}

Eigen::Vector3d vector3_arg(const py::handle& value, const char* name) {
  const std::vector<double> v = vector_arg(value, name, 3);
  return {v[0], v[1], v[2]};
}

std::vector<double> matrix_arg(const py::handle& value, const char* name, long rows, long columns) {
  const Array a = as_array(value, name);
  if (a.ndim() != 2 || (rows >= 0 && a.shape(0) != rows) || a.shape(1) != columns)
    throw InputError(std::string(name) + ": expected shape " + expected_text(rows, columns) +
                     ", got " + shape_text(a));
  return values_of(a);
}

py::array_t<double> new_array(std::size_t n, std::size_t columns) {
  if (columns == 0) return py::array_t<double>(static_cast<py::ssize_t>(n));
  return py::array_t<double>({static_cast<py::ssize_t>(n), static_cast<py::ssize_t>(columns)});
}

py::dict exact_rows_arrays(const std::vector<jobs::ExactMotionRow>& rows, bool with_t) {
  const std::size_t n = rows.size();
  py::array_t<double> t = new_array(n), q = new_array(n, 4), omega_body = new_array(n, 3),
                      omega_world = new_array(n, 3), L_world = new_array(n, 3), E = new_array(n);
  auto t_ = t.mutable_unchecked<1>();
  auto q_ = q.mutable_unchecked<2>();
  auto wb = omega_body.mutable_unchecked<2>();
  auto ww = omega_world.mutable_unchecked<2>();
  auto L = L_world.mutable_unchecked<2>();
  auto e = E.mutable_unchecked<1>();
  for (std::size_t i = 0; i < n; ++i) {
    const jobs::ExactMotionRow& row = rows[i];
    const auto r = static_cast<py::ssize_t>(i);
    t_(r) = row.t;
    for (int k = 0; k < 4; ++k) q_(r, k) = row.q[k];
    for (int k = 0; k < 3; ++k) {
      wb(r, k) = row.omega_body[k];
      ww(r, k) = row.omega_world[k];
      L(r, k) = row.L[k];
    }
    e(r) = row.E;
  }
  py::dict out;
  if (with_t) out["t"] = t;
  out["q"] = q;
  out["omega_body"] = omega_body;
  out["omega_world"] = omega_world;
  out["L_world"] = L_world;
  out["E"] = E;
  return out;
}

}  // namespace bookspin::python
