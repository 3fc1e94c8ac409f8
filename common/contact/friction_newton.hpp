// Frictional contact with a dual basis (chapter 8): chapter 6's condensation applied to the
// normal and the tangential rows at once, and a semismooth Newton method on the nodal
// conditions of friction_conditions.hpp.
//
// Node i of the non-mortar trace has two rows, B_n (weighted gap) and B_t (weighted slip), and
// two pivots, its y dof and its x dof. condense_contact takes the stacked rows [B_n; B_t] and
// replaces both pivots by w_n and w_t: u = T v + g, A = T^T K T, r = T^T (f - K g), and the
// multipliers are read node by node, (lambda_n, lambda_t)_i = (r - A v) at the two pivots.
// Equilibrium holds in every other row of A v = r; the pivot rows carry the nodal equations
// C_n = 0 and C_t = 0 instead, linearized at the current point:
//
//   grad C . (lambda_n, w_n, lambda_t, dw_t)^+ = grad C . (lambda_n, w_n, lambda_t, dw_t) - C,
//
// with lambda^+ = (r - A v^+) at the pivots: one sparse row per equation. Three kinds of row:
//  - a prescribed value (contact: w_n = 0; Tresca stick: dw_t = 0): v_p known, its column
//    moves to the right-hand side, the matrix stays symmetric;
//  - a row of A (open node: lambda = 0; Tresca slip: lambda_t = s z / |z|), symmetric, perhaps
//    with a shift of its diagonal;
//  - a coupled row (Coulomb slip: lambda_t = F lambda_n z / |z|, or Coulomb stick away from its
//    fixed point): the tangential row of node i holds a multiple of the normal row of A, and
//    no row holds the transpose. The matrix is then nonsymmetric: one sparse LU (UMFPACK).
// A step whose rows are of the first two kinds only is solved by Cholesky (CHOLMOD), as in
// chapter 6; a symmetric matrix that is not positive definite (a negative shift) falls back to
// the LU. The method stops when max |C_n| / Lambda and max |C_t| / Lambda^2 (Lambda the
// largest multiplier, or c times the largest weighted gap or slip) fall below the tolerance.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "common/contact/dual_condensation.hpp"
#include "common/contact/friction_conditions.hpp"
#include "common/linalg/sparse_lu.hpp"

namespace mortar {

// The normal problem p (rows B_n u <= G) and the tangential rows t (same nodes, same order, on
// the x dofs; their G is the slip offset, zero) as one problem: B = [B_n; B_t], pivots
// [y pivots; x pivots]. Throws when the two sets of rows are not on the same nodes.
SaddlePointProblem stack_frictional_rows(const SaddlePointProblem& p, const SaddlePointProblem& t);

// The factorizations of the Newton matrices: Cholesky (CHOLMOD) while a step's rows keep A's
// symmetry, sparse LU (UMFPACK) when a Coulomb row breaks it or the symmetric matrix is not
// positive definite (a negative shift of a slip row). The Newton matrix of a condensed problem
// always has the same pattern (explicit zeros hold unused places), so each keeps its analysis
// from one Newton step to the next, and, passed through FrictionOptions, from one load step to
// the next.
class FrictionFactorizations {
 public:
  explicit FrictionFactorizations(SpdBackend backend = fastest_spd_backend()) : spd_(backend) {}
  // Solves J v = b; counts the LU solves in lu_steps.
  Eigen::VectorXd solve(const SparseMatrix& J, const Eigen::VectorXd& b, bool symmetric, int& lu_steps);

 private:
  SpdSolver spd_;
  bool spd_ready_ = false;
  SparseLu lu_;
};

struct FrictionOptions {
  FrictionLaw law = FrictionLaw::coulomb;
  double friction = 0;               // F
  Eigen::VectorXd threshold;         // Tresca's s per node (law tresca)
  Eigen::VectorXd previous_slip;     // w_t at the end of the last load step (empty: zero)
  std::vector<NodalUnknowns> start;  // the point of the first linearization (empty: all zero)
  Eigen::VectorXd fixed_point_start;  // s^0 of solve_coulomb_by_fixed_point (empty: no slip)
  bool bounded_gradient = true;      // friction_conditions.hpp, tangential_gradient
  int max_steps = 50;
  double tolerance = 1e-12;
  SpdBackend backend = fastest_spd_backend();
  // Kept between calls on the same condensed problem (the load steps of a level); empty: one
  // for this call.
  std::shared_ptr<FrictionFactorizations> factorizations;
};

struct FrictionSolution {
  Eigen::VectorXd u;  // free dofs
  std::vector<NodalUnknowns> nodes;  // per node at the end (dw_t against previous_slip)
  Eigen::VectorXd lambda_n, lambda_t, w_n, w_t;
  std::vector<NodeStatus> status;
  int steps = 0;                  // Newton steps (solves)
  int lu_steps = 0;               // of which nonsymmetric (sparse LU)
  int restarts = 0;               // 1: restarted from the no-slip solution (friction_newton.cpp)
  std::vector<double> residuals;  // after each step
  std::vector<int> stick, slip;   // node counts after each step
};

// The nodal unknowns of node i (of c's m / 2) at v.
NodalUnknowns nodal_unknowns(const CondensedContact& c, const Eigen::VectorXd& v, int node, double previous_slip);

// When the Newton steps from the start cycle between statuses, stall for ten steps or reach
// max_steps, the method starts again from the solution of the same loads with no slip allowed
// (friction_newton.cpp). Throws std::runtime_error, in one line naming the last residual and
// the statuses, when that fails too: the discrete problem has then several solutions between
// which the steps cycle (Coulomb with a large F), or none (a load friction cannot hold).
FrictionSolution solve_frictional_contact(const CondensedContact& c, const FrictionOptions& options);

// Coulomb as a sequence of Tresca problems (the older method, for comparison): s^{k+1} =
// F max(0, lambda_n^k), from s^0 = options.fixed_point_start, or infinite thresholds (no slip)
// when it is empty, until the thresholds change by less than tolerance x max s: a relative
// change, so that the answer does not depend on the unit of the multipliers. Each Tresca
// problem is solved by the Newton method above. (Frictionless, s^0 = 0, would leave a body that
// friction alone holds free to slide in the first problem.)
struct FixedPointSolution {
  FrictionSolution last;
  int outer = 0;        // Tresca problems solved
  int total_steps = 0;  // Newton steps over all of them
  std::vector<double> threshold_changes;
};
FixedPointSolution solve_coulomb_by_fixed_point(const CondensedContact& c, const FrictionOptions& options,
                                                int max_outer = 100, double tolerance = 1e-10);

}  // namespace mortar
