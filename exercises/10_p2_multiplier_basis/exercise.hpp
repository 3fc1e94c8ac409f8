// Exercise 10: the end-modified P2 basis of the multiplier space M_h^1 (chapter 7, q = 2).
#pragma once

#include <Eigen/Dense>

#include "common/interface/interface_trace.hpp"

namespace exercise {

// For a P2 trace of N >= 2 elements (2N + 1 nodes: node 2e is x_e, node 2e + 1 the midpoint of
// element e), the (2N - 1) x (2N + 1) matrix C with psi_r = sum_j C(r, j) phi^1_j: continuous
// P2 on Gamma_c, P1 on the two end elements, one row per node other than the two end-element
// midpoints, in order along Gamma_c. Throws std::invalid_argument for a trace of degree other
// than 2 or of fewer than 2 elements.
Eigen::MatrixXd p2_multiplier_basis(const mortar::InterfaceTrace& trace1);

}  // namespace exercise
