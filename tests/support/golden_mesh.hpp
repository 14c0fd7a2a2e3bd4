// The mesh of a golden/mesh_props.json case: inline vertices and faces, or a golden OBJ file read
// here by a plain line reader (independent of pgamesh's readers, so reader bugs cannot hide in
// the references), with the case's `remove_faces` dropped.
#pragma once

#include <string>

#include "pgamesh/core/mesh.hpp"
#include "support/golden.hpp"

namespace pgamesh::test {

// Reads a plain OBJ file: "v x y z" and "f i j k …" lines (1-based; i/t/n corners keep i); other
// lines are ignored. The golden OBJ files hold exact float64 text.
Mesh load_obj_file(const std::string& path);

// load_obj_file of PGAMESH_GOLDEN_DIR/relative.
Mesh load_golden_obj(const std::string& relative);

// The mesh described by a case's "input" object.
Mesh golden_case_mesh(const json& input);

}  // namespace pgamesh::test
