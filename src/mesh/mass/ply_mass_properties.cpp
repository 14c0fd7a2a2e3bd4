#include "pgamesh/mesh/mass/ply_mass_properties.hpp"

#include "detail/memory/page_release.hpp"
#include "io/readers.hpp"

namespace pgamesh {

std::optional<MassProperties> ply_mass_properties(std::span<const char> bytes,
                                                  const std::string& name, MeshSource& source,
                                                  const MassOptions& options, bool release_pages) {
  source = MeshSource{};
  source.path = name;
  Mesh vertices_only;
  const auto sums =
      detail::read_ply_summing_faces(bytes, name, vertices_only, source, release_pages);
  if (!sums) return std::nullopt;
  // The last step and the header's page, as read_mesh_bytes() releases them.
  if (release_pages) detail::release_pages(bytes.data(), bytes.data() + bytes.size());
  return mesh_mass_properties_from_sums(sums->sums, sums->reference, vertices_only.vertices,
                                        sums->faces, sums->triangles, options,
                                        source.single_precision);
}

}  // namespace pgamesh
