// Small dense symmetric eigen-solver for the quadric layer (3×3, 4×4, 10×10): cyclic Jacobi.
#pragma once

#include <cstddef>
#include <vector>

namespace pgamesh::quadric::detail {

// Eigen-decomposition of the symmetric n×n matrix a (row-major, only read). values ascend;
// vectors[k*n + r] is component r of the unit eigenvector of values[k].
struct SymmetricEigen {
  std::vector<double> values;
  std::vector<double> vectors;
};
SymmetricEigen symmetric_eigen(const std::vector<double>& a, std::size_t n);

}  // namespace pgamesh::quadric::detail
