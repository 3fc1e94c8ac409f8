// Unilateral contact (paper, section 5): find u and lambda with
//
//     K u + B^T lambda = f,   B u <= G,   lambda >= 0,   lambda_i (B u - G)_i = 0,
//
// B the rows of chapter 3 or 4 (B u is the penetration [u.n] at a node, or tested with psi_i),
// G the initial gap tested the same way. Both solvers work on the multipliers alone, through
// the dual operator S = B K^{-1} B^T and the unconstrained response b = B K^{-1} f - G:
// penetration = b - S lambda. K is factorized once. A column S e_i costs one solve with K and
// is only needed once lambda_i may be nonzero, so columns are computed on demand and cached.
//  - Uzawa (a classical algorithm for such problems; the paper proves error estimates and gives
//    no solution algorithm): lambda <- max(0, lambda + rho (b - S lambda)), a projected gradient
//    step on the dual problem, convergent for 0 < rho < 2 / ||S||. It starts with
//    rho = 1 / ||S||, ||S|| from a few power iterations. Plain Uzawa then switches, once the
//    set of nonzero multipliers A has stopped changing, to rho = 2 / (lambda_max + lambda_min)
//    with lambda_min that of the block S_AA (Lanczos on its cached columns): the step that
//    makes the slowest and the fastest modes on A contract equally. A rise of the dual energy
//    sends it back to 1 / ||S|| for good.
//    With `accelerate`, Nesterov's momentum on the step 1 / ||S|| (FISTA on the dual).
//  - pdas, the primal-dual active set method (a semi-smooth Newton method): guess the active
//    set A = {i : lambda_i + c (b - S lambda)_i > 0}, solve S_AA lambda_A = b_A with
//    lambda = 0 elsewhere, repeat until A stops changing. S is no M-matrix, so A may come back
//    to a set already tried (a stiff body on a soft one): at the first repeat a primal
//    active-set method on the dual problem, which lowers the dual energy at every step and
//    so cannot cycle, finishes the solve.
// Both stop on the complementarity residual (below), never on the size of the last step.
#pragma once

#include <string>
#include <vector>

#include "common/linalg/spd_solver.hpp"

namespace mortar {

struct ContactProblem {
  SparseMatrix K;   // symmetric positive definite (the scene holds both bodies)
  Eigen::VectorXd f;
  SparseMatrix B;   // m x n
  Eigen::VectorXd G;  // m
};

enum class ContactSolverKind { uzawa, pdas };
ContactSolverKind parse_contact_solver(const std::string& name);
std::string contact_solver_name(ContactSolverKind kind);

struct ContactSolverOptions {
  ContactSolverKind kind = ContactSolverKind::pdas;
  bool accelerate = true;     // Uzawa only: Nesterov momentum
  double tol = 1e-8;          // on the complementarity residual
  double rho = 0;             // Uzawa step; 0 = chosen as above (1 / ||S||, then from both ends)
  bool step_from_both_ends = true;  // plain Uzawa, rho = 0: switch to 2 / (lambda_max + lambda_min)
  int max_iterations = 1000000;
  SpdBackend backend = fastest_spd_backend();
};

struct ContactSolution {
  Eigen::VectorXd u, lambda;
  int iterations = 0;
  int columns = 0;         // columns of S computed (one K solve each)
  double residual = 0;     // complementarity residual at the end
  double rho = 0;          // the Uzawa step used at the end
  double S_norm = 0;       // the estimate of ||B K^{-1} B^T||
  double lambda_min = 0;   // plain Uzawa: lambda_min(S_AA) estimate behind the last step (0: none)
  bool step_fell_back = false;  // plain Uzawa: the dual energy rose and rho went back to 1 / ||S||
  int cycled_at = 0;       // pdas: the iteration that met an active set again (0: none), after
                           // which the dual active-set method finished the solve
  int active_set_changes = 0;  // pdas: rows that entered or left the active set, over all steps
  std::vector<std::vector<int>> active_history;  // pdas: the rows each Newton step held active
};

// The complementarity residual, dimensionless:
//   max_i | min(lambda_i / lambda_scale, d_i / d_scale) |,   d = G - B u (the remaining gap),
// with d_scale = max_i b_i^+ (the largest penetration of the unconstrained bodies; max_i |b_i|
// when nothing penetrates) and lambda_scale = d_scale / ||S||.
// It is zero exactly when lambda >= 0, d >= 0 and lambda_i d_i = 0 for every i.
double complementarity_residual(const Eigen::VectorXd& lambda, const Eigen::VectorXd& gap,
                                double d_scale, double lambda_scale);

// Throws std::runtime_error when Uzawa diverges (rho too large) or a method fails to converge
// within max_iterations; the message gives the residual reached.
ContactSolution solve_contact(const ContactProblem& problem, const ContactSolverOptions& options);

}  // namespace mortar
