// The linear solve of one Newton step of Nitsche's method or penalty (nitsche_contact.hpp):
//     (K_ff + C_ff) du = r
// on the free dofs f, where C, the contact term's derivative, changes every step but touches only
// the dofs c of the triangles along Gamma_c. Two ways:
//  - condensed (the default): K_ff is factorized once, with c ordered last (chapter 5's trick,
//    SpdSolver::factorize_with_last), so the factor's trailing block gives the Schur complement
//    S = K_cc - K_ci K_ii^{-1} K_ic, dense on Gamma_c. Then with y = K^{-1} r,
//        (S + C_cc) du_c = S y_c,    du = y - K^{-1} (C_cc du_c extended by 0),
//    two solves with the one factor and one dense factorization of |c| x |c| per step: Cholesky
//    where the matrix is symmetric and positive definite (theta = 1 with gamma0 large enough,
//    penalty), partial-pivoting LU otherwise (theta = 0, -1, or theta = 1 that lost coercivity);
//  - sparse: K_ff + C_ff assembled and factorized whole every step, CHOLMOD where symmetric
//    (LU when that fails), UMFPACK otherwise, each keeping its ordering from the first step.
//    It needs no CHOLMOD (the condensed way does) and checks the condensed one.
#pragma once

#include <Eigen/Dense>
#include <memory>
#include <string>
#include <vector>

#include "common/fem/dirichlet.hpp"
#include "common/fem/p1_elasticity.hpp"

namespace mortar {

enum class NitscheLinearSolver { condensed, sparse };

class NitscheStepSolver {
 public:
  virtual ~NitscheStepSolver() = default;
  // C as triplets in the full numbering (entries on prescribed dofs are ignored); r on the free dofs
  virtual Eigen::VectorXd solve(const std::vector<Eigen::Triplet<double>>& C, const Eigen::VectorXd& r) = 0;
  virtual std::string name() const = 0;  // the solver of the last step
  int lu_fallbacks() const { return lu_fallbacks_; }  // symmetric steps solved by LU (not positive definite)

 protected:
  int lu_fallbacks_ = 0;
};

// K_ff + C_ff, C's triplets (full numbering) restricted to the free dofs of `free`.
SparseMatrix free_block_plus(const ReducedSystem& free, const std::vector<Eigen::Triplet<double>>& C);

// `free` holds K_ff and the numbering (kept by reference: it must outlive the solver); contact
// the full dofs C can touch; symmetric: theta = 1 or penalty. The condensed way falls back to
// the sparse one without CHOLMOD, beyond 5000 contact dofs (its dense work per step would
// outgrow a sparse factorization), and where K_ff alone is singular (a body that only the
// contact holds).
std::unique_ptr<NitscheStepSolver> make_step_solver(NitscheLinearSolver kind, const ReducedSystem& free,
                                                    const std::vector<int>& contact, bool symmetric);

}  // namespace mortar
