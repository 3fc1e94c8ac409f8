// Step 5 of chapter 9: chapter 6's semismooth Newton method on the condensed system, each step
// one Krylov solve (condensed_solver.hpp) instead of one Cholesky factorization.
//
// As in solve_dual_contact (common/contact/dual_condensation.cpp): guess the active set
// {i : lambda_i + c_i w_i > 0} (c_i = A_{s_i s_i}); fix w = 0 there, leave w free elsewhere;
// solve; read lambda = (r - A v) at the active pivots; stop when the set repeats. The pivots'
// values are gathered on every rank (the contact line is small), so every rank takes the same
// decision.
//
// An inexact Newton method: while the active set still moves, a solve only has to tell the next
// set, so it reduces its own initial residual by loose_rtol and starts from the last v. When a
// set repeats it is solved again to ksp_rtol, and the method stops when a set repeats after
// such a solve; after the first tight solve every solve is tight.
#pragma once

#include <petscksp.h>

#include <string>
#include <vector>

#include "distributed_condensation.hpp"

namespace chapter09 {

struct NewtonOptions {
  double ksp_rtol = 1e-13;    // the final solve: ||B residual|| <= rtol ||B rhs||
  double loose_rtol = 1e-2;   // a solve while the set moves: rtol times its initial residual
  int max_solves = 50;
  bool bilateral = false;     // w = 0 at every node: one solve, lambda of either sign
  // alpha of glued_stiffness.hpp: multigrid built on K glued along the first active set, when
  // that set is not empty; 0: on K itself
  double glue_weight = 3;
};

// A first guess (nested_start.hpp): u on this level's rows, and a multiplier for each row of B.
// The first active set is chapter 6's rule evaluated on it: lambda_i + c_i w_i > 0.
struct NewtonStart {
  Vec u = nullptr;
  std::vector<double> lambda;
  NewtonStart() = default;
  NewtonStart(const NewtonStart&) = delete;
  NewtonStart& operator=(const NewtonStart&) = delete;
  ~NewtonStart();
};

struct NewtonResult {
  std::vector<double> lambda, w;  // per row of B (every rank)
  std::vector<bool> active;
  std::vector<int> ksp_iterations;  // per Krylov solve
  std::vector<bool> tight;          // per Krylov solve: to the final tolerance
  int steps = 0;                    // Newton steps: the active sets solved for, as in chapter 6
  double setup_s = 0;               // building the preconditioner once: K_P (if glued) and GAMG
  int pc_setups = 0;                // times it was built (CondensedSolver::setups)
  int first_active = 0, last_active = 0;  // |A| guessed first and found
  Vec u = nullptr;                  // u = T v + g, distributed
  std::string ksp_type, pc_type;    // what PETSc ran (after the command line's options)
  ~NewtonResult();
};

// From v = 0 and no node active (start = nullptr), or from the start.
void solve_contact(NewtonResult& out, const DistributedSystem& s, const DistributedCondensation& c,
                   const NewtonOptions& o, const NewtonStart* start = nullptr);

}  // namespace chapter09
