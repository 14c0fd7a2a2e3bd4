// The fused fast path for binary STL: mass properties accumulated straight from the mapped
// float32 records on every core, without building a Mesh (docs/formats.md, Speed: parse and
// accumulate in one streaming pass). No topology: an STL has no shared vertices until they are
// welded, so closedness needs the weld of mesh/topology.
#pragma once

#include <string>

#include "io/stl_binary.hpp"
#include "pgamesh/core/bounding_box.hpp"
#include "pgamesh/mesh/mass/mass_properties.hpp"

namespace pgamesh {

// Records sampled to place the reference point and judge float32 precision: the bounding box of
// at most this many evenly spaced triangles (deterministic, and near the mesh whatever its size).
inline constexpr std::uint64_t stl_reference_samples = 4096;

// Mass properties of the triangles of a binary STL view (or of another array of float32 triangle
// records, BinaryStlView::layout: a GLB's packed positions), accumulated about the centre of a
// sample of its records. Fills faces = triangles = view.count and vertices = 3 × count (STL
// vertices are not shared). Adds the float32 far-from-origin warning when it applies. Throws
// InputError naming `name` and the byte offset of the first non-finite coordinate when there is
// one. With `release_records` — only for records in a read-only file mapping — the pages of the
// records are given back to the kernel as they are summed (madvise MADV_DONTNEED; they stay
// readable); a view that reads its file (BinaryStlView::file) touches no mapped page and releases
// none.
MassProperties binary_stl_mass_properties(const BinaryStlView& view, const std::string& name,
                                          const MassOptions& options = {},
                                          bool release_records = false);

}  // namespace pgamesh
