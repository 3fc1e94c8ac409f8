// The mortar matrices of two traces (paper section 3, space V_h^I):
//   D_ij = int_{Gamma_c} psi_i phi^1_j,    M_ik = int_{Gamma_c} psi_i phi^2_k,
// integrated exactly on the merged grid. On a merged segment psi_i, phi^1_j and phi^2_k are
// each one polynomial of degree q, so the products have degree 2q and Gauss-Legendre with
// q + 1 points (exact to degree 2q + 1) integrates them exactly: 2 points for P1, 3 for P2.
#pragma once

#include <Eigen/Sparse>

#include "common/interface/interface_trace.hpp"
#include "common/interface/merged_grid.hpp"
#include "common/interface/multiplier_space.hpp"

namespace mortar {

struct MortarMatrices {
  Eigen::SparseMatrix<double, Eigen::RowMajor> D;  // dim(M_h) x nodes of trace 1
  Eigen::SparseMatrix<double, Eigen::RowMajor> M;  // dim(M_h) x nodes of trace 2
};

// The points of the rule above for traces of degrees q1 and q2: ceil((2 max(q1, q2) + 1) / 2).
int mortar_gauss_points(int degree1, int degree2);

MortarMatrices mortar_matrices(const InterfaceTrace& trace1, const InterfaceTrace& trace2,
                               const MergedGrid& grid, const MultiplierSpace& space);

}  // namespace mortar
