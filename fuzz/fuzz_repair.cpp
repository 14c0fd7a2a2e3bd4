// libFuzzer harness: repair (weld, face removal, caps, orientation by nesting) on small meshes
// decoded from the bytes. Vertices lie on a 4 × 4 × 4 grid, so coincident vertices, duplicated
// and collapsed faces, holes, double walls and nested shells come up often. Whatever the mesh,
// the repair must end, leave a well-formed mesh (check_mesh), and be idempotent in what it
// removes: a second repair merges no vertex and removes no face.
#include "fuzz_common.hpp"
#include "pgamesh/mesh/repair/repair.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace pgamesh;
  if (size < 2) return 0;
  Mesh m;
  const std::size_t vertices = 1 + data[0] % 32;
  std::size_t at = 1;
  for (std::size_t v = 0; v < vertices; ++v, ++at) {
    const std::uint8_t b = at < size ? data[at] : 0;
    m.vertices.push_back({double(b & 3), double((b >> 2) & 3), double((b >> 4) & 3)});
  }
  while (at < size) {  // faces: a size byte (3..6 corners), then the corners
    const std::size_t corners = 3 + data[at++] % 4;
    if (at + corners > size) break;
    for (std::size_t k = 0; k < corners; ++k)
      m.corners.push_back(static_cast<std::uint32_t>(data[at++] % vertices));
    m.face_offsets.push_back(static_cast<std::uint32_t>(m.corners.size()));
  }
  RepairOptions options;
  options.hole.force = (data[0] & 0x80) != 0;
  repair(m, options);
  fuzz::check_mesh(m);
  const RepairReport again = repair(m, options);
  fuzz::require(again.merged_vertices == 0 && again.collapsed_faces == 0 &&
                again.repeated_corners == 0);
  fuzz::check_mesh(m);
  return 0;
}
