// libFuzzer harness: the STL readers (forced STL: ASCII or binary by size) and the binary view;
// and the two consumers of the one ASCII STL grammar (io/stl_ascii_grammar.hpp) against each
// other on every input: the summing consumer of `props --no-topology` must refuse exactly what the
// Mesh reader refuses, with the same message and position, and on everything the reader accepts
// give the read mesh's counts and warnings, its figures about the same reference point bit for bit
// when the text is one piece, and the same bits on one thread and on two — in one piece, and cut
// into pieces of a few dozen bytes.
#include <optional>
#include <string>

#include "fuzz_common.hpp"
#include "io/readers.hpp"
#include "mesh/mass/stl_ascii_sums.hpp"

using namespace pgamesh;

namespace {

bool same(double a, double b) {
  return fuzz::same_bits(a, b);
}
bool same(Vec3d a, Vec3d b) {
  return same(a.x, b.x) && same(a.y, b.y) && same(a.z, b.z);
}

bool same_mass(const MassProperties& a, const MassProperties& b) {
  bool ok = a.faces == b.faces && a.triangles == b.triangles && a.vertices == b.vertices &&
            a.warnings == b.warnings && same(a.reference_point, b.reference_point) &&
            same(a.center_of_mass, b.center_of_mass) && same(a.area, b.area) &&
            same(a.volume, b.volume) && same(a.mass, b.mass) && same(a.density, b.density) &&
            same(a.gap_area, b.gap_area) && same(a.carrier_sum.e0, b.carrier_sum.e0) &&
            same(a.carrier_sum.normal(), b.carrier_sum.normal());
  for (int i = 0; i < 3; ++i) {
    ok = ok && same(a.principal.moments[i], b.principal.moments[i]);
    for (int j = 0; j < 3; ++j)
      ok = ok && same(a.inertia_com[i][j], b.inertia_com[i][j]) &&
           same(a.inertia_origin[i][j], b.inertia_origin[i][j]);
  }
  return ok;
}

// The figures of `mesh` accumulated about the reference point of `summed`, as mass_properties()
// accumulates them about its own.
MassProperties mass_about(const Mesh& mesh, const MassProperties& summed,
                          const MeshSource& source) {
  return mesh_mass_properties_from_sums(mesh_boundary_sums(mesh, summed.reference_point, 1),
                                        summed.reference_point, mesh.vertices, mesh.face_count(),
                                        summed.triangles, {}, source.single_precision);
}

bool same_error(const InputError& a, const InputError& b) {
  return std::string(a.what()) == b.what() && a.where().has_line == b.where().has_line &&
         a.where().line == b.where().line && a.where().column == b.where().column &&
         a.where().byte_offset == b.where().byte_offset;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::read_bytes(data, size, MeshFormat::stl_binary);

  const std::span<const char> bytes{reinterpret_cast<const char*>(data), size};
  Mesh mesh;
  MeshSource read_source;
  std::optional<InputError> read_error;
  try {
    detail::read_stl_ascii(bytes, "fuzz", mesh, read_source);
  } catch (const InputError& e) {
    read_error = e;
  }
  std::optional<MassProperties> read_mass;
  if (!read_error) {
    fuzz::check_mesh(mesh);
    read_mass = mass_properties(mesh, {}, &read_source);
  }
  for (const std::size_t piece_bytes : {detail::stl_ascii_piece_bytes, std::size_t{48}}) {
    std::optional<MassProperties> one_thread;
    for (const unsigned threads : {1u, 2u}) {
      MassOptions options;
      options.threads = threads;
      MeshSource source;
      try {
        const MassProperties summed =
            ascii_stl_mass_properties(bytes, "fuzz", source, options, false, piece_bytes);
        fuzz::require(
            read_mass.has_value());  // the summing consumer accepted what the reader rejects
        fuzz::require(summed.faces == read_mass->faces &&
                      summed.triangles == read_mass->triangles &&
                      summed.vertices == read_mass->vertices);
        fuzz::require(source.format == read_source.format &&
                      source.warnings == read_source.warnings);
        // Text of one piece: the mesh's sums about the same point, bit for bit.
        if (size <= piece_bytes)
          fuzz::require(same_mass(summed, mass_about(mesh, summed, read_source)));
        // Any thread count: the same bits.
        if (one_thread)
          fuzz::require(same_mass(summed, *one_thread));
        else
          one_thread = summed;
      } catch (const InputError& e) {
        fuzz::require(read_error.has_value() && same_error(e, *read_error));
      }
    }
  }
  return 0;
}
