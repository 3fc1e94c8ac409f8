// Exercise 10: the end-modified P2 basis of the multiplier space M_h^1 (chapter 7, q = 2).
#pragma once

#include <Eigen/Dense>

#include "common/interface/interface_trace.hpp"

namespace exercise {

// For a P2 trace of N >= 2 elements (2N + 1 nodes: node 2e is x_e, node 2e + 1 the midpoint of
// element e), the matrix C with psi_r = sum_j C(r, j) phi^1_j, 2N + 1 columns, one row per basis
// function, of the multiplier space: continuous P2 on Gamma_c, P1 on the first element when
// linear_first and on the last when linear_last (the end elements that touch a crosspoint a_1,
// a_2 in the paper's M_h^1; an end of Gamma_c that is no crosspoint keeps full P2 there). The
// basis is the nodal one of the nodes whose values stay free, in order along Gamma_c. Throws
// std::invalid_argument for a trace of degree other than 2 or of fewer than 2 elements.
Eigen::MatrixXd p2_multiplier_basis(const mortar::InterfaceTrace& trace1, bool linear_first, bool linear_last);

}  // namespace exercise
