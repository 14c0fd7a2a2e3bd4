#include "props_report.hpp"

namespace pgamesh::cli {

const char* const inertia_convention =
    "inertia tensor I = integral of rho (|r|^2 1 - r r^T) dV: diagonal = moments of inertia, "
    "off-diagonal entries = minus the products of inertia (I_xy = -integral of x y dm); "
    "principal moments ascending, principal_axes row i = unit axis of moment i, right-handed, "
    "axes 1 and 2 with their largest-magnitude component positive";

}  // namespace pgamesh::cli
