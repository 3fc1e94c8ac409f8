// The multiplier space M_h^1 on the non-mortar trace xi^1 (paper section 3): continuous P1
// on T_c^1, but only P0 (q - 1 = 0) on the two elements touching the end points a1, a2.
//
// Basis: psi_i = phi^1_i for the interior nodes i = 1 .. N-1, except that the end hats are
// folded into their neighbours, psi_1 = phi_0 + phi_1 and psi_{N-1} = phi_{N-1} + phi_N.
// Dimension N - 1 (N elements); with N = 1 the single element gets the constant psi = 1.
// Every psi_i >= 0 and sum_i psi_i = 1 on Gamma_c.
//
// Chapter 6 adds a second basis of the same dimension, the dual (biorthogonal) one
// (common/interface/dual_basis.hpp), whose functions jump at the nodes. So a space also says
// what each psi_i is on each element, in the element's two local hats (the broken P1 basis):
// the one description the mortar matrices, the tested gap and the total force need.
#pragma once

#include <Eigen/Sparse>
#include <functional>

#include "common/interface/interface_trace.hpp"

namespace mortar {

using RowMajorMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

struct MultiplierSpace {
  // psi_i = sum_j C(i, j) phi^1_j: rows are multipliers, columns the nodes of trace 1. For the
  // dual basis, C holds the hats of M_h^1 on the same nodes: they read the coefficients
  // lambda_i as nodal values of a continuous curve (what contact_pressure draws).
  RowMajorMatrix C;
  // Discontinuous bases only (empty otherwise): psi_i on element e of trace 1 is
  // sum_{l = 0, 1} E(i, 2e + l) phi^1_{e+l}, the two local hats of e.
  RowMajorMatrix E;
  bool continuous() const { return E.size() == 0; }
  // E for every space: for a continuous one, E(i, 2e + l) = C(i, e + l).
  RowMajorMatrix element_coefficients() const;
  int dim() const { return static_cast<int>(C.rows()); }
  // The trace-1 node each multiplier sits on (node i + 1 for psi_i, the interior nodes).
  int node_of(int i) const { return C.rows() == 1 && C.cols() == 2 ? 0 : i + 1; }
};

MultiplierSpace end_modified_p1(const InterfaceTrace& trace1);

// int_{Gamma_c} f psi_i for every i, by 3-point Gauss on each element of trace 1 (exact for
// f of degree 3 or less against the linear psi_i|_e).
Eigen::VectorXd integrals_against_basis(const MultiplierSpace& space, const InterfaceTrace& trace1,
                                        const std::function<double(double)>& f);

}  // namespace mortar
