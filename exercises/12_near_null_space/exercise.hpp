// Exercise 12: the near-null space that algebraic multigrid is told, for chapter 9.
#pragma once

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <array>
#include <vector>

namespace exercise {

// The motions of a 2D elastic body that cost no strain energy, at its nodes: a matrix with one
// row per dof (node k's x and y dofs in rows 2k and 2k + 1) and one column per motion, as many
// columns as there are independent such motions of a body in the plane.
Eigen::MatrixXd rigid_body_modes(const std::vector<std::array<double, 2>>& nodes);

// The same motions in the unknowns v of a condensation u = T v (chapter 6 and 9, with g = 0):
// T is the identity except in its pivot rows, T is invertible. Returns V with T V = N.
Eigen::MatrixXd modes_in_condensed_unknowns(const Eigen::SparseMatrix<double>& T, const Eigen::MatrixXd& N);

}  // namespace exercise
