// Conversions shared by the binding files: JSON text to Python, vectors and matrices to numpy.
#include <cmath>
#include <stdexcept>

#include "bindings.hpp"

namespace pgamesh::python {

py::object json_to_python(const std::string& text) {
  // json.loads of the very text the CLI prints: the dict equals the CLI's JSON parsed, bit for bit
  // (%.17g reads back to the same double).
  // Never released (a static py::object would be released after the interpreter has finalised).
  static const py::handle loads = py::object(py::module_::import("json").attr("loads")).release();
  return loads(text);
}

Vec3d vec3_from(const py::handle& value, const char* what) {
  const py::array_t<double, py::array::c_style | py::array::forcecast> a =
      py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(value);
  if (!a || a.ndim() != 1 || a.shape(0) != 3)
    throw py::value_error(std::string(what) + " must be three numbers");
  const Vec3d v{a.at(0), a.at(1), a.at(2)};
  if (!is_finite(v)) throw py::value_error(std::string(what) + " must be finite");
  return v;
}

py::array_t<double> array_from(const Vec3d& v) {
  py::array_t<double> a(3);
  auto r = a.mutable_unchecked<1>();
  r(0) = v.x, r(1) = v.y, r(2) = v.z;
  return a;
}

py::array_t<double> array_from(const Mat3& m) {
  py::array_t<double> a({3, 3});
  auto r = a.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < 3; ++i)
    for (py::ssize_t j = 0; j < 3; ++j) r(i, j) = m[i][j];
  return a;
}

}  // namespace pgamesh::python
