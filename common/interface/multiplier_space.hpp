// The multiplier space M_h^1 on the non-mortar trace xi^1 (paper section 3): continuous P1
// on T_c^1, but only P0 (q - 1 = 0) on the two elements touching the end points a1, a2.
//
// Basis: psi_i = phi^1_i for the interior nodes i = 1 .. N-1, except that the end hats are
// folded into their neighbours, psi_1 = phi_0 + phi_1 and psi_{N-1} = phi_{N-1} + phi_N.
// Dimension N - 1 (N elements); with N = 1 the single element gets the constant psi = 1.
// Every psi_i >= 0 and sum_i psi_i = 1 on Gamma_c.
//
// For P2 bodies (chapter 7, q = 2) M_h^1 is continuous piecewise P2 on T_c^1, P1 on the two end
// elements (end_modified_p2). A P1 function on an end element is the P2 one whose midpoint value
// is the mean of its end values, so the basis is the P2 nodal functions of all nodes but the
// two end-element midpoints, each of these folded half into either neighbour:
// psi at x_0 = phi_0 + phi_1 / 2, at x_1: phi_2 + phi_1 / 2, and likewise at the other end.
// Dimension 2N - 1, the number of interior trace nodes, as for P1 (N - 1); the end points a1, a2
// now carry a multiplier of their own, and sum_i psi_i = 1 again.
//
// Chapter 6 adds a second basis of the same dimension, the dual (biorthogonal) one
// (common/interface/dual_basis.hpp), whose functions jump at the nodes. So a space also says
// what each psi_i is on each element, in the element's two local hats (the broken P1 basis):
// the one description the mortar matrices, the tested gap and the total force need. For q = 2,
// the element's three local quadratics.
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
  int degree = 1;  // q of trace 1: psi_i|_e is written in the q + 1 local functions of e
  bool continuous() const { return E.size() == 0; }
  // E for every space: for a continuous one, E(i, (q + 1) e + l) = C(i, q e + l).
  RowMajorMatrix element_coefficients() const;
  int dim() const { return static_cast<int>(C.rows()); }
  // The trace-1 node row i is solved for, its pivot: node i + 1 for psi_i, the interior nodes
  // (for P1 also the node psi_i peaks at).
  int node_of(int i) const { return C.rows() == 1 && C.cols() == 2 ? 0 : i + 1; }
};

MultiplierSpace end_modified_p1(const InterfaceTrace& trace1);
// q = 2: continuous P2, P1 on the end elements; needs N >= 2 elements.
MultiplierSpace end_modified_p2(const InterfaceTrace& trace1);
// M_h^1 of the trace's own degree: end_modified_p1 or end_modified_p2.
MultiplierSpace end_modified_space(const InterfaceTrace& trace1);

// int_{Gamma_c} f psi_i for every i, by 3-point Gauss on each element of trace 1 (exact for
// f of degree 3 or less against the linear psi_i|_e, of degree 2 or less against a quadratic).
Eigen::VectorXd integrals_against_basis(const MultiplierSpace& space, const InterfaceTrace& trace1,
                                        const std::function<double(double)>& f);

}  // namespace mortar
