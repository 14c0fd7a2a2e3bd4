// The module pgamesh._pgamesh: the pure-Python package pgamesh (python/pgamesh/__init__.py)
// re-exports it.
#include <pybind11/pybind11.h>

#include "bindings.hpp"

PYBIND11_MODULE(_pgamesh, m) {
  m.doc() =
      "pgamesh's C++ library: mesh reading, mass properties, topology, fuel gauging and the "
      "geometric algebras (docs/python.md). Import `pgamesh`, which re-exports this module.";
  using namespace pgamesh::python;
  bind_errors(m);
  bind_mesh(m);
  bind_tank(m);
  py::module_ pga3 = m.def_submodule("pga3", "PGA R(3,0,1): points, planes, lines, motors");
  bind_pga3(pga3);
  py::module_ models =
      m.def_submodule("models", "Conformal objects (CGA) and quadrics through points");
  bind_models(models);
}
