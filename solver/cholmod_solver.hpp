#pragma once
#include <Eigen/SparseCore>
#include "solver/stencil.hpp"

namespace magnus {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, long>;

/// The symmetric matrix of the discrete system in the unknowns' layout: the lower triangle only
/// (what CHOLMOD reads), or both triangles.
SparseMatrix assemble_matrix(const DiscreteOperator& op, bool lower_only = true);

}  // namespace magnus
