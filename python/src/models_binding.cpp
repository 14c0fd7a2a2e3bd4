// pgamesh.models: the conformal objects through points and their parameters (pgamesh/models/cga,
// `pgamesh cga`) and quadrics (pgamesh/models/quadric.hpp, `pgamesh quadric`, `pgamesh fit`), as
// functions returning dicts of the library's parameters.
#include <span>
#include <vector>

#include "bindings.hpp"
#include "pgamesh/models/cga.hpp"
#include "pgamesh/models/quadric.hpp"

namespace pgamesh::python {

namespace {

std::vector<Vec3d> points_from(const py::object& value) {
  const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(value);
  if (!a || a.ndim() != 2 || a.shape(1) != 3)
    throw py::value_error("points must be an (n, 3) array of numbers");
  std::vector<Vec3d> out(static_cast<std::size_t>(a.shape(0)));
  const auto r = a.unchecked<2>();
  for (py::ssize_t i = 0; i < a.shape(0); ++i) {
    out[i] = {r(i, 0), r(i, 1), r(i, 2)};
    if (!is_finite(out[i]))
      throw py::value_error("points row " + std::to_string(i) + " is not finite");
  }
  return out;
}

std::vector<Vec3d> exactly(const py::object& value, std::size_t n, const char* what) {
  std::vector<Vec3d> p = points_from(value);
  if (p.size() != n)
    throw py::value_error(std::string(what) + " is through " + std::to_string(n) + " points");
  return p;
}

py::dict round_dict(const cga::RoundParams& r) {
  py::dict d;
  d["center"] = array_from(r.center);
  d["radius"] = r.radius;
  d["radius_squared"] = r.radius_squared;
  d["imaginary"] = r.imaginary;
  return d;
}

quadric::Quadric quadric_from(const py::object& value) {
  const auto a = py::array_t<double, py::array::forcecast>::ensure(value);
  if (!a || a.ndim() != 1 || a.shape(0) != 10)
    throw py::value_error("a quadric has 10 coefficients: x2, y2, z2, xy, xz, yz, x, y, z, 1");
  quadric::Quadric q;
  for (int i = 0; i < 10; ++i) q[static_cast<std::size_t>(i)] = a.at(i);
  quadric::check_finite(q);
  return q;
}

}  // namespace

void bind_models(py::module_& m) {
  m.def(
      "sphere_through",
      [](const py::object& points) {
        const auto p = exactly(points, 4, "a sphere");
        return round_dict(cga::sphere_params(cga::sphere(p[0], p[1], p[2], p[3])));
      },
      py::arg("points"), "The CGA sphere P1∧P2∧P3∧P4 through four points: center, radius.");
  m.def(
      "circle_through",
      [](const py::object& points) {
        const auto p = exactly(points, 3, "a circle");
        const cga::CircleParams c = cga::circle_params(cga::circle(p[0], p[1], p[2]));
        py::dict d = round_dict(c.round);
        d["normal"] = array_from(c.normal);
        return d;
      },
      py::arg("points"), "The CGA circle through three points: center, radius, normal.");
  m.def(
      "plane_through",
      [](const py::object& points) {
        const auto p = exactly(points, 3, "a plane");
        const cga::PlaneParams c = cga::plane_params(cga::plane(p[0], p[1], p[2]));
        py::dict d;
        d["normal"] = array_from(c.normal);
        d["distance"] = c.distance;
        d["foot"] = array_from(c.foot);
        return d;
      },
      py::arg("points"), "The CGA plane through three points: unit normal, distance, foot.");
  m.def(
      "fit_sphere",
      [](const py::object& points) {
        const auto p = points_from(points);
        const cga::SphereFit f = cga::fit_sphere(p);
        py::dict d;
        d["center"] = array_from(f.center);
        d["radius"] = f.radius;
        d["rms"] = f.rms;
        d["max_error"] = f.max_error;
        return d;
      },
      py::arg("points"),
      "Least-squares sphere through points (CGA): center, radius, rms, max_error.");

  py::class_<quadric::Quadric>(m, "Quadric", R"(A quadric F = a x² + b y² + c z² + d xy + e xz +
f yz + g x + h y + i z + j (docs/models.md).)")
      .def(py::init([](const py::object& c) { return quadric_from(c); }), py::arg("coefficients"))
      .def_property_readonly(
          "coefficients",
          [](const quadric::Quadric& q) { return py::array_t<double>(10, q.k.data()); },
          "a … j as a float64 array.")
      .def(
          "value",
          [](const quadric::Quadric& q, const py::object& p) {
            return quadric::value(q, vec3_from(p, "point"));
          },
          py::arg("point"), "F at a point.")
      .def(
          "gradient",
          [](const quadric::Quadric& q, const py::object& p) {
            return array_from(quadric::gradient(q, vec3_from(p, "point")));
          },
          py::arg("point"), "∇F at a point.")
      .def(
          "classify",
          [](const quadric::Quadric& q) {
            const quadric::Classification c = quadric::classify(q);
            py::dict d;
            d["type"] = std::string(quadric::to_string(c.type));
            d["eigenvalues"] = array_from(c.eigenvalues);
            d["axes"] = array_from(c.axes);
            d["rank3"] = c.rank3;
            d["rank4"] = c.rank4;
            return d;
          },
          "Type (ellipsoid, hyperboloid, …), eigenvalues and axes of the quadratic part.")
      .def_static(
          "fit",
          [](const py::object& points) {
            const auto p = points_from(points);
            return quadric::fit(p).quadric;
          },
          py::arg("points"), "The least-squares quadric through nine or more points.");
}

}  // namespace pgamesh::python
