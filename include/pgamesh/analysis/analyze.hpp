// The library's front door: analyse a mesh file — mass properties, the topology report and what the
// reader learned about the source — choosing the fastest strategy for the format and the options
// itself. Every strategy gives the same bits (docs/architecture.md, "One front door"); the CLI, the
// viewer's server and the bindings call these functions and only format their result.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "pgamesh/core/mesh.hpp"
#include "pgamesh/mesh/mass/mass_properties.hpp"
#include "pgamesh/mesh/topology/topology.hpp"

namespace pgamesh {

struct AnalysisOptions {
  MassOptions mass;
  bool topology = true;  // false: no weld and edge pass (closedness is then unknown)
  TopologyOptions topology_options;
  MeshFormat format = MeshFormat::unknown;  // forced reader family (unknown: from the content)
  // The unit of a file that states none (--unit). A file that states its unit (3MF, glTF) and a
  // different one here is refused (std::invalid_argument): convert it with `pgamesh convert`.
  LengthUnit unit = LengthUnit::unspecified;
};

// The analysis of one part of a file that holds several (MeshSource::parts: a 3MF build item):
// analyze_mesh() of the part's faces alone, with the vertices they use.
struct PartAnalysis {
  MeshPart part;
  MassProperties mass;
  std::optional<TopologyReport> topology;
  std::optional<bool> volume_valid;
  std::vector<std::string> reasons;
};

struct Analysis {
  std::string file;
  MeshFormat format = MeshFormat::unknown;
  bool single_precision = false;  // the coordinates were float32 (binary STL, float PLY, glTF)
  // The unit of the figures: the file's own (3MF, glTF), else AnalysisOptions::unit.
  LengthUnit unit = LengthUnit::unspecified;
  bool streamed = false;  // accumulated straight from the file, no Mesh built
  MassProperties mass;
  std::optional<TopologyReport> topology;  // absent when not requested
  // Whether the volume, centre of mass and inertia describe a solid: false for an open,
  // inconsistently oriented, inward or flat mesh, absent when unknown for want of topology.
  std::optional<bool> volume_valid;
  std::vector<std::string> reasons;   // why the volume is not valid, in plain words
  std::vector<std::string> warnings;  // reader repairs, float32 precision, …
  bool density_from_mass = false;     // the density was derived from options.mass.mass
  // One per part when the file holds several (MeshSource::parts); the figures above are those of
  // the whole (mass properties add up; topology is per part).
  std::vector<PartAnalysis> parts;
};

// Reads the file at `path` ("-" for standard input) and analyses it. A binary STL is never read
// into a Mesh: without topology its records are summed as they are read; with the exact weld they
// are welded straight from the file. A GLB of one untransformed, non-indexed float32 triangle list
// takes the same passes (docs/formats.md, "glTF 2.0"). Throws InputError (naming the file and the
// position) for unreadable input, std::invalid_argument for bad options and std::range_error when
// the coordinates are so large that the area, volume or inertia overflow a double.
Analysis analyze_file(const std::string& path, const AnalysisOptions& options = {});

// The same for bytes already in memory (an upload); `name` names them in errors and the result.
Analysis analyze_bytes(std::span<const char> bytes, const std::string& name,
                       const AnalysisOptions& options = {});

// The analysis of a mesh already read, described by `source`.
Analysis analyze_mesh(const Mesh& mesh, const MeshSource& source,
                      const AnalysisOptions& options = {});

}  // namespace pgamesh
