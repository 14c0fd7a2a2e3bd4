// The parts of the Python module pgamesh._pgamesh (docs/python.md): each file binds one layer's
// public API. The binding converts and validates arguments and hands results back; every figure
// comes from the library (and the JSON documents from apps/common, as the CLI prints them).
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>

#include "pgamesh/core/vec3.hpp"

namespace pgamesh::python {

namespace py = pybind11;

// pgamesh.InputError (a ValueError) and the translation of pgamesh::InputError into it.
void bind_errors(py::module_& m);
// Mesh, load, analyze_file.
void bind_mesh(py::module_& m);
// Tank: fuel states, gauge tables, inverse levels, attitude grids.
void bind_tank(py::module_& m);
// pgamesh.pga3: the algebra of R(3,0,1).
void bind_pga3(py::module_& m);
// pgamesh.models: conformal objects and quadrics.
void bind_models(py::module_& m);

// A JSON text (apps/common's json_text) as the Python object json.loads makes of it.
py::object json_to_python(const std::string& text);

// A Vec3d from any sequence of three numbers (a tuple, a list, a numpy array).
Vec3d vec3_from(const py::handle& value, const char* what);
// A new float64 array of shape (3,) or (3, 3).
py::array_t<double> array_from(const Vec3d& v);
py::array_t<double> array_from(const Mat3& m);

}  // namespace pgamesh::python
