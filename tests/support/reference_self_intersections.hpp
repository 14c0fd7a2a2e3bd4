// The self-intersecting face pairs of a mesh computed the slow, obvious way from their definition
// (docs/topology.md, "Self-intersections"), in exact rational arithmetic (GMP mpq_class) on the
// double coordinates: every pair of fan triangles of different faces, the first clipped by the
// second's plane and its three edge half-spaces (Sutherland–Hodgman), and the pair intersecting
// when a point of the clipped polygon lies outside the hull of the welded vertices the two share.
// It shares nothing with the library's pass but the weld (weld_map, tested on its own). Only
// available when GMP's C++ interface was found (PGAMESH_HAVE_GMP).
#pragma once

#ifdef PGAMESH_HAVE_GMP

#include <cstdint>
#include <utility>
#include <vector>

#include "pgamesh/core/mesh.hpp"

namespace pgamesh::test {

// The pairs (f, g), f < g, ascending.
std::vector<std::pair<std::uint32_t, std::uint32_t>> reference_self_intersections(const Mesh& mesh);

}  // namespace pgamesh::test

#endif
