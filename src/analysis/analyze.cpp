#include "pgamesh/analysis/analyze.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <utility>

#include "detail/memory/page_release.hpp"
#include "io/readers.hpp"
#include "io/stl_binary.hpp"
#include "io/text_cursor.hpp"
#include "mesh/mass/stl_ascii_sums.hpp"
#include "mesh/mass/stl_mass_properties.hpp"
#include "mesh/topology/ply_topology.hpp"
#include "mesh/topology/welded_topology.hpp"
#include "mesh/weld/welded_triangles.hpp"
#include "pgamesh/core/bounding_box.hpp"
#include "pgamesh/core/input_error.hpp"
#include "pgamesh/io/mapped_file.hpp"
#include "pgamesh/io/read_mesh.hpp"

namespace pgamesh {

namespace {

bool all_finite(const Mat3& m) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (!std::isfinite(m[i][j])) return false;
  return true;
}

// Coordinates so large that the area, the volume or the inertia overflow a double (a part of size
// around 1e61 and up: inertia grows as the fifth power of the size) give inf or nan, which no
// output may print as a result: the analysis is refused, naming the file. The centre of mass and
// the inertia are undefined (nan) when the volume is 0, so they are judged only when it is not.
void refuse_overflow(const Analysis& r) {
  const MassProperties& m = r.mass;
  const bool finite = std::isfinite(m.area) && std::isfinite(m.volume) && std::isfinite(m.mass) &&
                      std::isfinite(m.gap_area) &&
                      (m.volume == 0 || (is_finite(m.center_of_mass) && all_finite(m.inertia_com) &&
                                         all_finite(m.inertia_origin)));
  if (!finite)
    throw std::range_error(
        "the coordinates are too large for double precision: the area, volume or inertia "
        "overflows (scale the mesh down, e.g. express it in a larger unit)");
}

// Whether the figures describe a solid, and why not.
void judge(Analysis& r) {
  refuse_overflow(r);
  if (r.topology) {
    r.volume_valid = r.topology->volume_valid;
    if (!r.topology->volume_valid)
      r.reasons.insert(r.reasons.end(), r.topology->notes.begin(), r.topology->notes.end());
  }
  if (r.mass.volume == 0) {
    r.volume_valid = false;
    r.reasons.push_back("zero volume: no centre of mass or inertia");
  } else if (r.mass.volume < 0) {
    r.volume_valid = false;
    r.reasons.push_back(
        "negative volume: the faces are oriented inward (clockwise seen from outside); the "
        "figures are those of the mesh as given, not abs()'d (pgamesh check --fix-orientation "
        "repairs the orientation)");
  }
  if (!r.topology && r.volume_valid.value_or(true))
    r.reasons.push_back("topology not computed (--no-topology): closedness unknown");
}

// The report without the topology: mass properties, the reader's and their warnings.
Analysis mass_report(MassProperties mass, const MeshSource& source,
                     const AnalysisOptions& options) {
  Analysis r;
  r.file = source.path;
  r.format = source.format;
  r.single_precision = source.single_precision;
  r.unit = source.unit;
  r.density_from_mass = options.mass.mass.has_value();
  r.mass = std::move(mass);
  r.warnings = source.warnings;
  r.warnings.insert(r.warnings.end(), r.mass.warnings.begin(), r.mass.warnings.end());
  return r;
}

Analysis mass_report(const Mesh& mesh, const MeshSource& source, const AnalysisOptions& options) {
  return mass_report(mass_properties(mesh, options.mass, &source), source, options);
}

// The faces of `part` as a mesh of their own, with the vertices from the lowest to the highest
// index they use (a 3MF build item's vertices are contiguous).
Mesh part_mesh(const Mesh& mesh, const MeshPart& part) {
  Mesh sub;
  const std::uint32_t first = mesh.face_offsets[part.first_face];
  const std::uint32_t last = mesh.face_offsets[part.first_face + part.face_count];
  if (first == last) return sub;
  const auto [lo, hi] =
      std::minmax_element(mesh.corners.begin() + first, mesh.corners.begin() + last);
  sub.vertices.assign(mesh.vertices.begin() + *lo, mesh.vertices.begin() + *hi + 1);
  sub.corners.reserve(last - first);
  for (std::uint32_t k = first; k < last; ++k) sub.corners.push_back(mesh.corners[k] - *lo);
  sub.face_offsets.reserve(part.face_count + 1);
  for (std::uint32_t f = part.first_face + 1; f <= part.first_face + part.face_count; ++f)
    sub.face_offsets.push_back(mesh.face_offsets[f] - first);
  return sub;
}

// Whether the file's only part is all of its faces: then the part's figures are the whole's,
// taken from it (whole_as_part) rather than computed twice.
bool one_whole_part(const Mesh& mesh, const MeshSource& source) {
  return source.parts.size() == 1 && source.parts[0].first_face == 0 &&
         source.parts[0].face_count == mesh.face_count();
}

std::vector<PartAnalysis> whole_as_part(const Analysis& whole, const MeshPart& part) {
  return {{part, whole.mass, whole.topology, whole.volume_valid, whole.reasons}};
}

// Each part analysed alone by analyze_mesh() (a part mesh has no parts of its own).
std::vector<PartAnalysis> part_analyses(const Mesh& mesh, const MeshSource& source,
                                        const AnalysisOptions& options) {
  std::vector<PartAnalysis> out;
  if (one_whole_part(mesh, source)) return out;  // whole_as_part, once the whole is known
  MeshSource part_source;
  part_source.path = source.path;
  part_source.format = source.format;
  part_source.unit = source.unit;
  for (const MeshPart& part : source.parts) {
    Analysis a = analyze_mesh(part_mesh(mesh, part), part_source, options);
    out.push_back(
        {part, std::move(a.mass), std::move(a.topology), a.volume_valid, std::move(a.reasons)});
  }
  return out;
}

// The report of a PLY file without topology, its faces summed as the PLY reader parses them (its
// summing consumer, read_ply_summing_faces in readers.hpp) and never stored: the figures of
// mass_properties() on the mesh read_mesh_bytes() would read, bit for bit, and a malformed file
// raises the reader's own error. nullopt for anything else: another format, topology wanted, a
// blank file (read_mesh_bytes() reports it) or a file whose faces come before its vertices (the
// reader declines it before reading any data; the Mesh path below reads it).
std::optional<Analysis> summed_ply_report(std::span<const char> bytes, const std::string& name,
                                          MeshFormat format, const AnalysisOptions& options,
                                          bool release_pages) {
  if (options.topology ||
      (format != MeshFormat::ply_ascii && format != MeshFormat::ply_binary_le &&
       format != MeshFormat::ply_binary_be) ||
      std::all_of(bytes.begin(), bytes.end(), detail::is_space))
    return std::nullopt;
  MeshSource source;
  source.path = name;
  Mesh vertices;  // the vertices only
  const auto sums = detail::read_ply_summing_faces(bytes, name, vertices, source, release_pages);
  if (!sums) return std::nullopt;
  // The last step and the header's page, as read_mesh_bytes() releases them.
  if (release_pages) detail::release_pages(bytes.data(), bytes.data() + bytes.size());
  Analysis r = mass_report(
      mesh_mass_properties_from_sums(sums->sums, sums->reference, vertices.vertices, sums->faces,
                                     sums->triangles, options.mass, source.single_precision),
      source, options);
  judge(r);
  return r;
}

// The report of a binary PLY triangle mesh with exact-weld topology, its faces re-read from the
// file rather than stored (ply_topology.hpp), or nullopt for a file that pass declines or finds
// fault with: the careful reader then reads it again and reports exactly what it reports.
std::optional<Analysis> ply_topology_report(std::span<const char> bytes, const std::string& name,
                                            MeshFormat format, const AnalysisOptions& options,
                                            bool release_pages) {
  if (!options.topology || options.topology_options.weld_tolerance != 0 ||
      (format != MeshFormat::ply_binary_le && format != MeshFormat::ply_binary_be))
    return std::nullopt;
  try {
    MeshSource source;
    auto props = ply_triangle_props(bytes, name, source, options.mass, options.topology_options,
                                    release_pages);
    if (!props) return std::nullopt;
    Analysis r = mass_report(std::move(props->mass), source, options);
    r.topology = std::move(props->topology);
    judge(r);
    return r;
  } catch (const InputError&) {
    return std::nullopt;
  }
}

// The unit of the figures: the file's own, else the one stated in the options; a file whose unit
// differs from the stated one is refused rather than silently rescaled (docs/formats.md, "Units").
Analysis with_unit(Analysis r, const AnalysisOptions& options) {
  if (r.unit == LengthUnit::unspecified) {
    r.unit = options.unit;
  } else if (options.unit != LengthUnit::unspecified && options.unit != r.unit) {
    throw std::invalid_argument(std::string("the file states its unit (") + unit_name(r.unit) +
                                "), not " + unit_name(options.unit) +
                                " as --unit says (pgamesh convert --unit rescales a file)");
  }
  return r;
}

}  // namespace

Analysis analyze_mesh(const Mesh& mesh, const MeshSource& source, const AnalysisOptions& options) {
  Analysis r = mass_report(mesh, source, options);
  r.parts = part_analyses(mesh, source, options);
  if (options.topology) r.topology = analyze_topology(mesh, options.topology_options);
  judge(r);
  if (one_whole_part(mesh, source)) r.parts = whole_as_part(r, source.parts[0]);
  return with_unit(std::move(r), options);
}

namespace {

// The report of float32 triangle records, a binary STL's or a GLB's (BinaryStlView::layout),
// never read into a Mesh: without topology, their mass properties are streamed from the records;
// with exact-weld topology, they are welded straight from the records (welded_triangles.hpp), and
// both the mass properties and the topology come from the welded triangles. The file's format is
// `format`; its unit and parts are the caller's to add.
Analysis records_report(const BinaryStlView& view, const std::string& name, MeshFormat format,
                        const AnalysisOptions& options, bool release_records) {
  Analysis r;
  r.file = name;
  r.format = format;
  r.single_precision = true;
  r.density_from_mass = options.mass.mass.has_value();
  if (!options.topology) {
    r.streamed = true;
    r.mass = binary_stl_mass_properties(view, name, options.mass, release_records);
  } else {
    const WeldedTriangles welded = weld_binary_stl(view, name, release_records);
    const Vec3d reference = bounding_box(welded.positions).centre();  // reference_point()
    WeldedTriangleProps props =
        analyze_welded_triangles(welded, reference, options.mass, options.topology_options, true);
    r.mass = std::move(props.mass);
    r.topology = std::move(props.topology);
  }
  r.warnings = r.mass.warnings;
  judge(r);
  return r;
}

// The report of a GLB that is one untransformed, non-indexed float32 triangle list
// (glb_triangle_list, readers.hpp): its positions streamed as 36-byte records through the binary
// STL's passes, the figures of a binary STL of the same triangles bit for bit; the unit (metre),
// the counts and the one part those of the Mesh path below. nullopt for any other GLB, and for one
// the passes find fault with (a non-finite coordinate): the reader then reads it and reports what
// it reports.
std::optional<Analysis> glb_triangle_report(std::span<const char> bytes, const std::string& name,
                                            const AnalysisOptions& options, int file) {
  const auto list = detail::glb_triangle_list(bytes, name);
  if (!list) return std::nullopt;
  const BinaryStlView view{reinterpret_cast<const unsigned char*>(bytes.data()) + list->offset,
                           list->triangles, file, packed_triangle_layout, list->offset};
  try {
    Analysis r = records_report(view, name, MeshFormat::glb, options, file >= 0);
    r.unit = LengthUnit::meter;  // glTF 2.0 §3.4, as read_gltf states it
    r.parts =
        whole_as_part(r, MeshPart{list->part_name, 0, static_cast<std::uint32_t>(list->triangles)});
    return r;
  } catch (const InputError&) {
    return std::nullopt;
  }
}

// The report of `bytes`. A binary STL is not read into a Mesh: without topology its mass
// properties are streamed from the records; with exact-weld topology it is welded straight from
// the records (welded_triangles.hpp), and both the mass properties and the topology come from the
// welded triangles — the same figures as reading the mesh first, in a quarter of the memory.
// `file` is the open descriptor of the read-only file mapping that `bytes` are (MappedFile), or −1
// for bytes of our own: with a mapping, the binary STL passes read the records from the file
// instead of touching the mapping (BinaryStlView::file), and the other readers give the mapping's
// pages back as they pass. A GLB of one untransformed, non-indexed float32 triangle list takes the
// binary STL's passes too (glb_triangle_report).
Analysis analyze(std::span<const char> bytes, const std::string& name,
                 const AnalysisOptions& options, int file) {
  const bool release_records = file >= 0;
  // The format by content, looked at once; a forced format picks the reader family.
  const MeshFormat detected = detect_format(bytes);
  const MeshFormat format = options.format == MeshFormat::unknown ? detected : options.format;
  // A zip (3MF) whose size happens to fit the binary STL arithmetic is still a zip, as
  // detect_format() says.
  const bool stl_allowed =
      (options.format == MeshFormat::unknown && detected != MeshFormat::threemf) ||
      options.format == MeshFormat::stl_binary || options.format == MeshFormat::stl_ascii;
  const bool weld_from_records = options.topology && options.topology_options.weld_tolerance == 0 &&
                                 options.format != MeshFormat::stl_ascii;
  if ((!options.topology || weld_from_records) && stl_allowed) {
    if (auto view = binary_stl_view(bytes, name)) {
      view->file = file;
      return records_report(*view, name, MeshFormat::stl_binary, options, release_records);
    }
    // ASCII STL without topology: the reader's grammar hands the facets to a summing consumer
    // instead of a Mesh, on every core (stl_ascii_sums.hpp): the figures, warnings and errors of
    // the mesh path below, bit for bit.
    if (!options.topology && detected == MeshFormat::stl_ascii) {
      MeshSource source;
      source.path = name;
      MassProperties mass =
          ascii_stl_mass_properties(bytes, name, source, options.mass, release_records);
      // An ASCII STL named .slp is an SLP without colours, as read_mesh_bytes names it.
      if (format_for_extension(name) == MeshFormat::slp) source.format = MeshFormat::slp;
      Analysis r = mass_report(std::move(mass), source, options);
      r.streamed = true;
      judge(r);
      return r;
    }
  }
  // (--format gltf reads a GLB too.)
  if ((format == MeshFormat::glb || format == MeshFormat::gltf) &&
      (!options.topology || weld_from_records))
    if (auto r = glb_triangle_report(bytes, name, options, file)) return std::move(*r);
  if (auto r = summed_ply_report(bytes, name, format, options, release_records))
    return std::move(*r);
  if (auto r = ply_topology_report(bytes, name, format, options, release_records))
    return std::move(*r);
  // The careful readers, releasing the file's pages as they parse (release_records); the mesh is
  // then handed to the topology pass, which frees it once welded (topology.hpp).
  MeshSource source;
  // A mapped file (file ≥ 0) is named by its path: a glTF's external buffers are read beside it.
  Mesh mesh =
      detail::read_mesh_bytes(bytes, name, &source, options.format, release_records, file >= 0);
  source.path = name;
  Analysis r = mass_report(mesh, source, options);
  r.parts = part_analyses(mesh, source, options);
  const bool whole_part = one_whole_part(mesh, source);
  if (options.topology) r.topology = analyze_topology(std::move(mesh), options.topology_options);
  judge(r);
  if (whole_part) r.parts = whole_as_part(r, source.parts[0]);
  return r;
}

}  // namespace

Analysis analyze_bytes(std::span<const char> bytes, const std::string& name,
                       const AnalysisOptions& options) {
  return with_unit(analyze(bytes, name, options, -1), options);
}

Analysis analyze_file(const std::string& path, const AnalysisOptions& options) {
  // MappedFile maps regular files (descriptor() ≥ 0); standard input and pipes are read into a
  // buffer of its own.
  const MappedFile file = MappedFile::open(path);
  return with_unit(analyze(file.bytes(), path, options, file.descriptor()), options);
}

}  // namespace pgamesh
