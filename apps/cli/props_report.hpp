// What `pgamesh props` computes for one mesh — mass properties, the topology summary and whether
// the figures mean anything — and its renderings: JSON (DESIGN.md §5), readable text, and the
// <inertial> elements of URDF and MJCF. The web viewer serves the same JSON from the same code.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "pgamesh/mesh/mass_properties.hpp"
#include "pgamesh/mesh/mesh.hpp"
#include "pgamesh/mesh/topology.hpp"

namespace pgamesh::cli {

struct PropsOptions {
  MassOptions mass;
  bool topology = true;  // false: skip the weld and edge pass (binary STL: streamed path)
  TopologyOptions topology_options;
  MeshFormat format = MeshFormat::unknown;  // forced reader family (unknown = detect)
};

struct PropsReport {
  std::string file;
  MeshFormat format = MeshFormat::unknown;
  bool single_precision = false;
  bool streamed = false;  // STL accumulated straight from the file, no Mesh built
  MassProperties mass;
  std::optional<TopologyReport> topology;  // absent when not requested
  // False when the volume, centre of mass and inertia do not describe a solid (open, inconsistent,
  // duplicated faces, inward, zero volume); null (absent) when unknown for want of topology.
  std::optional<bool> meaningful;
  std::vector<std::string> reasons;   // why not meaningful, in plain words
  std::vector<std::string> warnings;  // reader repairs, float32 precision, ...
  bool density_from_mass = false;
};

// Reads `path` and computes its report. Binary STL without topology is streamed from the mapped
// file (mesh/stl_mass_properties.hpp); with exact-weld topology it is welded from its records
// (mesh/welded_triangles.hpp) and no Mesh is built. Throws InputError for unreadable input.
PropsReport props_of_file(const std::string& path, const PropsOptions& options);

// The same for bytes already in memory (an upload); `name` names them in errors and the report.
PropsReport props_of_bytes(std::span<const char> bytes, const std::string& name,
                           const PropsOptions& options);

// The report of a mesh already read.
PropsReport props_of_mesh(const Mesh& mesh, const MeshSource& source, const PropsOptions& options);

// One JSON object (DESIGN.md §5 fields and more; numbers %.17g; undefined values null).
std::string props_json(const PropsReport& report);

// The readable report; `about_origin` adds the inertia tensor about the coordinate origin.
std::string props_text(const PropsReport& report, bool about_origin);

// URDF <inertial>: origin at the centre of mass, axes of the mesh frame, tensor entries (ixy is
// the tensor's entry, −∫xy dm), with the frame and convention in an XML comment.
std::string props_urdf(const PropsReport& report);

// MJCF <inertial>: pos at the centre of mass, diaginertia of the principal moments and quat of
// the principal frame (w x y z), fullinertia given in a comment.
std::string props_mjcf(const PropsReport& report);

// The sentence stating the inertia convention, as printed in every output.
extern const char* const inertia_convention;

}  // namespace pgamesh::cli
