// The full 16-component multivector of PGA R(3,0,1), coefficients in the docs/conventions.md §1
// basis order 1, e0, e1, e2, e3, e01, e02, e03, e12, e31, e23, e021, e013, e032, e123, e0123. Every
// product is read from one blade table generated at compile time from bitmask blades (e0 = bit 0,
// e1 = bit 1, e2 = bit 2, e3 = bit 3) and the project's blade signs (e31 = −e13, e021 = −e012,
// e032 = −e023), so the hand-specialised grade products (products.hpp, motor.hpp) can be checked
// against it.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <utility>

namespace pgamesh::pga3 {

/// Indices of the blades in Multivector::c (docs/conventions.md §1 order).
enum Blade : int {
  kS = 0,
  kE0,
  kE1,
  kE2,
  kE3,
  kE01,
  kE02,
  kE03,
  kE12,
  kE31,
  kE23,
  kE021,
  kE013,
  kE032,
  kE123,
  kE0123
};

/// The blade names in storage order, as the golden files spell them.
inline constexpr std::array<const char*, 16> kBladeNames = {
    "1",   "e0",  "e1",  "e2",   "e3",   "e01",  "e02",  "e03",
    "e12", "e31", "e23", "e021", "e013", "e032", "e123", "e0123"};

namespace detail {

/// Bitmask of each project blade and its sign relative to the ascending-index blade.
inline constexpr std::array<std::uint8_t, 16> kBladeMask = {
    0b0000, 0b0001, 0b0010, 0b0100, 0b1000, 0b0011, 0b0101, 0b1001,
    0b0110, 0b1010, 0b1100, 0b0111, 0b1011, 0b1101, 0b1110, 0b1111};
inline constexpr std::array<std::int8_t, 16> kBladeSign = {1, 1,  1, 1,  1, 1,  1, 1,
                                                           1, -1, 1, -1, 1, -1, 1, 1};

constexpr int popcount4(unsigned m) {
  return int(m & 1) + int(m >> 1 & 1) + int(m >> 2 & 1) + int(m >> 3 & 1);
}

/// Sign of reordering the product of ascending blades a b into ascending order.
constexpr int reorder_sign(unsigned a, unsigned b) {
  int swaps = 0;
  for (a >>= 1; a != 0; a >>= 1) swaps += popcount4(a & b);
  return swaps % 2 == 0 ? 1 : -1;
}

constexpr int index_of_mask(unsigned m) {
  for (int i = 0; i < 16; ++i)
    if (kBladeMask[i] == m) return i;
  return -1;
}

/// One entry of the geometric product table: blade_i blade_j = sign · blade_index (sign 0 when
/// e0 appears twice, e0² = 0).
struct ProductEntry {
  std::int8_t sign;
  std::uint8_t index;
};

constexpr std::array<std::array<ProductEntry, 16>, 16> make_product_table() {
  std::array<std::array<ProductEntry, 16>, 16> t{};
  for (int i = 0; i < 16; ++i)
    for (int j = 0; j < 16; ++j) {
      const unsigned a = kBladeMask[i], b = kBladeMask[j];
      const int k = index_of_mask(a ^ b);
      // e1² = e2² = e3² = 1, e0² = 0 (bit 0).
      const int metric = (a & b & 1u) ? 0 : 1;
      const int s = metric * reorder_sign(a, b) * kBladeSign[i] * kBladeSign[j] * kBladeSign[k];
      t[i][j] = {std::int8_t(s), std::uint8_t(k)};
    }
  return t;
}
inline constexpr auto kProductTable = make_product_table();

/// Grade of each blade.
constexpr int blade_grade(int i) {
  return popcount4(kBladeMask[i]);
}

/// Index and sign of the dual (e_J e_J* = e0123) and undual (e_J^(−*) e_J = e0123) of each blade
/// (paper text above eq. 3.2, docs/conventions.md §3).
constexpr std::array<ProductEntry, 16> make_dual_table(bool undual) {
  std::array<ProductEntry, 16> t{};
  for (int i = 0; i < 16; ++i) {
    const int k = index_of_mask(15u ^ kBladeMask[i]);
    const ProductEntry p = undual ? kProductTable[k][i] : kProductTable[i][k];
    t[i] = {p.sign, std::uint8_t(k)};  // p.index == kE0123, p.sign = ±1
  }
  return t;
}
inline constexpr auto kDualTable = make_dual_table(false);
inline constexpr auto kUndualTable = make_dual_table(true);

}  // namespace detail

/// A general element of R(3,0,1): 16 coefficients in the docs/conventions.md §1 basis order.
template <class T>
struct Multivector {
  using scalar_type = T;
  std::array<T, 16> c{};

  constexpr T& operator[](int i) { return c[i]; }
  constexpr const T& operator[](int i) const { return c[i]; }

  friend constexpr Multivector operator+(Multivector a, const Multivector& b) {
    for (int i = 0; i < 16; ++i) a.c[i] += b.c[i];
    return a;
  }
  friend constexpr Multivector operator-(Multivector a, const Multivector& b) {
    for (int i = 0; i < 16; ++i) a.c[i] -= b.c[i];
    return a;
  }
  friend constexpr Multivector operator-(Multivector a) {
    for (T& x : a.c) x = -x;
    return a;
  }
  friend constexpr Multivector operator*(T s, Multivector a) {
    for (T& x : a.c) x *= s;
    return a;
  }
  friend constexpr Multivector operator*(Multivector a, T s) { return s * a; }
  friend constexpr Multivector operator/(Multivector a, T s) {
    for (T& x : a.c) x /= s;
    return a;
  }
  friend constexpr bool operator==(const Multivector&, const Multivector&) = default;
};

/// The scalar s as a multivector.
template <class T>
constexpr Multivector<T> scalar(T s) {
  Multivector<T> m;
  m.c[kS] = s;
  return m;
}
/// The basis blade with index i (Blade).
template <class T>
constexpr Multivector<T> basis_blade(int i) {
  Multivector<T> m;
  m.c[i] = T(1);
  return m;
}

namespace detail {
/// Σ a_i b_j (blade_i blade_j), keeping the pairs for which keep(grade i, grade j, grade k).
template <class T, class Keep>
constexpr Multivector<T> product(const Multivector<T>& a, const Multivector<T>& b, Keep keep) {
  Multivector<T> r;
  for (int i = 0; i < 16; ++i) {
    if (a.c[i] == T(0)) continue;
    for (int j = 0; j < 16; ++j) {
      const ProductEntry e = kProductTable[i][j];
      if (e.sign == 0 || !keep(blade_grade(i), blade_grade(j), blade_grade(e.index))) continue;
      r.c[e.index] += T(e.sign) * a.c[i] * b.c[j];
    }
  }
  return r;
}
}  // namespace detail

/// The geometric product A B (paper §2), from the blade table.
template <class T>
constexpr Multivector<T> geometric_product(const Multivector<T>& a, const Multivector<T>& b) {
  return detail::product(a, b, [](int, int, int) { return true; });
}
/// The outer product A ∧ B (the meet, paper eq. 2.1): the grade r + s part of A_r B_s.
template <class T>
constexpr Multivector<T> outer_product(const Multivector<T>& a, const Multivector<T>& b) {
  return detail::product(a, b, [](int r, int s, int k) { return k == r + s; });
}
/// A ∧ B, the meet (alias of outer_product).
template <class T>
constexpr Multivector<T> meet(const Multivector<T>& a, const Multivector<T>& b) {
  return outer_product(a, b);
}
/// The symmetric ("fat dot") inner product ⟨A_r B_s⟩_|r−s| (docs/conventions.md §4, = ganja.js
/// `|`).
template <class T>
constexpr Multivector<T> inner_product(const Multivector<T>& a, const Multivector<T>& b) {
  return detail::product(a, b, [](int r, int s, int k) { return k == (r > s ? r - s : s - r); });
}
/// The left contraction A ⌋ B = Σ ⟨A_r B_s⟩_(s−r) for s ≥ r.
template <class T>
constexpr Multivector<T> left_contraction(const Multivector<T>& a, const Multivector<T>& b) {
  return detail::product(a, b, [](int r, int s, int k) { return s >= r && k == s - r; });
}
/// The right contraction A ⌊ B = Σ ⟨A_r B_s⟩_(r−s) for r ≥ s.
template <class T>
constexpr Multivector<T> right_contraction(const Multivector<T>& a, const Multivector<T>& b) {
  return detail::product(a, b, [](int r, int s, int k) { return r >= s && k == r - s; });
}
/// The scalar product ⟨A B⟩_0.
template <class T>
constexpr T scalar_product(const Multivector<T>& a, const Multivector<T>& b) {
  return detail::product(a, b, [](int, int, int k) { return k == 0; }).c[kS];
}
/// The commutator product A × B = ½ (A B − B A).
template <class T>
constexpr Multivector<T> commutator(const Multivector<T>& a, const Multivector<T>& b) {
  return T(0.5) * (geometric_product(a, b) - geometric_product(b, a));
}

/// The Hodge dual A* with e_J e_J* = e0123 (paper text above eq. 3.2, table in docs/conventions.md
/// §3).
template <class T>
constexpr Multivector<T> dual(const Multivector<T>& a) {
  Multivector<T> r;
  for (int i = 0; i < 16; ++i)
    r.c[detail::kDualTable[i].index] = T(detail::kDualTable[i].sign) * a.c[i];
  return r;
}
/// The undual A^(−*) with A^(−*) A = e0123 on blades, so (A*)^(−*) = A (docs/conventions.md §3).
template <class T>
constexpr Multivector<T> undual(const Multivector<T>& a) {
  Multivector<T> r;
  for (int i = 0; i < 16; ++i)
    r.c[detail::kUndualTable[i].index] = T(detail::kUndualTable[i].sign) * a.c[i];
  return r;
}
/// The join (regressive product) A ∨ B = (A* ∧ B*)^(−*) (paper eq. 2.2).
template <class T>
constexpr Multivector<T> join(const Multivector<T>& a, const Multivector<T>& b) {
  return undual(outer_product(dual(a), dual(b)));
}

namespace detail {
template <class T, class Sign>
constexpr Multivector<T> by_grade(Multivector<T> a, Sign sign) {
  for (int i = 0; i < 16; ++i)
    if (sign(blade_grade(i)) < 0) a.c[i] = -a.c[i];
  return a;
}
}  // namespace detail

/// The reverse Ã: grade k is multiplied by (−1)^(k(k−1)/2).
template <class T>
constexpr Multivector<T> reverse(const Multivector<T>& a) {
  return detail::by_grade(a, [](int k) { return (k * (k - 1) / 2) % 2 == 0 ? 1 : -1; });
}
/// The grade involution Â: grade k is multiplied by (−1)^k.
template <class T>
constexpr Multivector<T> grade_involution(const Multivector<T>& a) {
  return detail::by_grade(a, [](int k) { return k % 2 == 0 ? 1 : -1; });
}
/// The Clifford conjugate (reverse of the grade involution): (−1)^(k(k+1)/2).
template <class T>
constexpr Multivector<T> clifford_conjugate(const Multivector<T>& a) {
  return detail::by_grade(a, [](int k) { return (k * (k + 1) / 2) % 2 == 0 ? 1 : -1; });
}
/// The grade-k part ⟨A⟩_k.
template <class T>
constexpr Multivector<T> grade(const Multivector<T>& a, int k) {
  Multivector<T> r;
  for (int i = 0; i < 16; ++i)
    if (detail::blade_grade(i) == k) r.c[i] = a.c[i];
  return r;
}

/// The Euclidean split A = A_E + e0 A_I (paper eq. 3.1): both parts free of e0.
template <class T>
struct EuclideanSplit {
  Multivector<T> euclidean, ideal;
};
/// A_E and A_I with A = A_E + e0 A_I (paper eq. 3.1).
template <class T>
constexpr EuclideanSplit<T> euclidean_split(const Multivector<T>& a) {
  EuclideanSplit<T> r;
  for (int i = 0; i < 16; ++i) {
    if (detail::kBladeMask[i] & 1u) {
      // blade_i = e0 · (±blade_k): the sign is that of the table entry e0 blade_k.
      const int k = detail::index_of_mask(detail::kBladeMask[i] ^ 1u);
      r.ideal.c[k] = T(detail::kProductTable[kE0][k].sign) * a.c[i];
    } else {
      r.euclidean.c[i] = a.c[i];
    }
  }
  return r;
}
/// ‖A‖: root of the sum of squares of the coefficients without e0 (docs/conventions.md §6).
template <class T>
T norm(const Multivector<T>& a) {
  T s{};
  for (int i = 0; i < 16; ++i)
    if (!(detail::kBladeMask[i] & 1u)) s += a.c[i] * a.c[i];
  return std::sqrt(s);
}
/// ‖A‖∞ = ‖A ∨ o‖ = ‖A*‖: root of the sum of squares of the coefficients with e0
/// (docs/conventions.md §6).
template <class T>
T ideal_norm(const Multivector<T>& a) {
  T s{};
  for (int i = 0; i < 16; ++i)
    if (detail::kBladeMask[i] & 1u) s += a.c[i] * a.c[i];
  return std::sqrt(s);
}

/// A⁻¹ with A A⁻¹ = 1 when it exists: solves the 16 × 16 linear system of left multiplication by
/// A (Gaussian elimination with partial pivoting). Empty when A is not invertible (for example
/// any element without Euclidean part, such as e0 or e01, or 1 + e1), judged by a pivot below
/// `rel_eps` × the largest coefficient of the multiplication matrix.
template <class T>
std::optional<Multivector<T>> inverse(const Multivector<T>& a,
                                      T rel_eps = T(1e3) * std::numeric_limits<T>::epsilon()) {
  // Column j of L is A e_j.
  std::array<std::array<T, 17>, 16> m{};
  T scale{};
  for (int j = 0; j < 16; ++j) {
    const Multivector<T> col = geometric_product(a, basis_blade<T>(j));
    for (int i = 0; i < 16; ++i) {
      m[i][j] = col.c[i];
      scale = std::max(scale, std::abs(col.c[i]));
    }
  }
  if (scale == T(0)) return std::nullopt;
  m[kS][16] = T(1);
  for (int col = 0; col < 16; ++col) {
    int piv = col;
    for (int r = col + 1; r < 16; ++r)
      if (std::abs(m[r][col]) > std::abs(m[piv][col])) piv = r;
    if (std::abs(m[piv][col]) <= rel_eps * scale) return std::nullopt;
    std::swap(m[piv], m[col]);
    for (int r = 0; r < 16; ++r) {
      if (r == col || m[r][col] == T(0)) continue;
      const T f = m[r][col] / m[col][col];
      for (int k = col; k < 17; ++k) m[r][k] -= f * m[col][k];
    }
  }
  Multivector<T> x;
  for (int i = 0; i < 16; ++i) x.c[i] = m[i][16] / m[i][i];
  return x;
}

/// A * B: geometric product.
template <class T>
constexpr Multivector<T> operator*(const Multivector<T>& a, const Multivector<T>& b) {
  return geometric_product(a, b);
}
/// A ^ B: outer product (meet).
template <class T>
constexpr Multivector<T> operator^(const Multivector<T>& a, const Multivector<T>& b) {
  return outer_product(a, b);
}
/// A & B: join (regressive product).
template <class T>
constexpr Multivector<T> operator&(const Multivector<T>& a, const Multivector<T>& b) {
  return join(a, b);
}
/// A | B: symmetric inner product.
template <class T>
constexpr Multivector<T> operator|(const Multivector<T>& a, const Multivector<T>& b) {
  return inner_product(a, b);
}
/// ~A: reverse.
template <class T>
constexpr Multivector<T> operator~(const Multivector<T>& a) {
  return reverse(a);
}
/// !A: dual.
template <class T>
constexpr Multivector<T> operator!(const Multivector<T>& a) {
  return dual(a);
}

}  // namespace pgamesh::pga3
