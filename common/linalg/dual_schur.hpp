// The dual Schur complement S = B K^{-1} B^T of a constraint matrix B whose columns touch few
// unknowns (the normal dofs on Gamma_c), read off the factor of K instead of one solve per
// column (chapter 5's notes, "S as a Schur complement on the contact line"):
//
//   factorize K with those unknowns c last:  L_cc L_cc^T = K_cc - K_ci K_ii^{-1} K_ic,
//   so (K^{-1})_cc = L_cc^{-T} L_cc^{-1}  and  S = W^T W,  W = L_cc^{-1} B_c^T.
//
// Dense work of the size of the contact line (|c| x m), none of the size of the mesh.
#pragma once

#include <vector>

#include "common/linalg/spd_solver.hpp"

namespace mortar {

// The unknowns B touches (columns with a nonzero), in increasing order.
std::vector<int> touched_unknowns(const SparseMatrix& B);

// Factorizes K for S: with CHOLMOD the touched unknowns of B last, else plainly.
void factorize_for_dual_schur(SpdSolver& solver, const SparseMatrix& K, const SparseMatrix& B);

// S = B K^{-1} B^T, m x m, both triangles. With CHOLMOD from the trailing factor (after
// factorize_for_dual_schur); otherwise one solve per column, 64 right-hand sides at a time.
Eigen::MatrixXd dual_schur_complement(const SpdSolver& solver, const SparseMatrix& B);

}  // namespace mortar
