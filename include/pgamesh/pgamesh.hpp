// Every public header of pgamesh, layer by layer (docs/architecture.md). Include the headers you
// use for faster builds; this one is for a quick start.
#pragma once

// core
#include "pgamesh/core/bounding_box.hpp"
#include "pgamesh/core/input_error.hpp"
#include "pgamesh/core/mesh.hpp"
#include "pgamesh/core/number_text.hpp"
#include "pgamesh/core/vec3.hpp"

// algebra
#include "pgamesh/algebra/clifford.hpp"
#include "pgamesh/algebra/clifford/algebra.hpp"
#include "pgamesh/algebra/clifford/blade.hpp"
#include "pgamesh/algebra/clifford/closed_forms.hpp"
#include "pgamesh/algebra/clifford/divided_differences.hpp"
#include "pgamesh/algebra/clifford/multivector.hpp"
#include "pgamesh/algebra/clifford/products.hpp"
#include "pgamesh/algebra/clifford/real_roots.hpp"
#include "pgamesh/algebra/graded.hpp"
#include "pgamesh/algebra/graded/algebra.hpp"
#include "pgamesh/algebra/graded/convert.hpp"
#include "pgamesh/algebra/graded/multivector.hpp"
#include "pgamesh/algebra/graded/products.hpp"
#include "pgamesh/algebra/pga3.hpp"
#include "pgamesh/algebra/pga3/convert.hpp"
#include "pgamesh/algebra/pga3/exp_log.hpp"
#include "pgamesh/algebra/pga3/grades.hpp"
#include "pgamesh/algebra/pga3/join.hpp"
#include "pgamesh/algebra/pga3/linear.hpp"
#include "pgamesh/algebra/pga3/metric.hpp"
#include "pgamesh/algebra/pga3/motor.hpp"
#include "pgamesh/algebra/pga3/multivector.hpp"
#include "pgamesh/algebra/pga3/norm.hpp"
#include "pgamesh/algebra/pga3/products.hpp"
#include "pgamesh/algebra/pga3/quaternion.hpp"
#include "pgamesh/algebra/pgad.hpp"

// models
#include "pgamesh/models/cga.hpp"
#include "pgamesh/models/cga_algebra.hpp"
#include "pgamesh/models/cga_extract.hpp"
#include "pgamesh/models/cga_fit.hpp"
#include "pgamesh/models/cga_motor.hpp"
#include "pgamesh/models/cga_objects.hpp"
#include "pgamesh/models/cga_point.hpp"
#include "pgamesh/models/dcga.hpp"
#include "pgamesh/models/dpga.hpp"
#include "pgamesh/models/model_error.hpp"
#include "pgamesh/models/qcga.hpp"
#include "pgamesh/models/quadric.hpp"
#include "pgamesh/models/quadric_convert.hpp"

// geometry
#include "pgamesh/geometry/body_moments.hpp"
#include "pgamesh/geometry/carrier.hpp"
#include "pgamesh/geometry/complex.hpp"
#include "pgamesh/geometry/edge_loop.hpp"
#include "pgamesh/geometry/face_sums.hpp"
#include "pgamesh/geometry/gap.hpp"
#include "pgamesh/geometry/inertia_frame.hpp"
#include "pgamesh/geometry/polygon2d.hpp"
#include "pgamesh/geometry/polygon_face.hpp"
#include "pgamesh/geometry/reference_point.hpp"
#include "pgamesh/geometry/simplex.hpp"

// io
#include "pgamesh/io/mapped_file.hpp"
#include "pgamesh/io/mesh_format.hpp"
#include "pgamesh/io/read_mesh.hpp"
#include "pgamesh/io/write_file.hpp"
#include "pgamesh/io/write_mesh.hpp"

// mesh
#include "pgamesh/mesh/mass/mass_properties.hpp"
#include "pgamesh/mesh/primitives.hpp"
#include "pgamesh/mesh/topology/boundary_loops.hpp"
#include "pgamesh/mesh/topology/components.hpp"
#include "pgamesh/mesh/topology/edges.hpp"
#include "pgamesh/mesh/topology/orientation.hpp"
#include "pgamesh/mesh/topology/shell_nesting.hpp"
#include "pgamesh/mesh/topology/topology.hpp"
#include "pgamesh/mesh/weld/weld.hpp"

// analysis
#include "pgamesh/analysis/analyze.hpp"

// tank
#include "pgamesh/tank/attitude.hpp"
#include "pgamesh/tank/free_surface.hpp"
#include "pgamesh/tank/fuel_index.hpp"
#include "pgamesh/tank/fuel_plane.hpp"
#include "pgamesh/tank/fuel_state.hpp"
#include "pgamesh/tank/fuel_sweep.hpp"
#include "pgamesh/tank/inverse_level.hpp"
#include "pgamesh/tank/slice.hpp"
#include "pgamesh/tank/tank.hpp"
