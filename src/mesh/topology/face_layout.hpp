// Internal: how the topology pass (welded_topology.cpp) walks the faces of a welded mesh. Every
// corner starts one half-edge, from its welded vertex to the next corner's of the same face, and
// the half-edge is named by its corner (edges.hpp). Two layouts give the pass the same questions
// to ask of a face list: triangles, three corners per face, where a half-edge's face and successor
// are arithmetic (h = 3 f + k), and polygons of any size in Mesh's CSR (face_offsets), where they
// are looked up.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace pgamesh::detail {

// Whether the welded corners [begin, end) of a face reach fewer than three distinct vertices: the
// face is collapsed, has no edges and belongs to no component (edges.hpp).
inline bool collapsed_face(const std::uint32_t* corner, std::uint32_t begin, std::uint32_t end) {
  if (end - begin < 3) return true;
  const std::uint32_t a = corner[begin];
  std::uint32_t i = begin + 1;
  while (i < end && corner[i] == a) ++i;
  if (i == end) return true;
  const std::uint32_t b = corner[i];
  for (++i; i < end; ++i)
    if (corner[i] != a && corner[i] != b) return false;
  return true;
}

// Faces of three corners each: half-edge h = 3 f + k runs from corner h to 3 f + (k + 1) % 3.
struct TriangleLayout {
  const std::uint32_t* corner;  // welded vertex of each corner
  std::size_t faces;

  std::size_t face_count() const { return faces; }
  static std::uint32_t face_of(std::uint32_t h) { return h / 3; }
  std::uint32_t tail(std::uint32_t h) const { return corner[h]; }
  std::uint32_t head(std::uint32_t h) const { return corner[h % 3 == 2 ? h - 2 : h + 1]; }
  // Two corners welded to one vertex.
  bool collapsed(std::size_t f) const {
    const std::uint32_t a = corner[3 * f], b = corner[3 * f + 1], c = corner[3 * f + 2];
    return a == b || b == c || c == a;
  }
  // side(h, tail, head) for each half-edge of face f, which is not collapsed: all three lie on
  // edges.
  template <class Side>
  void for_each_side(std::size_t f, const Side& side) const {
    const auto h = static_cast<std::uint32_t>(3 * f);
    const std::uint32_t a = corner[h], b = corner[h + 1], c = corner[h + 2];
    side(h, a, b);
    side(h + 1, b, c);
    side(h + 2, c, a);
  }
  // The side a face is matched on for duplicated faces (duplicate_faces.hpp): its first.
  static bool first_side(std::uint32_t h) { return h % 3 == 0; }

  // Whether the faces of half-edges a and b, on one edge, have the same welded vertices: the same
  // vertex off the edge.
  struct SameVertices {
    const TriangleLayout& layout;
    bool operator()(std::uint32_t a, std::uint32_t b) const {
      return layout.third(a) == layout.third(b);
    }
  };
  SameVertices same_vertices() const { return {*this}; }

 private:
  // The corner of h's face off h: 3 f + (k + 2) % 3.
  std::uint32_t third(std::uint32_t h) const { return corner[3 * (h / 3) + (h % 3 + 2) % 3]; }
};

// Faces of any size: face f holds corners [offset[f], offset[f + 1]), and half-edge c runs from
// corner c to the next corner of its face, cyclically. A half-edge whose ends weld to one vertex
// lies on no edge (a collapsed side).
struct PolygonLayout {
  const std::uint32_t* corner;       // welded vertex of each corner
  const std::uint32_t* offset;       // face_offsets: face_count + 1 entries
  const std::uint32_t* corner_face;  // corner → its face
  std::size_t faces;

  std::size_t face_count() const { return faces; }
  std::uint32_t face_of(std::uint32_t h) const { return corner_face[h]; }
  std::uint32_t tail(std::uint32_t h) const { return corner[h]; }
  std::uint32_t head(std::uint32_t h) const {
    const std::uint32_t f = corner_face[h];
    return corner[h + 1 == offset[f + 1] ? offset[f] : h + 1];
  }
  bool collapsed(std::size_t f) const { return collapsed_face(corner, offset[f], offset[f + 1]); }
  // side(h, tail, head) for each half-edge of face f, which is not collapsed, that lies on an edge.
  template <class Side>
  void for_each_side(std::size_t f, const Side& side) const {
    const std::uint32_t begin = offset[f], end = offset[f + 1];
    for (std::uint32_t h = begin; h < end; ++h) {
      const std::uint32_t a = corner[h], b = corner[h + 1 == end ? begin : h + 1];
      if (a != b) side(h, a, b);
    }
  }
  // The side a face is matched on for duplicated faces (duplicate_faces.hpp): the first that lies
  // on an edge. h lies on one.
  bool first_side(std::uint32_t h) const {
    const std::uint32_t begin = offset[corner_face[h]];
    for (std::uint32_t c = begin; c < h; ++c)
      if (corner[c] != corner[c + 1]) return false;  // c + 1 ≤ h: no wrap before h
    return true;
  }

  // Whether the faces of half-edges a and b have the same set of welded vertices, compared sorted
  // in buffers of its own (one per thread).
  class SameVertices {
   public:
    explicit SameVertices(const PolygonLayout& layout) : layout_(layout) {}
    bool operator()(std::uint32_t a, std::uint32_t b) {
      const std::uint32_t face_a = layout_.corner_face[a];
      if (!have_a_ || face_a != face_a_) {  // a face is matched against several in a row
        layout_.vertex_set(face_a, set_a_);
        face_a_ = face_a;
        have_a_ = true;
      }
      layout_.vertex_set(layout_.corner_face[b], set_b_);
      return set_a_ == set_b_;
    }

   private:
    const PolygonLayout& layout_;
    bool have_a_ = false;
    std::uint32_t face_a_ = 0;  // whose set set_a_ holds
    std::vector<std::uint32_t> set_a_, set_b_;
  };
  SameVertices same_vertices() const { return SameVertices(*this); }

 private:
  // Face f's welded vertices, sorted, each once.
  void vertex_set(std::uint32_t f, std::vector<std::uint32_t>& out) const {
    out.assign(corner + offset[f], corner + offset[f + 1]);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
  }
};

// Corner → face of a CSR face list (PolygonLayout::corner_face).
inline std::vector<std::uint32_t> corner_faces(const std::vector<std::uint32_t>& offset) {
  std::vector<std::uint32_t> face(offset.empty() ? 0 : offset.back());
  for (std::size_t f = 0; f + 1 < offset.size(); ++f)
    std::fill(face.begin() + offset[f], face.begin() + offset[f + 1],
              static_cast<std::uint32_t>(f));
  return face;
}

}  // namespace pgamesh::detail
