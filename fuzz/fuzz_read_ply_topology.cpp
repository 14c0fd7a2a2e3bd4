// libFuzzer harness: the PLY topology pass that re-reads the faces from the bytes
// (ply_topology.hpp), with one range per vertex and with the default ranges. A malformed header
// must end in InputError and anything else it cannot read in nullopt; whatever it accepts the
// careful reader must accept too, with the same figures (a few fields compared bit for bit, the
// rest by tests/mesh/test_ply_topology.cpp).
#include <cstring>
#include <optional>

#include "fuzz_common.hpp"
#include "mesh/topology/ply_topology.hpp"
#include "pgamesh/mesh/mass/mass_properties.hpp"
#include "pgamesh/mesh/topology/topology.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace pgamesh;
  const std::span<const char> bytes(reinterpret_cast<const char*>(data), size);
  for (std::size_t budget : {std::size_t{1}, std::size_t{0}}) {
    std::optional<WeldedTriangleProps> props;
    MeshSource source;
    try {
      props = ply_triangle_props(bytes, "fuzz", source, {}, {}, false, PlyPassBudget{budget});
    } catch (const InputError&) {
      return 0;
    }
    if (!props) return 0;
    const Mesh mesh = read_mesh_bytes(bytes, "fuzz", nullptr, MeshFormat::unknown);
    fuzz::check_mesh(mesh);
    const MassProperties mass = mass_properties(mesh, {}, &source);
    const TopologyReport report = analyze_topology(mesh);
    fuzz::require(fuzz::same_bits(mass.volume, props->mass.volume));
    fuzz::require(fuzz::same_bits(mass.area, props->mass.area));
    fuzz::require(fuzz::same_bits(report.volume_min, props->topology.volume_min));
    fuzz::require(report.edges == props->topology.edges);
    fuzz::require(report.boundary_edges == props->topology.boundary_edges);
    fuzz::require(report.inconsistent_edges == props->topology.inconsistent_edges);
    fuzz::require(report.nonmanifold_edges == props->topology.nonmanifold_edges);
    fuzz::require(report.duplicated_faces == props->topology.duplicated_faces);
    fuzz::require(report.components == props->topology.components);
    fuzz::require(report.boundary_loops.size() == props->topology.boundary_loops.size());
  }
  return 0;
}
