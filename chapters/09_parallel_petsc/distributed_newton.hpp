// Step 5 of chapter 9: chapter 6's semismooth Newton method on the condensed system, each step
// one Krylov solve (KSP) instead of one Cholesky factorization.
//
// As in solve_dual_contact (common/contact/dual_condensation.cpp): guess the active set
// {i : lambda_i + c_i w_i > 0} (c_i = A_{s_i s_i}); fix w = 0 there (its rows and columns of A
// zeroed, MatZeroRowsColumns), leave w free elsewhere; solve; read lambda = (r - A v) at the
// active pivots; stop when the set repeats. The pivots' values are gathered on every rank (the
// contact line is small), so every rank takes the same decision.
//
// The linear solver is PETSc's: by default CG preconditioned by smoothed-aggregation AMG
// (GAMG) told the rigid-body modes of the two bodies (MatNullSpaceCreateRigidBody), or any
// -ksp_type / -pc_type given on the command line (MUMPS's Cholesky: -pc_type cholesky
// -pc_factor_mat_solver_type mumps).
#pragma once

#include <petscksp.h>

#include <vector>

#include "distributed_condensation.hpp"

namespace chapter09 {

struct NewtonOptions {
  double ksp_rtol = 1e-12;    // the final solve: ||residual|| <= rtol ||rhs||
  double loose_rtol = 1e-2;   // a solve while the active set still moves: ||residual|| <= rtol ||initial
                              // residual|| (an inexact Newton method); the set's repeat is solved again
                              // to ksp_rtol
  bool reuse_preconditioner = false;  // GAMG built on the first step's A, kept for every step
  int max_steps = 50;          // Krylov solves
};

struct NewtonResult {
  std::vector<double> lambda, w;  // per row of B (every rank)
  std::vector<bool> active;
  std::vector<int> ksp_iterations;  // per Krylov solve
  std::vector<bool> tight;          // per Krylov solve: to the final tolerance
  int steps = 0;                    // Newton steps: the active sets solved for, as in chapter 6
  Vec u = nullptr;  // u = T v + g, distributed
  std::string ksp_type, pc_type;  // what PETSc ran (after the command line's options)
  ~NewtonResult();
};

// The chapter's Krylov solver before the command line has its say: CG + GAMG to ||r|| <= rtol
// ||b||, then KSPSetFromOptions. Every solve of the chapter, and the trial solve that checks the
// PETSc options (petsc_options.cpp), is configured by this one function.
void configure_krylov_solver(KSP ksp, double rtol);

void solve_contact(NewtonResult& out, const DistributedSystem& s, const DistributedCondensation& c,
                   const NewtonOptions& o);

}  // namespace chapter09
