// pgamesh.pga3: PGA R(3,0,1) (pgamesh/algebra/pga3.hpp, docs/pga3.md) as two thin classes — the
// general Multivector, on which every product of the library is an operator, and the Motor of the
// principal frames — and the constructors of points, planes, lines and motors.
#include <array>
#include <string>

#include "bindings.hpp"
#include "pgamesh/algebra/pga3.hpp"

namespace pgamesh::python {

namespace {

using Multivector = pga3::Multivector<double>;
using Motor = pga3::Motor<double>;

Multivector multivector_from(const py::object& coefficients) {
  const auto a =
      py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(coefficients);
  if (!a || a.ndim() != 1 || a.shape(0) != 16)
    throw py::value_error("a multivector has 16 coefficients (basis order of pgamesh.pga3.BLADES)");
  Multivector m;
  for (int i = 0; i < 16; ++i) m[i] = a.at(i);
  return m;
}

int blade_index(const std::string& name) {
  for (int i = 0; i < 16; ++i)
    if (name == pga3::kBladeNames[i]) return i;
  throw py::key_error("no blade '" + name + "' (pgamesh.pga3.BLADES lists them)");
}

std::string text(const Multivector& m) {
  std::string s;
  for (int i = 0; i < 16; ++i) {
    if (m[i] == 0) continue;
    if (!s.empty()) s += " + ";
    s += std::string(py::str(py::float_(m[i])));
    if (i) s += std::string(" ") + pga3::kBladeNames[i];
  }
  return s.empty() ? "0" : s;
}

}  // namespace

void bind_pga3(py::module_& m) {
  py::list blades;
  for (const char* b : pga3::kBladeNames) blades.append(b);
  m.attr("BLADES") = py::tuple(blades);

  py::class_<Multivector>(m, "Multivector", R"(An element of R(3,0,1): 16 coefficients.

Basis order (BLADES): 1, e0, e1, e2, e3, e01, e02, e03, e12, e31, e23, e021, e013, e032, e123,
e0123; e0² = 0, e1² = e2² = e3² = 1. Operators: a * b geometric product, a ^ b outer product
(meet), a & b regressive product (join), a | b inner product, ~a reverse, -a, a + b, a - b, and
scaling by numbers. m['e12'] reads one coefficient.)")
      .def(py::init([](const py::object& c) { return multivector_from(c); }),
           py::arg("coefficients"))
      .def(py::init([] { return Multivector{}; }))
      .def_property_readonly(
          "coefficients", [](const Multivector& a) { return py::array_t<double>(16, a.c.data()); },
          "The 16 coefficients as a float64 array, in BLADES order.")
      .def("__getitem__",
           [](const Multivector& a, const std::string& b) { return a[blade_index(b)]; })
      .def("__mul__", [](const Multivector& a, const Multivector& b) { return a * b; })
      .def("__mul__", [](const Multivector& a, double s) { return a * s; })
      .def("__rmul__", [](const Multivector& a, double s) { return s * a; })
      .def("__truediv__", [](const Multivector& a, double s) { return a / s; })
      .def("__xor__", [](const Multivector& a, const Multivector& b) { return a ^ b; })
      .def("__and__", [](const Multivector& a, const Multivector& b) { return a & b; })
      .def("__or__", [](const Multivector& a, const Multivector& b) { return a | b; })
      .def("__invert__", [](const Multivector& a) { return ~a; })
      .def("__neg__", [](const Multivector& a) { return -a; })
      .def("__add__", [](const Multivector& a, const Multivector& b) { return a + b; })
      .def("__sub__", [](const Multivector& a, const Multivector& b) { return a - b; })
      .def("__eq__", [](const Multivector& a, const Multivector& b) { return a == b; })
      .def(
          "dual", [](const Multivector& a) { return pga3::dual(a); }, "The dual A*.")
      .def(
          "grade", [](const Multivector& a, int k) { return pga3::grade(a, k); }, py::arg("k"),
          "The grade-k part.")
      .def(
          "norm", [](const Multivector& a) { return pga3::norm(a); },
          "‖A‖: root of the sum of squares of the coefficients without e0 (2 × area for the join "
          "of three points).")
      .def(
          "ideal_norm", [](const Multivector& a) { return pga3::ideal_norm(a); },
          "‖A‖∞: root of the sum of squares of the coefficients with e0.")
      .def("__repr__", [](const Multivector& a) { return "pga3.Multivector(" + text(a) + ")"; });

  py::class_<Motor>(m, "Motor", R"(A motor (rotation, translation, screw): the even part
s + e01, e02, e03 + e12, e31, e23 + e0123. M * N composes (N first), ~M reverses, M(x) moves a
Multivector by the sandwich M x ~M, M.apply_point(p) moves a point given by its coordinates.)")
      .def(py::init([](const py::object& c) {
             const auto a = py::array_t<double, py::array::forcecast>::ensure(c);
             if (!a || a.ndim() != 1 || a.shape(0) != 8)
               throw py::value_error(
                   "a motor has 8 coefficients: s, e01, e02, e03, e12, e31, e23, e0123");
             return Motor{.s = a.at(0),
                          .e23 = a.at(6),
                          .e31 = a.at(5),
                          .e12 = a.at(4),
                          .e0123 = a.at(7),
                          .e01 = a.at(1),
                          .e02 = a.at(2),
                          .e03 = a.at(3)};
           }),
           py::arg("coefficients"))
      .def_readonly("s", &Motor::s)
      .def_readonly("e01", &Motor::e01)
      .def_readonly("e02", &Motor::e02)
      .def_readonly("e03", &Motor::e03)
      .def_readonly("e12", &Motor::e12)
      .def_readonly("e31", &Motor::e31)
      .def_readonly("e23", &Motor::e23)
      .def_readonly("e0123", &Motor::e0123)
      .def_property_readonly(
          "coefficients",
          [](const Motor& a) {
            const std::array<double, 8> c{a.s, a.e01, a.e02, a.e03, a.e12, a.e31, a.e23, a.e0123};
            return py::array_t<double>(8, c.data());
          },
          "s, e01, e02, e03, e12, e31, e23, e0123 as a float64 array.")
      .def_property_readonly(
          "multivector", [](const Motor& a) { return pga3::to_multivector(a); },
          "The motor as a Multivector.")
      .def("__mul__", [](const Motor& a, const Motor& b) { return a * b; })
      .def("__invert__", [](const Motor& a) { return ~a; })
      .def(
          "__call__",
          [](const Motor& a, const Multivector& x) {
            const Multivector mv = pga3::to_multivector(a);
            return mv * x * ~mv;
          },
          py::arg("x"), "M x ~M.")
      .def(
          "apply_point",
          [](const Motor& a, const py::object& p) {
            return array_from(pga3::apply(a, pga3::point(vec3_from(p, "point"))).euclidean());
          },
          py::arg("point"), "The moved point (x, y, z) as an array.")
      .def(
          "apply_direction",
          [](const Motor& a, const py::object& d) {
            return array_from(
                pga3::apply(a, pga3::direction(vec3_from(d, "direction"))).weighted());
          },
          py::arg("direction"), "The turned direction (translations do not move it).")
      .def("__repr__",
           [](const Motor& a) { return "pga3.Motor(" + text(pga3::to_multivector(a)) + ")"; });

  m.def(
      "point",
      [](double x, double y, double z) { return pga3::to_multivector(pga3::point(x, y, z)); },
      py::arg("x"), py::arg("y"), py::arg("z"),
      "The point (x, y, z) = e123 + x e032 + y e013 + z e021.");
  m.def(
      "direction",
      [](double x, double y, double z) { return pga3::to_multivector(pga3::direction(x, y, z)); },
      py::arg("x"), py::arg("y"), py::arg("z"), "The ideal point (direction) (x, y, z).");
  m.def(
      "origin", [] { return pga3::to_multivector(pga3::origin<double>()); }, "The origin e123.");
  m.def(
      "plane",
      [](double a, double b, double c, double d) {
        return pga3::to_multivector(pga3::plane(a, b, c, d));
      },
      py::arg("a"), py::arg("b"), py::arg("c"), py::arg("d"),
      "The plane a x + b y + c z + d = 0 as a e1 + b e2 + c e3 + d e0.");
  m.def(
      "line_through",
      [](const py::object& p, const py::object& d) {
        return pga3::to_multivector(
            pga3::line_through(vec3_from(p, "point"), vec3_from(d, "direction")));
      },
      py::arg("point"), py::arg("direction"), "The line through a point along a direction.");
  m.def(
      "scalar", [](double s) { return pga3::scalar(s); }, py::arg("s"), "The scalar s.");
  m.def(
      "blade", [](const std::string& name) { return pga3::basis_blade<double>(blade_index(name)); },
      py::arg("name"), "A basis blade by name ('e0', 'e12', …).");
  m.def(
      "rotor",
      [](double angle, const py::object& axis) {
        return pga3::rotor(angle, vec3_from(axis, "axis"));
      },
      py::arg("angle"), py::arg("axis"),
      "The rotor turning by +angle (radians, right-handed) about the axis through the origin.");
  m.def(
      "translator", [](const py::object& t) { return pga3::translator(vec3_from(t, "t")); },
      py::arg("t"), "The translator by t.");
  m.def(
      "identity", [] { return pga3::identity_motor<double>(); }, "The identity motor 1.");
}

}  // namespace pgamesh::python
