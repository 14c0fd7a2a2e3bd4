// Quadric surfaces independent of any algebra: the ten coefficients, values, gradients, tangent
// planes, line intersections, rigid motions, classification and fitting. The geometric-algebra
// models (dpga.hpp, dcga.hpp, qcga.hpp) reduce to these closed forms; docs/models-quadrics.md
// gives every formula and the paper's equation (Breuils et al., "Efficient representation and
// manipulation of quadratic surfaces using Geometric Algebras").
//
// The conventions of the three models (the corrected DPGA rotor, the e/f order of the paper) are
// docs/conventions.md §16.
//
// Coefficient order (every model and file, docs/models-quadrics.md §1):
//   F(x,y,z) = a x² + b y² + c z² + d xy + e xz + f yz + g x + h y + i z + j
// i.e. e is the xz and f the yz coefficient (the paper prints both e yz + f zx and e xz + f yz;
// the xz/yz reading is the one its extraction operators, Breuils eqs. 14, 37, 53–54, 61, use).
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <string_view>

#include "pgamesh/core/vec3.hpp"
#include "pgamesh/models/model_error.hpp"

namespace pgamesh::quadric {

// Points and 3×3 matrices are the core's (core/vec3.hpp).
using pgamesh::Mat3;
using pgamesh::Vec3d;
using Mat4 = std::array<std::array<double, 4>, 4>;

// The ten coefficients a … j of F, in the order above.
struct Quadric {
  std::array<double, 10> k{};

  double& operator[](std::size_t n) { return k[n]; }
  double operator[](std::size_t n) const { return k[n]; }
  friend bool operator==(const Quadric&, const Quadric&) = default;
};

// Names of the monomials of k[0..9]: "x2", "y2", "z2", "xy", "xz", "yz", "x", "y", "z", "1".
inline constexpr std::array<std::string_view, 10> monomial_names = {"x2", "y2", "z2", "xy", "xz",
                                                                    "yz", "x",  "y",  "z",  "1"};

// The monomials x², y², z², xy, xz, yz, x, y, z, 1 at p.
std::array<double, 10> monomials(const Vec3d& p);

// F(p) (Breuils eq. 37, the value every model's point test reduces to).
double value(const Quadric& q, const Vec3d& p);

// ∇F(p) = (2a x + d y + e z + g, 2b y + d x + f z + h, 2c z + e x + f y + i) (Breuils eqs. 15, 45).
Vec3d gradient(const Quadric& q, const Vec3d& p);

// ∇F(p)/‖∇F(p)‖. Throws ModelError at a singular point (zero gradient, e.g. a cone's apex).
Vec3d unit_normal(const Quadric& q, const Vec3d& p);

// Tangent plane at p as [n_x, n_y, n_z, −n·p] with n = ∇F(p): the plane n·x − n·p = 0 through p
// (for p on the surface; Breuils eqs. 17–18, 38, 46 corrected in docs/models-quadrics.md).
std::array<double, 4> tangent_plane(const Quadric& q, const Vec3d& p);

// The symmetric matrices: F(x) = xᵀ M3 x + (g, h, i)·x + j = [x 1] M4 [x 1]ᵀ.
Mat3 matrix3(const Quadric& q);
Mat4 matrix4(const Quadric& q);
// Inverse of matrix4 (symmetric part of m is used).
Quadric from_matrix4(const Mat4& m);

// q scaled to unit Euclidean norm, the sign chosen so that the first coefficient (order a … j)
// with |k| ≥ 10⁻³ max|k| is positive (the golden files' comparison rule). Zero stays zero.
Quadric normalized(const Quadric& q);

// Throws ModelError when a coefficient is NaN or infinite.
void check_finite(const Quadric& q);

// ---------------------------------------------------------------------------------- shapes
// (x−c)ᵀ diag(1/r²) (x−c) − 1, semi-axes r along x, y, z.
Quadric ellipsoid(const Vec3d& center, const Vec3d& semi_axes);
Quadric sphere(const Vec3d& center, double radius);

// ---------------------------------------------------------------------------- line meeting
enum class LineKind {
  two,        // two distinct real roots
  tangent,    // a double root (the line touches the surface, or passes through a cone's apex)
  one,        // A = 0, B ≠ 0: one root (a line parallel to an asymptotic direction)
  none,       // no real root
  contained,  // F ≡ 0 on the line
};
std::string_view to_string(LineKind kind);

// x(t) = origin + t·direction: F(x(t)) = A t² + B t + C with A = dᵀ M3 d, B = ∇F(o)·d, C = F(o).
// The kind is decided exactly on the float64 values of A, B, C and B² − 4AC unless
// relative_tolerance > 0: then A (and B, C when A is) counts as 0 when |A| ≤ tol·(|A| + |B| + |C|)
// and the discriminant when |B² − 4AC| ≤ tol·(B² + 4|AC|). Roots ascend; the stable formula
// q = −(B + sgn(B)√Δ)/2, t = q/A, C/q is used. Throws ModelError for a zero or non-finite
// direction or a non-finite origin.
struct LineIntersection {
  LineKind kind = LineKind::none;
  int count = 0;  // number of entries of t and points in use (0, 1 or 2)
  std::array<double, 2> t{};
  std::array<Vec3d, 2> points{};
  std::array<double, 3> quadratic{};  // A, B, C
};
LineIntersection intersect_line(const Quadric& q, const Vec3d& origin, const Vec3d& direction,
                                double relative_tolerance = 0.0);

// --------------------------------------------------------------------- rigid motions (direct)
// G(x) = F(A x + b): the substitution behind every transform below (M4 ↦ Hᵀ M4 H, H = [A b; 0 1]).
Quadric substitute(const Quadric& q, const Mat3& a, const Vec3d& b);
// The surface moved by t: F(x − t).
Quadric translate(const Quadric& q, const Vec3d& t);
// The surface rotated by the rotation matrix r about the origin: F(rᵀ x).
Quadric rotate(const Quadric& q, const Mat3& r);
// Rotation by theta in the (x_i, x_j) coordinate plane turning x_i towards x_j (i ≠ j, 0…2).
Mat3 plane_rotation(int i, int j, double theta);
// Rotation by theta (right-handed) about the unit axis (Rodrigues).
Mat3 axis_rotation(const Vec3d& axis, double theta);

// ------------------------------------------------------------------------ classification
enum class QuadricType {
  ellipsoid,
  sphere,
  hyperboloid_one_sheet,
  hyperboloid_two_sheets,
  cone,
  elliptic_paraboloid,
  hyperbolic_paraboloid,
  elliptic_cylinder,
  hyperbolic_cylinder,
  parabolic_cylinder,
  intersecting_planes,
  parallel_planes,
  single_plane,  // a plane (F linear) or a double plane (F = (plane)²)
  point,         // a single real point (imaginary cone, e.g. x² + y² + z² = 0)
  line,          // a single real line (imaginary plane pair, e.g. x² + y² = 0)
  imaginary,     // no real point (imaginary ellipsoid, cylinder or plane pair, F = const ≠ 0)
  degenerate,    // F ≡ 0
};
std::string_view to_string(QuadricType type);

// Classification from the eigenvalues of M3 and the reduced form in M3's eigenframe, which carries
// the rank and sign information of M4 (docs/models-quadrics.md §6). An eigenvalue is zero when
// |λ| ≤ tol·max|λ|; the reduced constant and linear part are zero when they are within tol of the
// terms they were computed from (so the test is invariant under scaling of F and of space).
struct Classification {
  QuadricType type = QuadricType::degenerate;
  Vec3d eigenvalues{};                   // of M3, ascending
  Mat3 axes{};                           // row k: unit eigenvector of eigenvalues[k]
  std::array<double, 4> eigenvalues4{};  // of M4, ascending
  int rank3 = 0, rank4 = 0;
};
Classification classify(const Quadric& q, double relative_tolerance = 1e-9);

// ----------------------------------------------------------------------------------- fit
// Least-squares fit of F to N ≥ 9 points: the unit coefficient vector minimising Σ F(p_n)²,
// computed on points centred at their centroid and scaled to unit RMS distance (then mapped back).
// Residuals use the normalized result (unit coefficient norm): algebraic |F(p)| and the
// first-order geometric distance |F(p)|/‖∇F(p)‖. Throws ModelError for fewer than 9 points,
// a non-finite coordinate, coincident points, or points that do not determine one quadric (they
// lie on a lower-order surface: the second-smallest eigenvalue of the scatter matrix is ≤
// 1e-12 of the largest).
// Far from the origin the ten global coefficients cannot hold a small surface precisely (j grows
// with the squared distance), so the result also carries the quadric in the fit's own frame,
// u = (x − centroid)/scale, and the residuals are evaluated there.
struct FitResult {
  Quadric quadric;  // normalized(), global coordinates
  Quadric local;    // unit norm, in u = (x − centroid)/scale
  Vec3d centroid{};
  double scale = 1;
  double algebraic_rms = 0, algebraic_max = 0;
  double geometric_rms = 0, geometric_max = 0;
  double smallest_eigenvalue_ratio = 0;         // λ1/λmax of the normalized scatter matrix
  double second_smallest_eigenvalue_ratio = 0;  // λ2/λmax: near 0 = ill-determined
};
FitResult fit(std::span<const Vec3d> points);

// Residuals of any quadric on points (the quadric is normalized() first).
struct Residuals {
  double algebraic_rms = 0, algebraic_max = 0;
  double geometric_rms = 0, geometric_max = 0;
};
Residuals residuals(const Quadric& q, std::span<const Vec3d> points);

// The quadric through exactly 9 points (the null vector of the 9×10 monomial matrix, by
// elimination with complete pivoting on centred and scaled points): the closed form of
// Breuils eq. 70. Throws ModelError for a non-finite coordinate or when the points do not
// determine a unique quadric (a pivot ≤ 1e-10 of the largest: points on a lower-order surface).
Quadric through_nine_points(std::span<const Vec3d, 9> points);

}  // namespace pgamesh::quadric
