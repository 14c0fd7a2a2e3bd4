// The renderings of the front door's analysis (pgamesh/analysis/analyze.hpp) that `pgamesh props`
// prints: JSON (docs/json.md), readable text, and the <inertial> elements of URDF and MJCF. The web
// viewer serves the same JSON from the same code.
#pragma once

#include <array>
#include <string>

#include "pgamesh/analysis/analyze.hpp"

namespace pgamesh::cli {

// One JSON object (docs/mass-properties.md fields and more; numbers %.17g; undefined values null).
std::string props_json(const Analysis& report);

// The readable report; `about_origin` adds the inertia tensor about the coordinate origin.
std::string props_text(const Analysis& report, bool about_origin);

// The figures of the robot-description exports in SI units: the report's, whose lengths are in
// the file's unit (1 m for a unitless file), scaled to metres; the density given is in kg/m³ (or
// the mass in kg). docs/mass-properties.md, "Exports".
struct SiInertial {
  double scale = 1;           // metres per unit of the file (the mesh elements' scale)
  bool unit_assumed = false;  // the file had no unit: metres assumed
  double mass = 0, density = 0;
  Vec3d center_of_mass{};
  Mat3 inertia{};  // about the centre of mass
  std::array<double, 3> moments{};
};
SiInertial si_inertial(const Analysis& report);

// The exports below, in SI units, each followed by the mesh element that places the file (its
// absolute path as a file:// URI, none for standard input) at the scale of its unit.
// URDF <inertial>: origin at the centre of mass, axes of the mesh frame, tensor entries (ixy is
// the tensor's entry, −∫xy dm), with the frame and convention in an XML comment; then <visual> and
// <collision> with <mesh filename=… scale=…>.
std::string props_urdf(const Analysis& report);

// MJCF <inertial>: pos at the centre of mass, diaginertia of the principal moments and quat of
// the principal frame (w x y z), fullinertia given in a comment; then the <mesh file=… scale=…>
// of the <asset> element.
std::string props_mjcf(const Analysis& report);

// SDFormat 1.7: <sdf><model><link> with <inertial> (pose, mass, inertia), <collision> and
// <visual> whose geometry is the mesh (<uri>, <scale>).
std::string props_sdf(const Analysis& report);

// The sentence stating the inertia convention, as printed in every output.
extern const char* const inertia_convention;

}  // namespace pgamesh::cli
