// The tank tests read golden and shared OBJ meshes with the test support's plain OBJ reader
// (load_obj_file, load_golden_obj), independent of pgamesh's readers.
#pragma once

#include "support/golden_mesh.hpp"
