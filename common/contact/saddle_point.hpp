// Saddle-point systems of bilateral contact (paper eq. (8) with the constraints as rows of B):
//
//     [ K  B^T ] [ u      ]   [ f ]
//     [ B  0   ] [ lambda ] = [ G ],
//
// K symmetric positive semidefinite (each body's stiffness, Dirichlet dofs eliminated), B the
// constraint rows, lambda the multipliers (contact forces). Two ways to solve it:
//  - lu: one sparse LU of the whole matrix (UMFPACK when available, Eigen's SparseLU
//    otherwise). Nothing to explain beyond the matrix itself: the readable reference.
//  - elimination: every row of B is solved for one "pivot" unknown (the non-mortar normal
//    dof at the row's node), u_s = B_s^{-1} (G - B_r u_r). Substituting u = T u_r + g leaves
//    T^T K T u_r = T^T (f - K g), symmetric positive definite, for one sparse Cholesky; then
//    lambda = B_s^{-T} (f - K u)_s. This is the space V_h written with a basis.
//  - schur: the multipliers first. K u = f - B^T lambda gives B u = B K^{-1} f - S lambda, so
//    S lambda = B K^{-1} f - G with S = B K^{-1} B^T, read off the factor of K with the contact
//    unknowns last (linalg/dual_schur.hpp); then u = K^{-1} (f - B^T lambda). Chapter 5's
//    solvers work this way. K itself must be SPD: a body held only through the constraints (the
//    patch test) is refused.
#pragma once

#include <string>
#include <vector>

#include "common/contact/constraints.hpp"
#include "common/fem/dirichlet.hpp"
#include "common/linalg/spd_solver.hpp"

namespace mortar {

struct SaddlePointProblem {
  SparseMatrix K;
  Eigen::VectorXd f;
  SparseMatrix B;
  Eigen::VectorXd G;
  std::vector<int> pivots;  // for elimination: the unknown each row is solved for
};

struct SaddlePointSolution {
  Eigen::VectorXd u;
  Eigen::VectorXd lambda;
};

enum class SaddleSolver { lu, elimination, schur };
SaddleSolver parse_saddle_solver(const std::string& name);
std::string saddle_solver_name(SaddleSolver s);

// The saddle-point problem on the free dofs: B's columns restricted to them, and the
// prescribed values moved to the right-hand side, G_free = G - B u_d.
SaddlePointProblem reduce_to_free_dofs(const ReducedSystem& system, const Constraints& c,
                                       const Eigen::VectorXd& G);

SaddlePointSolution solve_saddle_point(const SaddlePointProblem& p, SaddleSolver solver,
                                       SpdBackend backend = fastest_spd_backend());
SaddlePointSolution solve_saddle_point_lu(const SaddlePointProblem& p);
SaddlePointSolution solve_by_elimination(const SaddlePointProblem& p, SpdBackend backend);
SaddlePointSolution solve_by_dual_schur(const SaddlePointProblem& p, SpdBackend backend);

}  // namespace mortar
