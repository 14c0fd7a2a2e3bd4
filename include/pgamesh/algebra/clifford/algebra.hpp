// A Clifford algebra of any signature R(p,q,r) or of any symmetric bilinear form on n ≤ 24
// generators (null bases such as CGA's e_o, e_∞ or DPGA's w_i, w_i* included).
//
// The user's basis u_0 … u_(n−1) may be non-orthogonal. Blades of the user basis are OUTER
// products u_J = u_j1 ∧ … ∧ u_jk (as the golden files name them, e.g. `eo^einf`). Metric products
// are computed in an orthogonal basis f_0 … f_(n−1) (f_k² = λ_k) reached by a change of basis
// u_i = Σ_k A_ik f_k: a hand-built exact map for isolated null pairs (docs/conventions.md §15:
// e_∞ = e₊ + e₋, e_o = ½(e₋ − e₊), scaled to the pair's u_a·u_b), otherwise the eigen-decomposition
// of the Gram matrix. Its outermorphism carries blades to blades of the same grade and is an
// algebra isomorphism, so products computed on f and mapped back are the products on u. Outer and
// regressive products, duals and involutions do not depend on the metric and run on u directly.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pgamesh/algebra/clifford/multivector.hpp"

namespace pgamesh::clifford {

// A vector of the orthogonal basis, as (generator index, coefficient) pairs.
using SparseVector = std::vector<std::pair<int, double>>;

class Algebra {
 public:
  static constexpr int max_generators = 24;

  // R(p,q,r): generators ordered null, positive, negative. Names follow ganja.js: e0 for the null
  // generator when r == 1 (then e1 … e(p+q)), otherwise e1, e2, …; past e9 the names continue
  // with letters eA, eB, … so blade names stay one character per factor (e19AF).
  static Algebra signature(int p, int q, int r);

  // Orthogonal generators with squares `squares` (any real values) and the given names.
  static Algebra diagonal(std::vector<double> squares, std::vector<std::string> names);

  // Any symmetric bilinear form: gram[i][j] = u_i · u_j. Throws std::invalid_argument when the
  // matrix is not square, not symmetric, too large, or the names do not fit.
  static Algebra bilinear_form(std::vector<std::vector<double>> gram,
                               std::vector<std::string> names);

  int dimension() const { return n_; }
  BladeMask pseudoscalar_mask() const { return full_mask_; }
  const std::vector<std::string>& generator_names() const { return names_; }
  double inner(int i, int j) const { return gram_[static_cast<std::size_t>(i * n_ + j)]; }
  bool is_diagonal() const { return diagonal_; }
  // Squares λ_k of the orthogonal basis f_k the metric products run in.
  const std::vector<double>& orthogonal_squares() const { return squares_; }
  // Images of the user generators: u_i = Σ_k A_ik f_k (identity for a diagonal form).
  const std::vector<SparseVector>& generator_images() const { return to_orthogonal_; }

  // Gives blade names of a custom basis (e.g. PGA3's e31, e021): each name lists factors by their
  // generator suffix in product order; its sign relative to the ascending blade is worked out.
  // Throws std::invalid_argument when a name is not a blade of this algebra.
  void set_blade_names(const std::vector<std::string>& names);
  // Adds another name for a generator (e.g. `einf` for `ei`) accepted by parse_blade.
  void add_generator_alias(const std::string& alias, int generator);

  // Canonical name of a basis blade and the sign s with  named blade = s · e_mask:
  // the custom name when one was given; else concatenated suffixes (e12, e0123) when the basis
  // is orthogonal and every generator is named e<one character>; else outer products joined with
  // '^' in basis order (eo^e1^ei); "1" for the scalar.
  std::pair<std::string, double> blade_name(BladeMask mask) const;

  // Parses a blade name: custom names, "1", '^'-joined generator names, or e<suffixes> in any
  // order (e21 = −e12) when concatenated names apply. Returns nullopt when it is not a blade.
  std::optional<std::pair<BladeMask, double>> parse_blade(std::string_view name) const;

  // Printing order: the custom basis order when blade names were given, else by grade, then
  // lexicographically by factor indices (e12, e13, e14, e23, …).
  bool display_before(BladeMask a, BladeMask b) const;

  // Named coefficients of A in ascending blade order (name, coefficient of the named blade).
  std::vector<std::pair<std::string, double>> named_coefficients(const Multivector& a) const;

  // Change of basis (outermorphism of u_i ↦ Σ_k A_ik f_k) and its inverse.
  Multivector to_orthogonal(const Multivector& a) const;
  Multivector from_orthogonal(const Multivector& a) const;

  // Algebras with at most this many generators keep their product table and the change-of-basis
  // images of every basis blade, so their products run on stack arrays without allocating.
  static constexpr int small_generators = 6;

  // The table of product_factor for n ≤ small_generators, indexed (a << n) | b (empty otherwise).
  std::span<const double> product_table() const { return table_; }

  // Image of the basis blade `mask` under to_orthogonal / from_orthogonal as sorted terms;
  // cached for non-diagonal algebras with n ≤ small_generators (empty spans otherwise).
  std::span<const Term> orthogonal_image(BladeMask mask) const {
    return blade_image(to_orthogonal_images_, mask);
  }
  std::span<const Term> user_image(BladeMask mask) const {
    return blade_image(from_orthogonal_images_, mask);
  }

  // Product weight of the repeated factors `common` in the orthogonal basis: Π_{k∈common} λ_k.
  double metric_weight(BladeMask common) const;

  // sign(e_a e_b) · λ(a∧b common factors) in the orthogonal basis: the coefficient of e_(a^b)
  // in e_a e_b (a cached table for n ≤ 6).
  double product_factor(BladeMask a, BladeMask b) const {
    if (!table_.empty()) return table_[(static_cast<std::size_t>(a) << n_) | b];
    return reorder_sign(a, b) * metric_weight(a & b);
  }

 private:
  Algebra() = default;
  void finish();
  static std::span<const Term> blade_image(const std::vector<Multivector>& images, BladeMask mask) {
    if (images.empty()) return {};
    return images[mask].terms;
  }
  std::string concatenated_or_joined(BladeMask mask) const;

  int n_ = 0;
  BladeMask full_mask_ = 0;
  std::vector<std::string> names_;
  std::vector<double> gram_;
  std::vector<double> squares_;
  bool diagonal_ = true;
  bool unit_metric_ = true;  // every λ_k ∈ {−1, 0, 1}
  BladeMask negative_mask_ = 0, null_mask_ = 0;
  std::vector<SparseVector> to_orthogonal_, from_orthogonal_;
  std::vector<double> table_;
  std::vector<Multivector> to_orthogonal_images_, from_orthogonal_images_;  // by blade mask
  bool concatenated_names_ = false;
  std::vector<std::string> custom_names_;  // indexed by mask (empty when none)
  std::vector<double> custom_signs_;
  std::vector<int> custom_rank_;
  std::vector<std::pair<std::string, int>> aliases_;
};

// Presets (names as in `pgamesh calc --algebra NAME`): pga2, pga3, pgaN (N = 1…6), cga3 (eo, e1,
// e2, e3, ei; eo·ei = −1, alias einf), dpga (w0…w3, w0s…w3s; w_i·w_j* = ½δ_ij), dcga (eo1, e1, e2,
// e3, ei1, eo2, e4, e5, e6, ei2), qcga (e1, e2, e3, eo1…eo6, ei1…ei6; eo_i·ei_j = −δ_ij), and
// "p,q,r". Returns nullopt for an unknown name.
std::optional<Algebra> make_algebra(std::string_view name);

}  // namespace pgamesh::clifford
