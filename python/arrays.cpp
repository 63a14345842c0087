// numpy arrays in and out (docs/python.md): every array argument is read as float64 in C order
// (a list or another dtype is converted), its shape checked against the one documented; a wrong
// shape is bad input (bookspin.Error), named by the argument.
#include <cstdio>
#include <new>
#include <string>
#include <utility>
#include <vector>

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

/// InputError: `value` cannot be copied into a float64 array, for want of memory; its size said.
[[noreturn]] void out_of_memory(const py::handle& value, const char* name) {
  PyErr_Clear();
  std::string size;
  if (py::hasattr(value, "size")) {
    const double count = py::cast<double>(value.attr("size"));
    char text[160];
    std::snprintf(text, sizeof text, "%.0f values, %.3g GiB as float64", count,
                  count * 8.0 / (1024.0 * 1024.0 * 1024.0));
    size = text;
  } else {
    size = "its values";
  }
  throw InputError(std::string(name) + ": cannot copy the array into memory (" + size +
                   "): too large for this machine");
}

std::string expected_text(long rows, long columns) {
  const std::string n = rows < 0 ? "N" : std::to_string(rows);
  return columns < 0 ? "(" + n + ",)" : "(" + n + ", " + std::to_string(columns) + ")";
}

/// InputError where `value` is a numpy array or scalar whose dtype numpy would not cast to
/// float64 under its `same_kind` rule: complex numbers (their imaginary part dropped), text,
/// objects. A list, a bool, an integer or a float array is read as numbers.
void check_kind(const py::handle& value, const char* name) {
  if (!py::hasattr(value, "dtype")) return;
  const py::object dtype = value.attr("dtype");
  const py::module_ numpy = py::module_::import("numpy");
  if (numpy.attr("can_cast")(dtype, numpy.attr("float64"), py::arg("casting") = "same_kind")
          .cast<bool>())
    return;
  const std::string kind = py::str(dtype.attr("kind"));
  const std::string type = py::str(dtype);
  if (kind == "c")
    throw InputError(std::string(name) + ": expected real numbers (float64), got " + type +
                     ": the imaginary part would be dropped");
  throw InputError(std::string(name) + ": expected numbers (float64), got an array of " + type +
                   " (numpy casts it to float64 only unsafely)");
}

/// `value` as a float64 array (C order; a copy where it is not one already); InputError where
/// it is not numbers, or where the copy does not fit in memory (its size said).
Array as_array(const py::handle& value, const char* name) {
  check_kind(value, name);
  py::object source = py::reinterpret_borrow<py::object>(value);
  if (py::isinstance<py::array>(value)) {
    // numpy's own copy, so that one it cannot allocate says so (Array::ensure clears the error).
    try {
      source = py::module_::import("numpy").attr("ascontiguousarray")(value,
                                                                      py::arg("dtype") = "float64");
    } catch (const py::error_already_set& e) {
      if (e.matches(PyExc_MemoryError)) out_of_memory(value, name);
      throw InputError(std::string(name) + ": expected an array of numbers (float64), got " +
                       std::string(py::str(py::type::handle_of(value).attr("__name__"))));
    }
  }
  const Array a = Array::ensure(source);
  if (!a) {
    PyErr_Clear();
    throw InputError(std::string(name) + ": expected an array of numbers (float64), got " +
                     std::string(py::str(py::type::handle_of(value).attr("__name__"))));
  }
  return a;
}

std::vector<double> values_of(const Array& a, const char* name) {
  try {
    return std::vector<double>(a.data(), a.data() + a.size());
  } catch (const std::bad_alloc&) {
    char text[200];
    std::snprintf(text, sizeof text,
                  ": cannot copy the array into memory (%zd values, %.3g GiB as float64): too "
                  "large for this machine",
                  static_cast<py::ssize_t>(a.size()),
                  static_cast<double>(a.size()) * 8.0 / (1024.0 * 1024.0 * 1024.0));
    throw InputError(std::string(name) + text);
  }
}

}  // namespace

std::vector<double> vector_arg(const py::handle& value, const char* name, long n) {
  const Array a = as_array(value, name);
  if (a.ndim() != 1 || (n >= 0 && a.shape(0) != n))
    throw InputError(std::string(name) + ": expected shape " + expected_text(n, -1) + ", got " +
                     shape_text(a));
  return values_of(a, name);
}

Eigen::Vector3d vector3_arg(const py::handle& value, const char* name) {
  const std::vector<double> v = vector_arg(value, name, 3);
  return {v[0], v[1], v[2]};
}

std::vector<double> matrix_arg(const py::handle& value, const char* name, long rows, long columns) {
  const Array a = as_array(value, name);
  if (a.ndim() != 2 || (rows >= 0 && a.shape(0) != rows) || a.shape(1) != columns) {
    // Any rows asked for: those given are right, the columns are what is wrong.
    const long expected_rows = rows < 0 && a.ndim() == 2 ? static_cast<long>(a.shape(0)) : rows;
    throw InputError(std::string(name) + ": expected shape " +
                     expected_text(expected_rows, columns) + ", got " + shape_text(a));
  }
  return values_of(a, name);
}

void same_rows(const std::vector<std::pair<const char*, std::size_t>>& arrays) {
  // The count most of them have (the first given's where as many disagree): the others are
  // the odd ones out.
  std::size_t common = arrays.front().second;
  int best = 0;
  for (const auto& [name, rows] : arrays) {
    int holders = 0;
    for (const auto& other : arrays) holders += other.second == rows;
    if (holders > best) best = holders, common = rows;
  }
  for (const auto& [name, rows] : arrays) {
    if (rows == common) continue;
    std::string others;
    for (const auto& other : arrays)
      if (other.second == common)
        others += (others.empty() ? "" : " and ") + std::string(other.first);
    throw InputError(std::string(name) + ": " + std::to_string(rows) + " rows, but " + others +
                     (best > 1 ? " have " : " has ") + std::to_string(common) +
                     ": one row of each per time");
  }
}

py::array_t<double> new_array(std::size_t n, std::size_t columns) {
  if (columns == 0) return py::array_t<double>(static_cast<py::ssize_t>(n));
  return py::array_t<double>({static_cast<py::ssize_t>(n), static_cast<py::ssize_t>(columns)});
}

ExactArrays::ExactArrays(std::size_t n, bool with_t)
    : with_t_(with_t),
      t_(new_array(with_t ? n : 0)),
      q_(new_array(n, 4)),
      omega_body_(new_array(n, 3)),
      omega_world_(new_array(n, 3)),
      L_world_(new_array(n, 3)),
      E_(new_array(n)),
      into_{
          with_t ? t_.mutable_data() : nullptr, q_.mutable_data(),       omega_body_.mutable_data(),
          omega_world_.mutable_data(),          L_world_.mutable_data(), E_.mutable_data()} {}

void ExactArrays::set(std::size_t i, const jobs::ExactMotionRow& row) { into_.put(i, row); }

py::dict ExactArrays::dict() const {
  py::dict out;
  if (with_t_) out["t"] = t_;
  out["q"] = q_;
  out["omega_body"] = omega_body_;
  out["omega_world"] = omega_world_;
  out["L_world"] = L_world_;
  out["E"] = E_;
  return out;
}

py::dict exact_rows_arrays(const std::vector<jobs::ExactMotionRow>& rows, bool with_t) {
  ExactArrays arrays(rows.size(), with_t);
  for (std::size_t i = 0; i < rows.size(); ++i) arrays.set(i, rows[i]);
  return arrays.dict();
}

}  // namespace bookspin::python
