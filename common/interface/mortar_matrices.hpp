// The mortar matrices of two traces (paper section 3, space V_h^I):
//   D_ij = int_{Gamma_c} psi_i phi^1_j,    M_ik = int_{Gamma_c} psi_i phi^2_k,
// integrated exactly on the merged grid (2-point Gauss per merged segment).
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

MortarMatrices mortar_matrices(const InterfaceTrace& trace1, const InterfaceTrace& trace2,
                               const MergedGrid& grid, const MultiplierSpace& space);

}  // namespace mortar
