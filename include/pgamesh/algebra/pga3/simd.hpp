// Internal: four-lane vectors of float or double for the straight-line motor kernels (motor.hpp),
// as GCC/clang vector extensions — plain C++ operators that the compiler lowers to whatever the
// target has (SSE2 on every x86-64: one register for four floats, two for four doubles; NEON on
// aarch64; scalar code elsewhere). Nothing here depends on the instruction set, and no fused
// multiply-add is formed unless the build asks for contraction (docs/pga3.md "Speed"). Only float
// and double take these paths; every other scalar (mpq_class in the exact tests) uses the generic
// formulas, which give the same values lane by lane.
#pragma once

#include <cstring>
#include <type_traits>

#if defined(__GNUC__) || defined(__clang__)
#define PGAMESH_PGA3_SIMD 1
// Lanes (i, j, k, l) of a, and of the concatenation a, b (4 … 7 are b's lanes). Macros, not
// functions: __builtin_shufflevector needs constant lane numbers, and a function passing four
// doubles by value would have an ABI that depends on AVX. PGAMESH_LANES permutes a's bits in
// ShuffleView (below): the same lanes moved, whatever the view.
#define PGAMESH_LANES(a, ...)                                                 \
  reinterpret_cast<std::remove_cvref_t<decltype(a)>>(__builtin_shufflevector( \
      reinterpret_cast<::pgamesh::pga3::detail::ShuffleView<decltype(a)>>(a), \
      reinterpret_cast<::pgamesh::pga3::detail::ShuffleView<decltype(a)>>(a), __VA_ARGS__))
#define PGAMESH_LANES2(a, b, ...) __builtin_shufflevector(a, b, __VA_ARGS__)
#endif

namespace pgamesh::pga3::detail {

#ifdef PGAMESH_PGA3_SIMD
template <class T>
using V4 [[gnu::vector_size(4 * sizeof(T))]] = T;

/// The vector type PGAMESH_LANES permutes V's bits as. Four floats without AVX: four 32-bit
/// integers, so that x86-64 permutes one register into another with one pshufd. SSE's shufps
/// overwrites its source, and GCC then copies every input it still needs first: 12 to 24 movaps
/// in each kernel of motor.hpp and join.hpp, a fifth to a third of their instructions. With AVX
/// (three-operand vpermilps) and for double, the vector itself.
template <class V>
struct ShuffleViewOf {
  using type = V;
};
#ifndef __AVX__
template <>
struct ShuffleViewOf<V4<float>> {
  using type [[gnu::vector_size(16)]] = int;
};
#endif
template <class V>
using ShuffleView = typename ShuffleViewOf<std::remove_cvref_t<V>>::type;

/// Whether T takes the vector kernels: float always (four floats fill one SSE2 or NEON
/// register); double only where four doubles fill one register (AVX) — split over two SSE2
/// registers, the lane shuffles cost more than the generic code (docs/pga3.md "Speed").
template <class T>
inline constexpr bool kHasSimd = std::is_same_v<T, float>
#ifdef __AVX__
                                 || std::is_same_v<T, double>
#endif
    ;
/// Whether lane-wise arithmetic (no shuffles) on V4<T> pays: float and double (two SSE2
/// registers for four doubles cost nothing extra without shuffles).
template <class T>
inline constexpr bool kHasSimdArithmetic = std::is_same_v<T, float> || std::is_same_v<T, double>;

/// Coefficients k … k + 3 of an element (Plane, Point, Motor: contiguous T) as one vector.
template <class T, class Element>
[[gnu::always_inline]] inline void load_lanes(const Element& x, int k, V4<T>& v) {
  static_assert(sizeof(Element) % sizeof(V4<T>) == 0);
  std::memcpy(&v, reinterpret_cast<const char*>(&x) + k * sizeof(T), sizeof v);
}
/// The element whose coefficients k … k + 3 are v's lanes.
template <class T, class Element>
[[gnu::always_inline]] inline void store_lanes(Element& x, int k, const V4<T>& v) {
  static_assert(sizeof(Element) % sizeof(V4<T>) == 0);
  std::memcpy(reinterpret_cast<char*>(&x) + k * sizeof(T), &v, sizeof v);
}
#else
template <class T>
inline constexpr bool kHasSimd = false;
template <class T>
inline constexpr bool kHasSimdArithmetic = false;
#endif

}  // namespace pgamesh::pga3::detail
