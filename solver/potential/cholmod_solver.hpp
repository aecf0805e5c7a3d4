#pragma once
#include <Eigen/SparseCore>
#include "solver/potential/stencil.hpp"

namespace magnus {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, long>;

/// The symmetric matrix of the discrete system in the unknowns' layout: the lower triangle only
/// (what CHOLMOD reads), or both triangles.
SparseMatrix assemble_matrix(const DiscreteOperator& op, bool lower_only = true);

/// A fill-reducing order of the unknowns from the grid's geometry (nested dissection): the
/// periodic annulus opens along two radial lines, rectangles split across their longer side,
/// separators after the parts they separate; the outer ring (exact far field) or C last.
std::vector<long> nested_dissection(const DiscreteOperator& op);

}  // namespace magnus
