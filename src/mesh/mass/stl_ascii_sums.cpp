#include "mesh/mass/stl_ascii_sums.hpp"

#include <cstdint>
#include <numeric>
#include <vector>

#include "geometry/chunked_sums.hpp"
#include "pgamesh/geometry/face_sums.hpp"

namespace pgamesh {

namespace {

// The summing consumer of the ASCII STL grammar for one piece of the text: each facet is added to
// the piece's running sums about the reference point as soon as its last vertex is read, face k of
// the piece in lane k mod 4 of its chunk (StreamedChunkSums), so the piece keeps only the facet
// being read.
class FacetSums {
 public:
  explicit FacetSums(Vec3d reference) : reference_(reference) { facet_.reserve(8); }

  void vertex(const Vec3d& v) { facet_.push_back(v); }
  void end_facet(std::size_t n) {  // facet_ holds the facet's n vertices
    if (corners_.size() < n) {
      corners_.resize(n);
      std::iota(corners_.begin(), corners_.end(), std::uint32_t{0});
    }
    add_mesh_face(sums_.current(), facet_.data(), corners_.data(), n, reference_);
    sums_.next();
    facet_.clear();
  }

  BoundarySums total() const { return sums_.total(); }

 private:
  Vec3d reference_;
  std::vector<Vec3d> facet_;
  std::vector<std::uint32_t> corners_;  // 0, 1, …, n − 1
  StreamedChunkSums<> sums_;
};

}  // namespace

MassProperties ascii_stl_mass_properties(std::span<const char> bytes, const std::string& name,
                                         MeshSource& source, const MassOptions& options,
                                         bool release_pages, std::size_t piece_bytes) {
  using Piece = detail::StlAsciiPiece<FacetSums>;
  source.format = MeshFormat::stl_ascii;
  // The reference point before the parse, so that no vertex need be kept (docs/conventions.md §13);
  // a text without a vertex line to sample has no facet to sum either.
  const Box3 sample = detail::stl_ascii_sampled_box(bytes, name, release_pages);
  const Vec3d reference = sample.empty() ? Vec3d{} : sample.centre();
  const std::vector<Piece> pieces = detail::parse_ascii_stl_pieces<FacetSums>(
      bytes, name, options.threads, release_pages,
      [&](std::size_t) { return FacetSums(reference); }, piece_bytes);
  if (release_pages) detail::release_pages(bytes.data(), bytes.data() + bytes.size());
  const detail::StlAsciiState state = detail::joined_state(pieces);
  detail::add_stl_ascii_warnings(state, bytes.data(), name, source.warnings);
  BoundarySums sums;
  for (const Piece& p : pieces) sums += p.out.total();  // in file order: the same bits always
  return mesh_mass_properties_from_sums(sums, reference, Box3{},
                                        static_cast<std::size_t>(state.vertices), state.facets,
                                        state.triangles, options, false);
}

}  // namespace pgamesh
