// libFuzzer harness: the GLB triangle list that the front door streams through the binary STL's
// passes (glb_triangle_list, src/io/readers.hpp; docs/formats.md, "glTF 2.0"). Whatever it
// accepts must lie inside the bytes, and the careful reader must read the same triangles: the
// same counts, and from the weld of the records the read mesh's figures bit for bit. The one file
// it accepts that the reader refuses is one with a non-finite coordinate, which the passes must
// find too (the front door then reports the reader's error). Seeds: fuzz/corpus/gltf.
#include <cstring>

#include "fuzz_common.hpp"
#include "io/readers.hpp"
#include "io/stl_binary.hpp"
#include "mesh/mass/stl_mass_properties.hpp"
#include "mesh/weld/welded_triangles.hpp"
#include "pgamesh/core/bounding_box.hpp"
#include "pgamesh/mesh/mass/mass_properties.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace pgamesh;
  const std::span<const char> bytes(reinterpret_cast<const char*>(data), size);
  const auto list = detail::glb_triangle_list(bytes, "fuzz");
  if (!list) return 0;
  fuzz::require(list->triangles > 0 && list->offset <= size &&
                list->triangles <= (size - list->offset) / 36);
  const BinaryStlView view{data + list->offset, list->triangles, -1, packed_triangle_layout,
                           list->offset};
  Mesh mesh;
  try {
    mesh = read_mesh_bytes(bytes, "fuzz", nullptr, MeshFormat::glb);
  } catch (const InputError&) {
    bool found = false;
    try {
      check_binary_stl_finite(view, "fuzz");
    } catch (const InputError&) {
      found = true;
    }
    fuzz::require(found);
    return 0;
  }
  fuzz::check_mesh(mesh);
  fuzz::require(mesh.face_count() == list->triangles &&
                mesh.vertices.size() == 3 * list->triangles);
  const MassProperties streamed = binary_stl_mass_properties(view, "fuzz");
  fuzz::require(streamed.triangles == list->triangles && streamed.vertices == mesh.vertices.size());
  const WeldedTriangles welded = weld_binary_stl(view, "fuzz");
  const MassProperties from_weld =
      mass_properties(welded, bounding_box(welded.positions).centre(), {}, true);
  const MassProperties read = mass_properties(mesh);
  fuzz::require(fuzz::same_bits(from_weld.volume, read.volume));
  fuzz::require(fuzz::same_bits(from_weld.area, read.area));
  fuzz::require(fuzz::same_bits(from_weld.center_of_mass.x, read.center_of_mass.x));
  return 0;
}
