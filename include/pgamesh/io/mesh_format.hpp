// Names of the mesh file formats, as printed in outputs and accepted by --format.
#pragma once

#include "pgamesh/core/mesh.hpp"

namespace pgamesh {

const char* format_name(MeshFormat f);

}  // namespace pgamesh
