#include "exercise.hpp"

#include <stdexcept>
#include <string>

namespace exercise {

Eigen::MatrixXd p2_multiplier_basis(const mortar::InterfaceTrace& trace1) {
  const int N = trace1.num_elements();
  // N = 1: the one element touches both a1 and a2, so M_h^1 is P1 there, of dimension 2, but
  // there is a single interior node (its midpoint) to solve for: the count 2N - 1 fails.
  if (trace1.degree != 2 || N < 2)
    throw std::invalid_argument("p2_multiplier_basis: needs a P2 trace of at least 2 elements, got degree " +
                                std::to_string(trace1.degree) + " with " + std::to_string(N));
  const int rows = 2 * N - 1;
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(rows, 2 * N + 1);
  // kept nodes in order along Gamma_c: x_0 = node 0, then nodes 2 .. 2N - 2, then x_N = node 2N
  C(0, 0) = 1.0;
  for (int r = 1; r <= rows - 2; ++r) C(r, r + 1) = 1.0;
  C(rows - 1, 2 * N) = 1.0;
  // P1 on an end element: its midpoint value is the mean of its end values, so phi_1 goes half
  // to psi_0 (node 0) and half to psi_1 (node 2); phi_{2N-1} likewise at the other end. For
  // N = 2, psi_1 takes both halves.
  C(0, 1) += 0.5;
  C(1, 1) += 0.5;
  C(rows - 2, 2 * N - 1) += 0.5;
  C(rows - 1, 2 * N - 1) += 0.5;
  return C;
}

// The two questions of the statement.
// 1. Why sum_r psi_r = 1: every column of C sums to one (a kept node's 1 in its own row, a
//    folded midpoint's two halves), so sum_r psi_r = sum_j phi_j, and the P2 nodal functions
//    add up to one. The constant 1 is in M_h^1 (it is linear on the end elements), which is
//    what keeps int w under the mortar projection and lets the patch test pass.
// 2. N = 1: the element holding a1 is the one holding a2. M_h^1 is then P1 on it, of dimension
//    2, while 2N - 1 = 1: the trace has one interior node, the midpoint, and that is exactly the
//    node folded away. There is no square block of D (one row per multiplier, one column per
//    interior node) to solve with, and the recipe's rows 0, 1 and 2N - 3, 2N - 2 fall outside
//    a one-row C. The library refuses, and so does this function.

}  // namespace exercise
