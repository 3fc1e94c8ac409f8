// Exercise 3: the end-modified basis of the multiplier space M_h^1.
#pragma once

#include <Eigen/Dense>

namespace exercise {

// For a P1 non-mortar trace of N >= 1 elements (nodes 0 .. N), the matrix C with
// psi_r = sum_j C(r, j) phi^1_j, N + 1 columns, one row per basis function, of the multiplier
// space: continuous P1 on Gamma_c, constant on the first element when constant_first and on the
// last when constant_last (the end elements that touch a crosspoint a_1, a_2 in the paper's
// M_h^1; an end of Gamma_c that is no crosspoint keeps P1 there). The basis is the nodal one of
// the free nodal values, in order along Gamma_c. Throws std::invalid_argument for N < 1.
Eigen::MatrixXd end_modified_basis(int N, bool constant_first, bool constant_last);

}  // namespace exercise
