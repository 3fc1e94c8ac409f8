// Exercise 3: the end-modified basis of the multiplier space M_h^1.
#pragma once

#include <Eigen/Dense>

namespace exercise {

// For N >= 2 elements on side 1, the (N - 1) x (N + 1) matrix C with psi_i = sum_j C(i, j)
// phi^1_j: continuous P1 on the interior, constant on the two end elements.
Eigen::MatrixXd end_modified_basis(int N);

}  // namespace exercise
