// The model functions of `pgamesh calc` (docs/calc.md, Models): point embeddings and the objects
// of CGA, DPGA, DCGA and QCGA, each a call into the models layer (include/pgamesh/models/) or,
// for PGA points, the algebra layer's pgad. No formula of a model is repeated here: values move
// between the calculator's general-engine multivectors and the models' types by copying blades.
#include <array>
#include <cmath>
#include <string>

#include "calc_functions.hpp"
#include "pgamesh/algebra/graded.hpp"
#include "pgamesh/algebra/pgad.hpp"
#include "pgamesh/models/cga.hpp"
#include "pgamesh/models/dcga.hpp"
#include "pgamesh/models/dpga.hpp"
#include "pgamesh/models/qcga.hpp"
#include "pgamesh/models/quadric.hpp"

namespace pgamesh::cli {

using clifford::Multivector;

namespace {

constexpr unsigned cga_only = model_bit(CalcModel::cga);
constexpr unsigned point_models = model_bit(CalcModel::pga) | cga_only | quadric_models;

template <graded::GradeMask G>
double max_abs(const cga::Multivector<G>& x) {
  double m = 0;
  for (double v : x.c) m = std::max(m, std::abs(v));
  return m;
}

// ---- arguments
// -----------------------------------------------------------------------------------

// The coefficient of the blade `name` of the algebra (e.g. "w3").
double coefficient(const CallArgs& c, const Multivector& m, const char* name) {
  const auto b = c.algebra().parse_blade(name);
  return m[b->first] * b->second;
}
Multivector blade(const CallArgs& c, const char* name, double value) {
  const auto b = c.algebra().parse_blade(name);
  return clifford::basis_blade(b->first, b->second * value);
}

std::string nth(std::size_t i) {
  return "argument " + std::to_string(i + 1);
}

// ---- points: embeddings from the models layer
// ----------------------------------------------------

template <int D>
Multivector pga_point(const std::vector<double>& x) {
  pgad::Vec<D> v{};
  for (int i = 0; i < D; ++i) v[static_cast<std::size_t>(i)] = x[static_cast<std::size_t>(i)];
  const pgad::Multivector<D> p = pgad::point<D>(v);
  Multivector out;
  for (clifford::BladeMask m = 0; m < p.c.size(); ++m)
    if (p.c[m] != 0) out.terms.push_back({m, p.c[m]});
  return out;
}

Multivector embed_point(const CallArgs& c, const std::vector<double>& x) {
  const Vec3d p = x.size() == 3 ? Vec3d{x[0], x[1], x[2]} : Vec3d{};
  switch (c.alg.model) {
    case CalcModel::pga:
      switch (x.size()) {
        case 1:
          return pga_point<1>(x);
        case 2:
          return pga_point<2>(x);
        case 3:
          return pga_point<3>(x);
        case 4:
          return pga_point<4>(x);
        case 5:
          return pga_point<5>(x);
        case 6:
          return pga_point<6>(x);
        case 7:
          return pga_point<7>(x);
        default:
          c.fail("point() is implemented for R(d,0,1) with d <= 7");
      }
    case CalcModel::cga:
      return graded::to_clifford(cga::up({x[0], x[1], x[2]}));
    case CalcModel::dpga:
      return dpga::to_null_basis(dpga::point(p));
    case CalcModel::dcga:
      return dcga::point(p);
    case CalcModel::qcga:
      return qcga::to_clifford(qcga::point(p));
    case CalcModel::none:
      break;
  }
  c.fail("point() is not defined in algebra " + c.alg.name);
}

Multivector point_(const CallArgs& c) {
  if (static_cast<int>(c.size()) != c.alg.point_dimension)
    c.fail("point() takes " + std::to_string(c.alg.point_dimension) + " coordinates in algebra " +
           c.alg.name + ", got " + std::to_string(c.size()));
  std::vector<double> x;
  for (std::size_t i = 0; i < c.size(); ++i) x.push_back(c.number(i, "a coordinate"));
  return embed_point(c, x);
}

// ---- CGA
// -----------------------------------------------------------------------------------------

cga::Full to_cga(const CallArgs& c, std::size_t i) {
  try {
    return graded::from_clifford<cga::Full>(c[i]);
  } catch (const std::exception&) {
    c.fail_at(i, std::string(c.name) + ": " + nth(i) + " is not an element of cga3");
  }
}
template <graded::GradeMask G>
Multivector from_cga(const cga::Multivector<G>& x) {
  return graded::to_clifford(x);
}
Multivector euclidean(const Vec3d& v) {
  return clifford::from_terms({{cga::e1_mask, v.x}, {cga::e2_mask, v.y}, {cga::e3_mask, v.z}});
}

// A Euclidean vector x e1 + y e2 + z e3 at argument i.
Vec3d cga_vector_arg(const CallArgs& c, std::size_t i, std::string_view what) {
  for (const auto& t : c[i].terms)
    if (t.mask != cga::e1_mask && t.mask != cga::e2_mask && t.mask != cga::e3_mask)
      c.fail_at(i, std::string(c.name) + ": " + std::string(what) +
                       " must be a Euclidean vector x*e1 + y*e2 + z*e3");
  const Vec3d v{c[i][cga::e1_mask], c[i][cga::e2_mask], c[i][cga::e3_mask]};
  if (!is_finite(v))
    c.fail_at(i, std::string(c.name) + ": " + std::string(what) + " is not finite");
  return v;
}

// A point at argument i: a conformal point (point(x,y,z), any weight) or a Euclidean vector.
Vec3d cga_point_arg(const CallArgs& c, std::size_t i) {
  const Multivector& m = c[i];
  const std::string bad =
      std::string(c.name) + ": " + nth(i) + " must be a point: point(x,y,z) or x*e1 + y*e2 + z*e3";
  if (clifford::grades_present(m) & ~2u) c.fail_at(i, bad);
  const double w = m[cga::eo_mask];
  if (w == 0) {
    if (m[cga::einf_mask] != 0) c.fail_at(i, bad + " (this is a dual plane or a direction)");
    return cga_vector_arg(c, i, nth(i));
  }
  const cga::Vector v = graded::from_clifford<cga::Vector>(m);
  const Vec3d x = cga::down(v);
  // A point has e_∞ coefficient ½|x|² w; a dual sphere differs by −½ r² w.
  const double expected = 0.5 * dot(x, x) * w, got = m[cga::einf_mask];
  if (std::abs(got - expected) > 1e-9 * std::max(1.0, std::abs(expected)))
    c.fail_at(i, bad + " (this vector is not null: a dual sphere?)");
  if (!std::isfinite(x.x) || !std::isfinite(x.y) || !std::isfinite(x.z))
    c.fail_at(i, std::string(c.name) + ": " + nth(i) + " is not finite");
  return x;
}

// The form an object is read in: a non-null vector can only be a dual sphere or plane; everything
// else is read as a direct (outer-product) form.
cga::Form form_of(const cga::Full& x) {
  const auto v = graded::project<cga::NullBasis::all_grades & 2u>(x);
  bool only_vector = true;
  for (std::size_t k = 0; k < x.size; ++k)
    if (clifford::grade_of(x.blades[k]) != 1 && x.c[k] != 0) only_vector = false;
  if (!only_vector) return cga::Form::direct;
  const double scale = std::max(max_abs(v), 1e-300);
  return std::abs(cga::scalar_product(v, v)) > 1e-12 * scale * scale ? cga::Form::dual
                                                                     : cga::Form::direct;
}

Multivector up_(const CallArgs& c) {
  if (c.size() == 3) return point_(c);
  return from_cga(cga::up(cga_point_arg(c, 0)));
}
Multivector down_(const CallArgs& c) {
  return euclidean(cga_point_arg(c, 0));
}

Multivector pair_(const CallArgs& c) {
  return from_cga(cga::point_pair(cga_point_arg(c, 0), cga_point_arg(c, 1)));
}
Multivector line_(const CallArgs& c) {
  return from_cga(cga::line(cga_point_arg(c, 0), cga_point_arg(c, 1)));
}
Multivector circle_(const CallArgs& c) {
  if (c.size() == 3 && is_scalar(c[2]))
    return from_cga(cga::circle_from_center(cga_point_arg(c, 0), cga_vector_arg(c, 1, "the normal"),
                                            c.number(2, "the radius")));
  if (c.size() != 3) c.fail("circle() takes three points, or circle(C, N, r)");
  return from_cga(cga::circle(cga_point_arg(c, 0), cga_point_arg(c, 1), cga_point_arg(c, 2)));
}
Multivector plane_(const CallArgs& c) {
  if (c.size() == 2)
    return from_cga(
        cga::plane_from_normal(cga_vector_arg(c, 0, "the normal"), c.number(1, "the distance")));
  return from_cga(cga::plane(cga_point_arg(c, 0), cga_point_arg(c, 1), cga_point_arg(c, 2)));
}
Multivector sphere_(const CallArgs& c) {
  if (c.size() == 2) {
    const double r = c.number(1, "the radius");
    if (!(r >= 0)) c.fail_at(1, "sphere: the radius must be zero or positive");
    return from_cga(cga::sphere_from_center(cga_point_arg(c, 0), r));
  }
  if (c.size() != 4) c.fail("sphere() takes four points, or sphere(C, r)");
  return from_cga(cga::sphere(cga_point_arg(c, 0), cga_point_arg(c, 1), cga_point_arg(c, 2),
                              cga_point_arg(c, 3)));
}

cga::Kind kind_of(const cga::Full& x, cga::Form form) {
  return cga::classify(x, form);
}
[[noreturn]] void wrong_kind(const CallArgs& c, cga::Kind k, const char* expected) {
  c.fail_at(0, std::string(c.name) + ": the argument is a " + cga::kind_name(k) + "; " +
                   std::string(c.name) + "() reads " + expected);
}

Multivector center_(const CallArgs& c) {
  const cga::Full x = to_cga(c, 0);
  return euclidean(cga::location(x, form_of(x)));
}
Multivector radius2_(const CallArgs& c) {
  const cga::Full x = to_cga(c, 0);
  return clifford::scalar(cga::round_params(x, form_of(x)).radius_squared);
}
Multivector radius_(const CallArgs& c) {
  const cga::Full x = to_cga(c, 0);
  const cga::RoundParams r = cga::round_params(x, form_of(x));
  if (r.imaginary)
    c.fail("radius: an imaginary round (radius2 = " + std::to_string(r.radius_squared) +
           "); radius2() gives the signed square");
  return clifford::scalar(r.radius);
}
Multivector direction_(const CallArgs& c) {
  const cga::Full x = to_cga(c, 0);
  const cga::Form form = form_of(x);
  const cga::Kind k = kind_of(x, form);
  if (k == cga::Kind::line) return euclidean(cga::line_params(x, form).unit_direction);
  if (k == cga::Kind::point_pair || k == cga::Kind::imaginary_point_pair ||
      (k == cga::Kind::tangent && max_abs(graded::project<4u>(x)) > 0))
    return euclidean(cga::pair_params(x, form).direction);
  wrong_kind(c, k, "lines and point pairs");
}
Multivector normal_(const CallArgs& c) {
  const cga::Full x = to_cga(c, 0);
  const cga::Form form = form_of(x);
  const cga::Kind k = kind_of(x, form);
  if (k == cga::Kind::plane) return euclidean(cga::plane_params(x, form).normal);
  if (k == cga::Kind::circle || k == cga::Kind::imaginary_circle)
    return euclidean(cga::circle_params(x, form).normal);
  wrong_kind(c, k, "planes and circles");
}
Multivector distance_(const CallArgs& c) {
  if (c.size() == 2) return clifford::scalar(length(cga_point_arg(c, 0) - cga_point_arg(c, 1)));
  const cga::Full x = to_cga(c, 0);
  const cga::Form form = form_of(x);
  const cga::Kind k = kind_of(x, form);
  if (k != cga::Kind::plane) wrong_kind(c, k, "planes (or two points: distance(P, Q))");
  return clifford::scalar(cga::plane_params(x, form).distance);
}
Multivector pair_point_(const CallArgs& c) {
  const cga::Full x = to_cga(c, 0);
  const int k = c.size() > 1 ? c.integer(1, 2, "the index") : 1;
  if (k < 1) c.fail_at(1, "pair_point: the index is 1 (larger norm) or 2");
  return from_cga(cga::up(cga::pair_points(x, form_of(x))[static_cast<std::size_t>(k - 1)]));
}
// The meet of two objects in direct form: undual(dual(A) ∧ dual(B)).
Multivector intersect_cga(const CallArgs& c) {
  const cga::Full a = to_cga(c, 0), b = to_cga(c, 1);
  const auto da = graded::project<cga::NullBasis::all_grades>(cga::dual(a));
  const auto db = graded::project<cga::NullBasis::all_grades>(cga::dual(b));
  return from_cga(cga::undual(cga::meet_dual(da, db)));
}
Multivector translator_(const CallArgs& c) {
  return from_cga(cga::translator({c.number(0, "x"), c.number(1, "y"), c.number(2, "z")}));
}
Multivector rotor_(const CallArgs& c) {
  return from_cga(cga::rotor(cga_vector_arg(c, 0, "the axis"), c.number(1, "the angle")));
}
Multivector dilator_(const CallArgs& c) {
  return from_cga(cga::dilator(c.number(0, "the scale factor")));
}

// ---- quadric models
// ------------------------------------------------------------------------------

// The DPGA element of a null-basis multivector: each blade w_a ∧ w_b ∧ … rebuilt as the outer
// product of dpga::w / dpga::w_star on the graded engine (the inverse of dpga::to_null_basis).
dpga::Bivector to_dpga_bivector(const CallArgs& c, std::size_t i) {
  dpga::Bivector q;
  for (const auto& t : c[i].terms) {
    if (clifford::grade_of(t.mask) != 2)
      c.fail_at(i, std::string(c.name) + ": " + nth(i) + " must be a bivector (a DPGA quadric)");
    int a = -1, b = -1;
    for (int k = 0; k < 8; ++k)
      if (t.mask & (1u << k)) (a < 0 ? a : b) = k;
    auto gen = [](int k) { return k < 4 ? dpga::w(k) : dpga::w_star(k - 4); };
    q = q + t.coeff * (gen(a) ^ gen(b));
  }
  return q;
}

Vec3d model_point_arg(const CallArgs& c, std::size_t i) {
  const std::string bad =
      std::string(c.name) + ": " + nth(i) + " must be a point of " + c.alg.name + " (point(x,y,z))";
  Vec3d p{};
  try {
    switch (c.alg.model) {
      case CalcModel::dpga: {
        if (clifford::grades_present(c[i]) & ~2u) c.fail_at(i, bad);
        for (const char* star : {"w0s", "w1s", "w2s", "w3s"})
          if (coefficient(c, c[i], star) != 0) c.fail_at(i, bad + " (it has a w_i* part)");
        const double w = coefficient(c, c[i], "w3");
        if (w == 0) c.fail_at(i, bad + " (its w3 weight is zero: a direction)");
        p = {coefficient(c, c[i], "w0") / w, coefficient(c, c[i], "w1") / w,
             coefficient(c, c[i], "w2") / w};
        break;
      }
      case CalcModel::dcga:
        p = dcga::point_coordinates(c[i]);
        break;
      case CalcModel::qcga:
        p = qcga::point_coordinates(qcga::from_clifford(c[i]));
        break;
      default:
        c.fail_at(i, bad);
    }
  } catch (const ModelError& e) {
    c.fail_at(i, bad + ": " + e.what());
  }
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
    c.fail_at(i, bad + " (not finite)");
  return p;
}

Multivector model_element(const CallArgs& c, const quadric::Quadric& q) {
  switch (c.alg.model) {
    case CalcModel::dpga:
      return dpga::to_null_basis(dpga::quadric(q));
    case CalcModel::dcga:
      return dcga::quadric(q);
    case CalcModel::qcga:
      return qcga::to_clifford(qcga::dual_quadric(q));
    default:
      c.fail("quadrics are elements of dpga, dcga and qcga");
  }
}

// The ten coefficients of the quadric at argument i; fails when the element is not a quadric of
// the model (rebuilding it from its coefficients must give it back).
quadric::Quadric coefficients_arg(const CallArgs& c, std::size_t i) {
  quadric::Quadric q;
  try {
    switch (c.alg.model) {
      case CalcModel::dpga:
        q = dpga::coefficients(to_dpga_bivector(c, i));
        break;
      case CalcModel::dcga:
        q = dcga::coefficients(c[i]);
        break;
      case CalcModel::qcga:
        q = qcga::coefficients(qcga::from_clifford(c[i]));
        break;
      default:
        c.fail("quadrics are elements of dpga, dcga and qcga");
    }
  } catch (const ModelError& e) {
    c.fail_at(i, std::string(c.name) + ": " + nth(i) + " is not a quadric: " + e.what());
  }
  const Multivector back = model_element(c, q) - c[i];
  if (clifford::max_abs_coeff(back) > 1e-9 * std::max(clifford::max_abs_coeff(c[i]), 1e-300))
    c.fail_at(i, std::string(c.name) + ": " + nth(i) + " is not a quadric of " + c.alg.name +
                     " (build one with quadric(a,b,c,d,e,f,g,h,i,j))");
  return q;
}

Multivector quadric_(const CallArgs& c) {
  if (c.size() == 10) {
    quadric::Quadric q;
    for (std::size_t k = 0; k < 10; ++k) q[k] = c.number(k, "a coefficient");
    quadric::check_finite(q);
    return model_element(c, q);
  }
  if (c.size() != 9) c.fail("quadric() takes ten coefficients a..j or nine points");
  std::array<Vec3d, 9> pts;
  for (std::size_t k = 0; k < 9; ++k) pts[k] = model_point_arg(c, k);
  if (c.alg.model == CalcModel::qcga)  // Breuils eq. 70
    return qcga::to_clifford(qcga::quadric_from_points(pts));
  return model_element(c, quadric::through_nine_points(pts));
}

Multivector value_(const CallArgs& c) {
  const Vec3d p = model_point_arg(c, 1);
  switch (c.alg.model) {
    case CalcModel::dpga:
      return clifford::scalar(dpga::value(to_dpga_bivector(c, 0), p));
    case CalcModel::dcga:  // Q·X: quadrics and quartics alike
      return clifford::scalar(dcga::value(c[0], p));
    default:
      return clifford::scalar(qcga::value(qcga::from_clifford(c[0]), p));
  }
}

Multivector gradient_(const CallArgs& c) {
  const Vec3d p = model_point_arg(c, 1);
  switch (c.alg.model) {
    case CalcModel::dpga: {  // the first three coefficients of the polar plane, on w0*..w2*
      const auto pi = dpga::polar_plane(to_dpga_bivector(c, 0), p);
      return blade(c, "w0s", pi[0]) + blade(c, "w1s", pi[1]) + blade(c, "w2s", pi[2]);
    }
    case CalcModel::dcga: {
      const Vec3d n = dcga::gradient(c[0], p);
      return blade(c, "e1", n[0]) + blade(c, "e2", n[1]) + blade(c, "e3", n[2]);
    }
    default: {
      const Vec3d n = qcga::normal(qcga::from_clifford(c[0]), p);
      return blade(c, "e1", n[0]) + blade(c, "e2", n[1]) + blade(c, "e3", n[2]);
    }
  }
}

Multivector tangent_plane_(const CallArgs& c) {
  const Vec3d p = model_point_arg(c, 1);
  switch (c.alg.model) {
    case CalcModel::dpga: {
      const auto pi = dpga::polar_plane(to_dpga_bivector(c, 0), p);
      return blade(c, "w0s", pi[0]) + blade(c, "w1s", pi[1]) + blade(c, "w2s", pi[2]) +
             blade(c, "w3s", pi[3]);
    }
    case CalcModel::dcga:
      return dcga::tangent_plane(c[0], p);
    default:
      return qcga::to_clifford(qcga::tangent_plane(qcga::from_clifford(c[0]), p));
  }
}

// intersect(Q, P1, P2[, k]): the k-th point (ascending along P1 → P2) where the line through P1
// and P2 meets Q.
Multivector intersect_quadric(const CallArgs& c) {
  const quadric::Quadric q = coefficients_arg(c, 0);
  const Vec3d a = model_point_arg(c, 1), b = model_point_arg(c, 2);
  const int k = c.size() > 3 ? c.integer(3, 2, "the index") : 1;
  if (k < 1) c.fail_at(3, "intersect: the index is 1 or 2");
  const Vec3d d{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const quadric::LineIntersection hit = quadric::intersect_line(q, a, d);
  if (hit.kind == quadric::LineKind::contained) c.fail("intersect: the line lies on the quadric");
  if (k > hit.count)
    c.fail("intersect: the line meets the quadric in " + std::to_string(hit.count) + " point" +
           (hit.count == 1 ? "" : "s") + " (" + std::string(quadric::to_string(hit.kind)) + ")");
  const Vec3d& x = hit.points[static_cast<std::size_t>(k - 1)];
  return embed_point(c, {x[0], x[1], x[2]});
}

Multivector intersect_(const CallArgs& c) {
  if (c.alg.model == CalcModel::cga) {
    if (c.size() != 2) c.fail("intersect() takes two objects in cga3: intersect(A, B)");
    return intersect_cga(c);
  }
  if (c.size() < 3) c.fail("intersect() takes a quadric and two points: intersect(Q, P1, P2[, k])");
  return intersect_quadric(c);
}

// rotate(X, i, j, angle) in the quadric models (x_i towards x_j, axes 0, 1, 2), rotate(X, N, angle)
// in cga3 (about the axis N through the origin).
Multivector rotate_(const CallArgs& c) {
  if (c.alg.model == CalcModel::cga) {
    if (c.size() != 3) c.fail("rotate() takes rotate(X, N, angle) in cga3");
    const auto r = cga::rotor(cga_vector_arg(c, 1, "the axis"), c.number(2, "the angle"));
    return from_cga(cga::apply(r, to_cga(c, 0)));
  }
  if (c.size() != 4) c.fail("rotate() takes rotate(Q, i, j, angle) in " + c.alg.name);
  const int i = c.integer(1, 2, "the axis i"), j = c.integer(2, 2, "the axis j");
  if (i == j) c.fail_at(2, "rotate: the axes i and j must differ");
  const double angle = c.number(3, "the angle");
  switch (c.alg.model) {
    case CalcModel::dpga:
      return dpga::to_null_basis(dpga::rotate(to_dpga_bivector(c, 0), i, j, angle));
    case CalcModel::dcga:
      return dcga::transform(dcga::rotor(i, j, angle), c[0]);
    default:
      return model_element(
          c, quadric::rotate(coefficients_arg(c, 0), quadric::plane_rotation(i, j, angle)));
  }
}

// translate(X, x, y, z): DCGA and CGA by their translators; DPGA has no translating versor and
// QCGA's is not implemented: both through the coefficients (docs/models-quadrics.md §2).
Multivector translate_(const CallArgs& c) {
  const Vec3d t{c.number(1, "x"), c.number(2, "y"), c.number(3, "z")};
  switch (c.alg.model) {
    case CalcModel::cga:
      return from_cga(cga::apply(cga::translator(t), to_cga(c, 0)));
    case CalcModel::dcga:
      return dcga::transform(dcga::translator({t.x, t.y, t.z}), c[0]);
    default:
      return model_element(c, quadric::translate(coefficients_arg(c, 0), {t.x, t.y, t.z}));
  }
}

constexpr FunctionInfo models[] = {
    {"point", "point(x, y[, z...])", "the model's point", 1, 7, point_models, point_},
    {"up", "up(x, y, z) | up(V)", "conformal point of coordinates or of x*e1 + y*e2 + z*e3", 1, 3,
     cga_only, up_},
    {"down", "down(P)", "Euclidean vector x*e1 + y*e2 + z*e3 of a conformal point", 1, 1, cga_only,
     down_},
    {"pair", "pair(P1, P2)", "point pair P1 ^ P2", 2, 2, cga_only, pair_},
    {"line", "line(P1, P2)", "line P1 ^ P2 ^ ei", 2, 2, cga_only, line_},
    {"circle", "circle(P1, P2, P3) | circle(C, N, r)", "circle through 3 points, or by centre", 3,
     3, cga_only, circle_},
    {"plane", "plane(P1, P2, P3) | plane(N, d)", "plane through 3 points, or n.x = d", 2, 3,
     cga_only, plane_},
    {"sphere", "sphere(P1, P2, P3, P4) | sphere(C, r)", "sphere through 4 points, or by centre", 2,
     4, cga_only, sphere_},
    {"center", "center(X)", "centre of a round, position of a point, foot of a flat", 1, 1,
     cga_only, center_},
    {"radius", "radius(X)", "radius of a real round", 1, 1, cga_only, radius_},
    {"radius2", "radius2(X)", "signed squared radius of a round (< 0: imaginary)", 1, 1, cga_only,
     radius2_},
    {"direction", "direction(X)", "unit direction of a line or point pair", 1, 1, cga_only,
     direction_},
    {"normal", "normal(X)", "unit normal of a plane or circle", 1, 1, cga_only, normal_},
    {"distance", "distance(X) | distance(P, Q)",
     "signed distance of a plane from the origin, or of two points", 1, 2, cga_only, distance_},
    {"pair_point", "pair_point(X[, k])", "point k (1: larger norm, 2) of a point pair", 1, 2,
     cga_only, pair_point_},
    {"intersect", "intersect(A, B)", "meet of two objects: undual(dual(A) ^ dual(B))", 2, 2,
     cga_only, intersect_},
    {"translator", "translator(x, y, z)", "translation versor", 3, 3, cga_only, translator_},
    {"rotor", "rotor(N, angle)", "rotation about the axis N through the origin", 2, 2, cga_only,
     rotor_},
    {"dilator", "dilator(s)", "scaling by s about the origin", 1, 1, cga_only, dilator_},
    {"rotate", "rotate(X, N, angle)", "X rotated about the axis N", 3, 3, cga_only, rotate_},
    {"translate", "translate(X, x, y, z)", "X translated", 4, 4, cga_only, translate_},
    {"quadric", "quadric(a..j) | quadric(P1..P9)",
     "quadric from its ten coefficients or through nine points", 9, 10, quadric_models, quadric_},
    {"value", "value(Q, P)", "F(p) of the quadric at a point", 2, 2, quadric_models, value_},
    {"gradient", "gradient(Q, P)", "the gradient of F at a point", 2, 2, quadric_models, gradient_},
    {"tangent_plane", "tangent_plane(Q, P)", "the model's tangent (polar) plane at a point", 2, 2,
     quadric_models, tangent_plane_},
    {"intersect", "intersect(Q, P1, P2[, k])",
     "k-th point (1, 2) where the line P1P2 meets the quadric", 3, 4, quadric_models, intersect_},
    {"rotate", "rotate(Q, i, j, angle)", "Q rotated turning axis i towards j (0 x, 1 y, 2 z)", 4, 4,
     quadric_models, rotate_},
    {"translate", "translate(Q, x, y, z)", "Q translated", 4, 4, quadric_models, translate_},
};

}  // namespace

std::span<const FunctionInfo> model_functions() {
  return models;
}

}  // namespace pgamesh::cli
