// libFuzzer harness: the fused ASCII STL mass-property pass against the careful reader. The fused
// pass must never crash or throw on bad input, and whatever it accepts the careful reader must
// accept too, with the same facets (triangles only), vertices and warnings.
#include "fuzz_common.hpp"
#include "pgamesh/mesh/mass/stl_ascii_mass_properties.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace pgamesh;
  const std::span<const char> bytes{reinterpret_cast<const char*>(data), size};
  const std::optional<MassProperties> fused = ascii_stl_mass_properties(bytes, "fuzz");
  if (!fused) return 0;  // declined: the careful reader decides
  MeshSource source;
  Mesh m;
  try {
    m = read_mesh_bytes(bytes, "fuzz", &source, MeshFormat::stl_ascii);
  } catch (const InputError&) {
    fuzz::require(false);  // the fused pass accepted what the reader rejects
  }
  fuzz::check_mesh(m);
  fuzz::require(source.format == MeshFormat::stl_ascii);
  fuzz::require(m.face_count() == fused->faces && fused->triangles == fused->faces);
  fuzz::require(m.corners.size() == 3 * m.face_count());
  fuzz::require(m.vertices.size() == fused->vertices);
  fuzz::require(source.warnings == fused->warnings);
  return 0;
}
