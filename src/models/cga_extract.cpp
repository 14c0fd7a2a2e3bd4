// Parameters of conformal objects and the classification of blades (docs/models-cga.md §5).
#include "pgamesh/models/cga_extract.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "pgamesh/models/cga_motor.hpp"

namespace pgamesh::cga {

namespace {

double max_abs(const Full& x) {
  double m = 0;
  for (double c : x.c) m = std::max(m, std::abs(c));
  return m;
}

// The grades whose coefficients exceed rel · max|x|.
GradeMask grades_present(const Full& x, double rel) {
  const double tol = rel * max_abs(x);
  GradeMask g = 0;
  for (std::size_t i = 0; i < x.size; ++i)
    if (std::abs(x.c[i]) > tol) g |= GradeMask{1} << clifford::grade_of(x.blades[i]);
  return g;
}

int single_grade(const Full& x) {
  const GradeMask g = grades_present(x, 0.0);
  for (int k = 0; k <= 5; ++k)
    if (g == (GradeMask{1} << k)) return k;
  return -1;
}

Full direct_form(const Full& x, Form form) {
  return form == Form::dual ? undual(x) : x;
}

// x's grade in direct form, or a ModelError naming what was expected.
int require_grade(const Full& x, const char* what, int expected_direct) {
  const int k = single_grade(x);
  if (k != expected_direct)
    throw ModelError(
        std::string("cga::") + what + ": expected a grade-" + std::to_string(expected_direct) +
        " blade in direct form (grade " + std::to_string(5 - expected_direct) +
        " in dual form), got " +
        (k < 0 ? std::string("a zero or mixed-grade element") : "grade " + std::to_string(k)));
  return k;
}

// The centre of a round as the normalised X e_∞ X; throws for a flat (weight zero).
Vec3d raw_center(const Full& x) {
  const Vector c = product<detail::Product::geometric, 2u>(x * einf(), x);
  const double w = weight(c);
  const Vec3d p = euclidean(c) / w;
  if (w == 0 || !std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
    throw ModelError(
        "cga: the element has no centre (X e_inf X has no e_o part): a flat, not a round");
  return p;
}

Full translated(const Full& x, Vec3d t) {
  return sandwich(translator(t), x);
}

// ρ² = ⟨X X̂⟩₀ / ⟨(e_∞⌋X)²⟩₀ of a round about (near) the origin.
double raw_radius_squared(const Full& x) {
  const Full l = widen<63>(left_contraction(einf(), x));
  const double den = scalar_product(l, l);
  if (den == 0) throw ModelError("cga: the element is not a round (e_inf _| X squares to 0)");
  return scalar_product(x, graded::involution(x)) / den;
}

// Centre (refined once about the first estimate) and the element moved to it.
Vec3d center_and_move(const Full& x, Full& at_center) {
  const Vec3d c0 = raw_center(x);
  const Full y = translated(x, -c0);
  const Vec3d dc = raw_center(y);
  at_center = translated(y, -dc);
  return c0 + dc;
}

RoundParams round_of(const Full& x) {
  Full z;
  RoundParams r;
  r.center = center_and_move(x, z);
  r.radius_squared = raw_radius_squared(z);
  r.imaginary = r.radius_squared < 0;
  r.radius = std::sqrt(std::abs(r.radius_squared));
  return r;
}

double coeff(const Full& x, BladeMask m) {
  return x[m];
}

// Hodge dual in 3-D of the Euclidean bivector with coefficients on e12, e13, e23: (b23, −b13, b12).
Vec3d bivector_to_vector(double b12, double b13, double b23) {
  return {b23, -b13, b12};
}

}  // namespace

const char* kind_name(Kind k) {
  switch (k) {
    case Kind::zero:
      return "zero";
    case Kind::scalar:
      return "scalar";
    case Kind::point:
      return "point";
    case Kind::point_at_infinity:
      return "point at infinity";
    case Kind::flat_point:
      return "flat point";
    case Kind::point_pair:
      return "point pair";
    case Kind::imaginary_point_pair:
      return "imaginary point pair";
    case Kind::tangent:
      return "tangent (round of zero radius)";
    case Kind::line:
      return "line";
    case Kind::circle:
      return "circle";
    case Kind::imaginary_circle:
      return "imaginary circle";
    case Kind::plane:
      return "plane";
    case Kind::sphere:
      return "sphere";
    case Kind::imaginary_sphere:
      return "imaginary sphere";
    case Kind::direction:
      return "direction (free blade)";
    case Kind::space:
      return "space (pseudoscalar)";
    case Kind::vector:
      return "non-null vector (a dual sphere or plane, no direct object)";
    case Kind::mixed_grades:
      return "mixed grades";
    case Kind::not_a_blade:
      return "not a blade";
  }
  return "?";
}

RoundParams round_params(const Full& x, Form form) {
  const Full d = direct_form(x, form);
  const int k = single_grade(d);
  if (k < 2 || k > 4)
    throw ModelError(
        "cga::round_params: expected a point pair, circle or sphere (direct grade 2-4)");
  return round_of(d);
}

PairParams pair_params(const Full& x, Form form) {
  const Full d = direct_form(x, form);
  require_grade(d, "pair_params", 2);
  PairParams p;
  p.round = round_of(d);
  // V2 = b + ½ v e_∞ − u e_o − ½ γ N (Hitzer eq. 6) with −u e_o = e_o ∧ u, −½ γ N = ½ γ e_o∧e_∞.
  p.u = {coeff(d, eo_mask | e1_mask), coeff(d, eo_mask | e2_mask), coeff(d, eo_mask | e3_mask)};
  p.v = 2.0 * Vec3d{coeff(d, e1_mask | einf_mask), coeff(d, e2_mask | einf_mask),
                    coeff(d, e3_mask | einf_mask)};
  p.gamma = 2.0 * coeff(d, eo_mask | einf_mask);
  p.b = bivector_to_vector(coeff(d, e1_mask | e2_mask), coeff(d, e1_mask | e3_mask),
                           coeff(d, e2_mask | e3_mask));
  const double lu = length(p.u);
  if (!(lu > 0)) throw ModelError("cga::pair_params: the pair has no direction (u = 0)");
  p.direction = -p.u / lu;  // Hitzer eq. 11: the e_o part is 2r p̂ ∧ e_o, so p̂ = −u/|u|
  return p;
}

std::array<Vec3d, 2> pair_points(const Full& x, Form form) {
  const Full d = direct_form(x, form);
  require_grade(d, "pair_points", 2);
  Full z;
  const Vec3d c = center_and_move(d, z);
  const Bivector v2 = graded::grade<2>(z);
  const double s2 = scalar_product(v2, v2);
  if (s2 < 0)
    throw ModelError(
        "cga::pair_points: the point pair is imaginary (V2^2 < 0): it has no real points");
  const Vector dv = left_contraction(einf(), v2);
  const double dd = scalar_product(dv, dv);
  if (!(dd > 0)) throw ModelError("cga::pair_points: the element is not a point pair");
  const Vector dinv = dv / dd;
  const double s = std::sqrt(s2);
  const Vector base = graded::grade<1>(v2 * dinv);
  std::array<Vec3d, 2> out = {c + down(base - s * dinv), c + down(base + s * dinv)};
  if (dot(out[1], out[1]) > dot(out[0], out[0])) std::swap(out[0], out[1]);
  return out;
}

LineParams line_params(const Full& x, Form form) {
  const Full d = direct_form(x, form);
  require_grade(d, "line_params", 3);
  LineParams l;
  // m e_∞ + d N with d N = e_o ∧ d ∧ e_∞ (Hitzer eq. 16).
  l.direction = {coeff(d, eo_mask | e1_mask | einf_mask), coeff(d, eo_mask | e2_mask | einf_mask),
                 coeff(d, eo_mask | e3_mask | einf_mask)};
  l.moment = bivector_to_vector(coeff(d, e1_mask | e2_mask | einf_mask),
                                coeff(d, e1_mask | e3_mask | einf_mask),
                                coeff(d, e2_mask | e3_mask | einf_mask));
  const double dd = dot(l.direction, l.direction);
  if (!(dd > 0)) throw ModelError("cga::line_params: the element has no direction: not a line");
  l.unit_direction = l.direction / std::sqrt(dd);
  l.closest_point = cross(l.direction, l.moment) / dd;  // Hitzer eq. 17 at α = 0
  return l;
}

CircleParams circle_params(const Full& x, Form form) {
  const Full d = direct_form(x, form);
  require_grade(d, "circle_params", 3);
  CircleParams c;
  c.round = round_of(d);
  // The e_o ∧ Ic part (Hitzer eq. 24: Ic n̄ = Ic ∧ e_o = e_o ∧ Ic).
  c.plane_bivector = {coeff(d, eo_mask | e1_mask | e2_mask), coeff(d, eo_mask | e1_mask | e3_mask),
                      coeff(d, eo_mask | e2_mask | e3_mask)};
  const Vec3d n = bivector_to_vector(c.plane_bivector[0], c.plane_bivector[1], c.plane_bivector[2]);
  const double ln = length(n);
  if (!(ln > 0)) throw ModelError("cga::circle_params: the element has no plane bivector");
  c.normal = n / ln;
  c.carrier = graded::grade<4>(d ^ einf());
  return c;
}

PlaneParams plane_params(const Full& x, Form form) {
  PlaneParams p;
  if (form == Form::dual) {
    const int k = single_grade(x);
    if (k != 1) throw ModelError("cga::plane_params: a dual plane is a vector n + delta e_inf");
    const Vector v = graded::grade<1>(x);
    const Vec3d n = euclidean(v);
    const double ln = length(n);
    if (!(ln > 0)) throw ModelError("cga::plane_params: the dual plane has no normal");
    if (std::abs(weight(v)) > 1e-12 * std::max(ln, std::abs(v[einf_mask])))
      throw ModelError("cga::plane_params: the vector has an e_o part: a dual sphere, not a plane");
    p.normal = n / ln;
    p.distance = v[einf_mask] / ln;
  } else {
    require_grade(x, "plane_params", 4);
    // e_o ∧ Ip ∧ e_∞ + (p1 ∧ p2 ∧ p3) ∧ e_∞ (Hitzer eqs. 36–38; −Ip N = e_o ∧ Ip ∧ e_∞).
    const Vec3d n = bivector_to_vector(coeff(x, eo_mask | e1_mask | e2_mask | einf_mask),
                                       coeff(x, eo_mask | e1_mask | e3_mask | einf_mask),
                                       coeff(x, eo_mask | e2_mask | e3_mask | einf_mask));
    const double ln = length(n);
    if (!(ln > 0)) throw ModelError("cga::plane_params: the element has no normal: not a plane");
    p.normal = n / ln;
    p.distance = coeff(x, e1_mask | e2_mask | e3_mask | einf_mask) / ln;
  }
  p.foot = p.distance * p.normal;  // Hitzer eq. 39
  return p;
}

RoundParams sphere_params(const Full& x, Form form) {
  const Full d = direct_form(x, form);
  require_grade(d, "sphere_params", 4);
  // Through the dual σ = ± w (C − ½ ρ² e_∞) (Hitzer eq. 50): centre σ_E / σ_o and
  // ρ² = σ² / (σ·e_∞)², σ² taken about the centre.
  const Vector s = graded::grade<1>(dual(d));
  const double w = weight(s);
  if (w == 0 || !std::isfinite(w))
    throw ModelError("cga::sphere_params: the element is a plane (no e_o part in its dual)");
  RoundParams r;
  r.center = euclidean(s) / w;
  const Vector sc = sandwich(translator(-r.center), s) / w;
  r.radius_squared = scalar_product(sc, sc);
  r.imaginary = r.radius_squared < 0;
  r.radius = std::sqrt(std::abs(r.radius_squared));
  return r;
}

Vec3d location(const Full& x, Form form) {
  const Full d = direct_form(x, form);
  switch (classify(x, form)) {
    case Kind::point:
      return down(graded::grade<1>(d));
    case Kind::flat_point: {
      const double w = coeff(d, eo_mask | einf_mask);
      return Vec3d{coeff(d, e1_mask | einf_mask), coeff(d, e2_mask | einf_mask),
                   coeff(d, e3_mask | einf_mask)} /
             w;
    }
    case Kind::line:
      return line_params(d).closest_point;
    case Kind::plane:
      return plane_params(x, form).foot;
    case Kind::point_pair:
    case Kind::imaginary_point_pair:
    case Kind::circle:
    case Kind::imaginary_circle:
    case Kind::sphere:
    case Kind::imaginary_sphere:
    case Kind::tangent:
      return round_of(d).center;
    default:
      throw ModelError(std::string("cga::location: a ") + kind_name(classify(x, form)) +
                       " has no location");
  }
}

Full carrier(const Full& x, Form form) {
  return widen<63>(direct_form(x, form) ^ einf());
}

Kind classify(const Full& x, Form form, double rel) {
  const double scale = max_abs(x);
  if (scale == 0) return Kind::zero;
  const GradeMask g = grades_present(x, rel);
  int k = -1;
  for (int i = 0; i <= 5; ++i)
    if (g == (GradeMask{1} << i)) k = i;
  if (k < 0) return Kind::mixed_grades;
  Full d = direct_form(x, form);
  for (std::size_t i = 0; i < d.size; ++i)  // drop the other grades' round-off
    if (clifford::grade_of(d.blades[i]) != (form == Form::dual ? 5 - k : k)) d.c[i] = 0;
  if (form == Form::dual) {
    // A null vector is a point in either form (as a dual sphere it has radius 0).
    if (k == 1) {
      const Vector v = graded::grade<1>(x);
      if (std::abs(scalar_product(v, v)) <= rel * scale * scale)
        return std::abs(weight(v)) <= rel * scale ? Kind::point_at_infinity : Kind::point;
    }
    k = 5 - k;
  }
  if (k == 0) return Kind::scalar;
  if (k == 5) return Kind::space;
  if (k == 1) {
    const Vector v = graded::grade<1>(d);
    if (std::abs(scalar_product(v, v)) <= rel * scale * scale)
      return std::abs(weight(v)) <= rel * scale ? Kind::point_at_infinity : Kind::point;
    return Kind::vector;
  }
  // Move a round to its centre first, so that the relative tests do not depend on where it is.
  // The move adds round-off of about ε times the original coefficients (`noise`), which the
  // tolerances include. Flats have no centre (X e_∞ X has weight 0) and stay where they are;
  // their e_o ∧ E part is exactly zero and stays so under any translation.
  const double s0 = max_abs(d);
  try {
    const Vec3d c = raw_center(d);
    if (length(c) < 1e9 * (1 + s0)) d = translated(d, -c);
  } catch (const ModelError&) {
  }
  const double s = max_abs(d);
  const double noise = 64 * std::numeric_limits<double>::epsilon() * s0;
  const double tol1 = rel * s + noise, tol2 = rel * s * s + noise * s;
  auto small = [&](const Full& y, double tol) { return max_abs(y) <= tol; };
  // Blades: grade 2 needs X ∧ X = 0; grade 3 is a blade when its dual (a bivector) is one.
  if (k == 2 && !small(widen<63>(d ^ d), tol2)) return Kind::not_a_blade;
  if (k == 3) {
    const Full y = dual(d);
    if (!small(widen<63>(y ^ y), tol2)) return Kind::not_a_blade;
  }
  if (small(widen<63>(einf() ^ d), tol1)) {
    if (small(widen<63>(left_contraction(einf(), d)), tol1)) return Kind::direction;
    return k == 2 ? Kind::flat_point : (k == 3 ? Kind::line : Kind::plane);
  }
  const Full l = widen<63>(left_contraction(einf(), d));
  const double num = scalar_product(d, graded::involution(d));
  const double den = scalar_product(l, l);
  if (std::abs(num) <= tol2) return Kind::tangent;
  const bool imaginary = num / den < 0;
  if (k == 2) return imaginary ? Kind::imaginary_point_pair : Kind::point_pair;
  if (k == 3) return imaginary ? Kind::imaginary_circle : Kind::circle;
  return imaginary ? Kind::imaginary_sphere : Kind::sphere;
}

double distance(Vec3d x, Vec3d y) {
  return point_distance(up(x), up(y));
}

double distance_to_plane(Vec3d x, const Vector& dual_plane) {
  const double ln = length(euclidean(dual_plane));
  if (!(ln > 0)) throw ModelError("cga::distance_to_plane: the dual plane has no normal");
  return scalar_product(up(x), dual_plane) / ln;  // X·π = n·x − δ (e_o·e_∞ = −1)
}

double distance_to_sphere(Vec3d x, const Vector& dual_sphere) {
  const RoundParams r = sphere_params(undual(dual_sphere), Form::direct);
  const double w = weight(dual_sphere);
  const double q = scalar_product(up(x - r.center), sandwich(translator(-r.center), dual_sphere));
  const double dist = length(x - r.center);
  const double denom = dist + r.radius;
  if (denom == 0) return -r.radius;
  return -2.0 * (q / w) / denom;
}

}  // namespace pgamesh::cga
