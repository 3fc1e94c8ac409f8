// The multiplier space M_h^1 on the non-mortar trace xi^1 (paper section 3): continuous P1
// on T_c^1, but only P0 (q - 1 = 0) on the two elements touching the end points a1, a2.
//
// Basis: psi_i = phi^1_i for the interior nodes i = 1 .. N-1, except that the end hats are
// folded into their neighbours, psi_1 = phi_0 + phi_1 and psi_{N-1} = phi_{N-1} + phi_N.
// Dimension N - 1 (N elements); with N = 1 the single element gets the constant psi = 1.
// Every psi_i >= 0 and sum_i psi_i = 1 on Gamma_c.
#pragma once

#include <Eigen/Sparse>

#include "common/interface/interface_trace.hpp"

namespace mortar {

struct MultiplierSpace {
  // psi_i = sum_j C(i, j) phi^1_j: rows are multipliers, columns the nodes of trace 1.
  Eigen::SparseMatrix<double, Eigen::RowMajor> C;
  int dim() const { return static_cast<int>(C.rows()); }
  // The trace-1 node each multiplier sits on (node i + 1 for psi_i, the interior nodes).
  int node_of(int i) const { return C.rows() == 1 && C.cols() == 2 ? 0 : i + 1; }
};

MultiplierSpace end_modified_p1(const InterfaceTrace& trace1);

}  // namespace mortar
