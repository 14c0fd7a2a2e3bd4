// The renderings of the front door's analysis (pgamesh/analysis/analyze.hpp) that `pgamesh props`
// prints: JSON (docs/json.md), readable text, and the <inertial> elements of URDF and MJCF. The web
// viewer serves the same JSON from the same code.
#pragma once

#include <string>

#include "pgamesh/analysis/analyze.hpp"

namespace pgamesh::cli {

// One JSON object (docs/mass-properties.md fields and more; numbers %.17g; undefined values null).
std::string props_json(const Analysis& report);

// The readable report; `about_origin` adds the inertia tensor about the coordinate origin.
std::string props_text(const Analysis& report, bool about_origin);

// URDF <inertial>: origin at the centre of mass, axes of the mesh frame, tensor entries (ixy is
// the tensor's entry, −∫xy dm), with the frame and convention in an XML comment.
std::string props_urdf(const Analysis& report);

// MJCF <inertial>: pos at the centre of mass, diaginertia of the principal moments and quat of
// the principal frame (w x y z), fullinertia given in a comment.
std::string props_mjcf(const Analysis& report);

// The sentence stating the inertia convention, as printed in every output.
extern const char* const inertia_convention;

}  // namespace pgamesh::cli
