// Contact with a dual multiplier basis (chapter 6): D diagonal, so each constraint row can be
// solved for its own unknown, and the multipliers leave the linear algebra.
//
// Row i of B (integral matching, a dual basis) is  b_i u_{s_i} + (B_r u)_i, with b_i = +-D_ii
// on the non-mortar normal dof s_i of psi_i's node, and B_r on dofs that are no pivot (the
// mortar normals, the non-mortar end nodes). Take the weighted gap w_i = (B u - G)_i as the
// unknown in place of u_{s_i}:
//
//     u_{s_i} = (G_i + w_i - (B_r u)_i) / b_i,     u = T v + g,   v = (u_r, w),
//
// a change of unknowns node by node, which keeps K's symmetry: A = T^T K T, r = T^T (f - K g)
// (Hueber and Wohlmuth 2005, with the weighted gap). A has K's pattern plus couplings next to
// the contact line, the same for every active set. Then
//  - bilateral contact (B u = G) is w = 0: the rows and columns of w become identity rows, and
//    A is the SPD matrix of the displacements alone, condensed (paper (8) without lambda);
//  - unilateral contact (B u <= G) is w <= 0, lambda >= 0, lambda_i w_i = 0, and
//    lambda = (r - A v)_w, read node by node, with no solve. The semismooth Newton method
//    (primal-dual active set) guesses A = {i : lambda_i + c_i w_i > 0} (c_i = A_{s_i s_i}),
//    sets w_A = 0, leaves w free elsewhere (where lambda = 0), solves, and repeats until the
//    set stops changing. Every step is one SPD solve whose matrix has the same pattern: the
//    analysis (ordering, symbolic factor) is done once, each step refactorizes numerically.
#pragma once

#include <vector>

#include "common/contact/saddle_point.hpp"
#include "common/linalg/spd_solver.hpp"

namespace mortar {

struct CondensedContact {
  std::vector<int> pivots;  // s_i, a free dof per row
  Eigen::VectorXd b;        // B(i, s_i)
  Eigen::SparseMatrix<double, Eigen::RowMajor> Z;  // m x n: row i is row s_i of T (1/b_i at s_i)
  Eigen::VectorXd g;        // n: G_i / b_i at s_i, zero elsewhere
  SparseMatrix A;           // T^T K T, both triangles stored
  Eigen::VectorXd rhs;      // T^T (f - K g)
  double dropped_max = 0;   // largest |B(i, s_k)| / |b_i|, k != i, treated as zero

  int rows() const { return static_cast<int>(pivots.size()); }
  Eigen::VectorXd displacement(const Eigen::VectorXd& v) const;  // u = T v + g
  Eigen::VectorXd weighted_gap(const Eigen::VectorXd& v) const;   // w = v at the pivots
};

// T, A and r from the problem on the free dofs (K, f, B, G and the pivots of
// reduce_to_free_dofs). B must be diagonal on the pivot columns: entries there off row i
// below 1e-10 |b_i| (round-off of the quadrature) are dropped and their largest size kept in
// dropped_max; anything larger is refused (the basis is not dual).
CondensedContact condense_contact(const SaddlePointProblem& p);
// New loads on the same rows (a load path): g and r = T^T (f - K g) again from the free-dof K,
// f and G; T, Z and A = T^T K T are kept, since neither depends on the loads.
void update_condensed_loads(CondensedContact& c, const SparseMatrix& K, const Eigen::VectorXd& f,
                            const Eigen::VectorXd& G);

struct DualContactOptions {
  bool unilateral = true;      // false: bilateral, w = 0 everywhere
  int max_iterations = 100;
  std::vector<bool> initial_active;  // empty: none active (the first step is the free bodies)
  SpdBackend backend = fastest_spd_backend();
};

struct DualContactSolution {
  Eigen::VectorXd u, lambda, w;  // free dofs; multipliers and weighted gaps per row
  std::vector<bool> active;
  int iterations = 0;            // solves (each one numerical factorization)
  double residual = 0;           // complementarity residual (contact_solvers.hpp) at the end
  std::vector<int> active_sizes;  // |A| of each step
  int active_set_changes = 0;     // rows that entered or left A, over all steps
  std::vector<std::vector<int>> active_history;  // the rows of A in each step, in order
};

// Throws std::runtime_error when the active set has not settled within max_iterations.
DualContactSolution solve_dual_contact(CondensedContact& c, const DualContactOptions& options);

}  // namespace mortar
