// k-complexes in PGA R(d,0,1) measured from their oriented boundary (paper §4(c), §5):
// sum the boundary carriers first, then take norms. With B = Σ_∂K S(σk−1):
//   magnitude of K          ‖B‖∞ / k!                                   (Thm 4.2)
//   magnitude of the gap    ‖B‖ / (k − 1)!                              (Cor. 4.1)
//   signed d-volume (k = d) (o ∨ B) / d!                                (Table 1, o on the left)
//   centre of mass (k = d)  Σ (v0 + … + v_(d−1) + o)(o ∨ S) / (d + 1)!   (eq. 5.3, with the sign
//                                                                    of docs/conventions.md §9)
// A boundary is a list of (k−1)-simplices, each k vertex indices, oriented so that the complex's
// k-simplices induce them (outward for a closed d-volume). Coordinates are taken relative to a
// reference point o near the complex before any carrier is formed (docs/conventions.md §13).
#pragma once

#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "pgamesh/algebra/pgad.hpp"
#include "pgamesh/geometry/simplex.hpp"

namespace pgamesh::geometry {

// A boundary chain: vertices and facets of `facet_size` = k vertices each (indices flattened).
template <int D>
struct BoundaryChain {
  std::span<const pgad::Vec<D>> vertices;
  std::span<const int> facets;  // facets.size() is a multiple of facet_size
  int facet_size = D;           // k; the complex has dimension k, its boundary k − 1
};

// Sums over a boundary, about the reference point `origin`.
template <int D>
struct BoundarySums {
  int k = D;                         // dimension of the complex
  pgad::Vec<D> origin{};             // the reference point o
  pgad::Multivector<D> carrier_sum;  // B = Σ S(σk−1), coordinates relative to o
  pgad::Multivector<D> com_sum;  // Σ (v0 + … + v_(k−1) + o)(o ∨ S(σk−1)), relative to o
};

namespace detail {
template <int D>
pgad::Vec<D> relative(const pgad::Vec<D>& v, const pgad::Vec<D>& o) {
  pgad::Vec<D> r{};
  for (int i = 0; i < D; ++i)
    r[static_cast<std::size_t>(i)] =
        v[static_cast<std::size_t>(i)] - o[static_cast<std::size_t>(i)];
  return r;
}
}  // namespace detail

// The boundary sums of a chain about `origin`. Throws std::invalid_argument for a facet size out
// of 1…d, a ragged index list or an index out of range.
template <int D>
BoundarySums<D> boundary_sums(const BoundaryChain<D>& chain, const pgad::Vec<D>& origin) {
  const int k = chain.facet_size;
  if (k < 1 || k > D) throw std::invalid_argument("boundary_sums: facet size must be 1…d");
  if (chain.facets.size() % static_cast<std::size_t>(k) != 0)
    throw std::invalid_argument("boundary_sums: index count is not a multiple of the facet size");
  BoundarySums<D> s{};
  s.k = k;
  s.origin = origin;
  const pgad::Multivector<D> o = pgad::origin<D>();
  std::vector<pgad::Vec<D>> facet(static_cast<std::size_t>(k));
  for (std::size_t f = 0; f < chain.facets.size(); f += static_cast<std::size_t>(k)) {
    pgad::Multivector<D> points = o;  // v0 + … + v_(k−1) + o as a sum of points
    for (int i = 0; i < k; ++i) {
      const int index = chain.facets[f + static_cast<std::size_t>(i)];
      if (index < 0 || static_cast<std::size_t>(index) >= chain.vertices.size())
        throw std::invalid_argument("boundary_sums: vertex index " + std::to_string(index) +
                                    " out of range");
      facet[static_cast<std::size_t>(i)] =
          detail::relative<D>(chain.vertices[static_cast<std::size_t>(index)], origin);
      points += pgad::point<D>(facet[static_cast<std::size_t>(i)]);
    }
    const pgad::Multivector<D> carrier_k = carrier<D>(facet);
    s.carrier_sum += carrier_k;
    if (k == D) s.com_sum += pgad::join(o, carrier_k).c[0] * points;
  }
  return s;
}

// Magnitude of the complex from its boundary: ‖B‖∞ / k! (paper Thm 4.2).
template <int D>
double complex_magnitude(const BoundarySums<D>& s) {
  return pgad::ideal_norm(s.carrier_sum) / factorial(s.k);
}

// Magnitude of the gap of an open complex: ‖B‖ / (k − 1)! (paper Cor. 4.1); 0 when closed. It
// equals the missing (k−1)-magnitude only when the missing facets share one carrier.
template <int D>
double gap_magnitude(const BoundarySums<D>& s) {
  return pgad::norm(s.carrier_sum) / factorial(s.k - 1);
}

// Signed d-volume of a d-complex: (o ∨ B) / d!, positive for an outward boundary.
template <int D>
double signed_volume(const BoundarySums<D>& s) {
  if (s.k != D) throw std::invalid_argument("signed_volume: needs a d-complex");
  return pgad::join(pgad::origin<D>(), s.carrier_sum).c[0] / factorial(D);
}

// Centre of mass as a homogeneous point with weight = signed volume (paper eq. 5.3 with o on the
// left, docs/conventions.md §8), in coordinates relative to the reference point.
template <int D>
pgad::Multivector<D> center_of_mass_point(const BoundarySums<D>& s) {
  if (s.k != D) throw std::invalid_argument("center_of_mass: needs a d-complex");
  return (1.0 / factorial(D + 1)) * s.com_sum;
}

// Euclidean centre of mass in absolute coordinates (reference point added back).
template <int D>
pgad::Vec<D> center_of_mass(const BoundarySums<D>& s) {
  pgad::Vec<D> c = pgad::position<D>(center_of_mass_point(s));
  for (int i = 0; i < D; ++i)
    c[static_cast<std::size_t>(i)] += s.origin[static_cast<std::size_t>(i)];
  return c;
}

// Magnitude of a complex given by its k-simplices (the left side of Thm 4.2): Σ ‖S(σk)‖ / k!.
template <int D>
double magnitude_of_simplices(std::span<const pgad::Vec<D>> vertices,
                              std::span<const int> simplices, int simplex_size) {
  if (simplex_size < 1 || simplices.size() % static_cast<std::size_t>(simplex_size) != 0)
    throw std::invalid_argument("magnitude_of_simplices: bad simplex size");
  double total = 0;
  std::vector<pgad::Vec<D>> s(static_cast<std::size_t>(simplex_size));
  for (std::size_t f = 0; f < simplices.size(); f += static_cast<std::size_t>(simplex_size)) {
    for (int i = 0; i < simplex_size; ++i) {
      const int index = simplices[f + static_cast<std::size_t>(i)];
      if (index < 0 || static_cast<std::size_t>(index) >= vertices.size())
        throw std::invalid_argument("magnitude_of_simplices: vertex index out of range");
      s[static_cast<std::size_t>(i)] = vertices[static_cast<std::size_t>(index)];
    }
    total += magnitude<D>(s);
  }
  return total;
}

}  // namespace pgamesh::geometry
