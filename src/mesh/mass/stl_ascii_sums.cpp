#include "mesh/mass/stl_ascii_sums.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "detail/memory/huge_pages.hpp"
#include "geometry/chunked_sums.hpp"
#include "pgamesh/core/bounding_box.hpp"
#include "pgamesh/geometry/face_sums.hpp"

namespace pgamesh {

namespace {

// The summing consumer of the ASCII STL grammar for one piece of the text. It keeps what the sums
// need: the piece's vertices and their bounding box — the reference point, the centre of the box of
// every vertex of the file, is known only once every piece is parsed — and, from the first facet
// that is not a triangle on, where each facet ends. No corner or face list (Mesh: 16 bytes more a
// triangle), and the text's pages can go as soon as the piece is parsed.
class FacetSums {
 public:
  explicit FacetSums(std::size_t piece_bytes) {
    vertices_.reserve(piece_bytes / 40);  // as read_stl_ascii: no reallocation for ≥ 120 B a facet
  }

  void vertex(const Vec3d& v) {
    vertices_.push_back(v);
    box_.add(v);
  }
  void end_facet(std::size_t n) {
    if (n != 3 && !polygons_) {  // the first polygon: the triangles before it end every 3
      polygons_ = true;
      for (std::size_t f = 1; f <= faces_; ++f) ends_.push_back(static_cast<std::uint32_t>(3 * f));
    }
    if (polygons_) ends_.push_back(static_cast<std::uint32_t>(vertices_.size()));
    ++faces_;
  }

  std::size_t faces() const { return faces_; }
  const Box3& box() const { return box_; }

  // Adds the `count` facets of the piece from `local` on to the lanes, as mesh_boundary_sums adds
  // faces: facet local + i is face `face` + i of the file.
  void add_faces(LanedSums<>& s, std::size_t face, std::size_t local, std::size_t count,
                 Vec3d reference) const {
    static constexpr std::uint32_t triangle[3] = {0, 1, 2};
    if (!polygons_) {
      for (std::size_t i = 0; i < count; ++i)
        add_mesh_face(s[face + i], &vertices_[3 * (local + i)], triangle, 3, reference);
      return;
    }
    thread_local std::vector<std::uint32_t> corners;  // 0, 1, …, n − 1
    for (std::size_t i = 0; i < count; ++i) {
      const std::size_t f = local + i;
      const std::uint32_t begin = f ? ends_[f - 1] : 0, n = ends_[f] - begin;
      for (auto k = static_cast<std::uint32_t>(corners.size()); k < n; ++k) corners.push_back(k);
      add_mesh_face(s[face + i], &vertices_[begin], corners.data(), n, reference);
    }
  }

 private:
  // On whole huge pages: a piece of the summing pass keeps about 2.5 MB of vertices, which in 4 KiB
  // pages would cost some 600 page faults a piece (docs/topology.md, huge pages).
  detail::HugeVector<Vec3d> vertices_;
  std::vector<std::uint32_t> ends_;  // the end of each facet's vertices, once polygons_
  std::size_t faces_ = 0;
  bool polygons_ = false;  // a facet of the piece is not a triangle
  Box3 box_;
};

}  // namespace

MassProperties ascii_stl_mass_properties(std::span<const char> bytes, const std::string& name,
                                         MeshSource& source, const MassOptions& options,
                                         bool release_pages, std::size_t piece_bytes) {
  using Piece = detail::StlAsciiPiece<FacetSums>;
  source.format = MeshFormat::stl_ascii;
  const std::vector<Piece> pieces = detail::parse_ascii_stl_pieces<FacetSums>(
      bytes, name, options.threads, release_pages, [](std::size_t size) { return FacetSums(size); },
      piece_bytes);
  if (release_pages) detail::release_pages(bytes.data(), bytes.data() + bytes.size());
  const detail::StlAsciiState state = detail::joined_state(pieces);
  detail::add_stl_ascii_warnings(state, bytes.data(), name, source.warnings);

  // reference_point() of the mesh (docs/conventions.md §13): the centre of the bounding box of
  // every vertex (the boxes of the pieces joined in file order keep the box's choice between +0
  // and −0).
  Box3 box;
  std::vector<std::size_t> first_face;  // of each piece, in the file's face numbering
  std::size_t faces = 0;
  for (const Piece& p : pieces) {
    box.add(p.out.box());
    first_face.push_back(faces);
    faces += p.out.faces();
  }
  const Vec3d reference = box.centre();
  // mesh_boundary_sums: the same faces in the same chunks and lanes, so the same bits
  // (docs/conventions.md §13, deterministic reduction order).
  const BoundarySums sums =
      chunked_sums(faces, options.threads, [&](LanedSums<>& s, std::size_t begin, std::size_t end) {
        auto k = static_cast<std::size_t>(
            std::upper_bound(first_face.begin(), first_face.end(), begin) - first_face.begin() - 1);
        for (std::size_t f = begin; f < end; ++k) {  // the pieces' runs of faces in the chunk
          const std::size_t stop = std::min(end, first_face[k] + pieces[k].out.faces());
          if (stop > f) pieces[k].out.add_faces(s, f, f - first_face[k], stop - f, reference);
          f = std::max(f, stop);
        }
      });
  return mesh_mass_properties_from_sums(sums, reference, Box3{},
                                        static_cast<std::size_t>(state.vertices), state.facets,
                                        state.triangles, options, false);
}

}  // namespace pgamesh
