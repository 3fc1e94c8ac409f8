// Exercise 2: the mixed mass matrix of two grids, computed on their merged grid.
#pragma once

#include <Eigen/Dense>
#include <vector>

namespace exercise {

// P(j, k) = int phi^1_j phi^2_k for the P1 hats of the sorted grids x1 (rows) and x2 (columns),
// integrated where both grids are: over [max(x1.front(), x2.front()), min(x1.back(), x2.back())],
// the whole of Gamma_c when they share their end points, the zero matrix when they do not
// overlap. With psi = C phi^1 (exercise 3), the mortar matrix is M = C P.
Eigen::MatrixXd mixed_mass(const std::vector<double>& x1, const std::vector<double>& x2);

}  // namespace exercise
