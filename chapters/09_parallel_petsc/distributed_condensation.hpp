// Step 4 of chapter 9: chapter 6's condensation on the distributed matrix.
//
// The contact line is one-dimensional and small, so every rank builds it whole, as chapter 6
// does (traces, merged grid, dual basis, the rows of B and the weighted gap G), on the two cell
// rows along Gamma_c (RowSplit::contact_strip), and moves B's columns to the global numbering. Then, as in
// common/contact/dual_condensation.hpp, the weighted gap w_i = (B u - G)_i replaces the
// non-mortar normal dof s_i of each row:
//
//     u = T v + g,   u_{s_i} = (G_i + w_i - (B_r u)_i) / b_i,   T = I elsewhere,
//
// and the unknowns v solve A v = r with A = T^T K T and r = T^T (f - K g). One change from
// chapter 6: the unknown at s_i is w_i / b_i, a length like the displacements around it, not
// w_i. Then T's pivot entry is 1, T = I - E with E nonzero only in pivot rows and non-pivot
// columns, and T^{-1} = I + E: the preconditioner of condensed_solver.hpp needs it. Each rank
// writes the rows of T it owns: the identity, or for a pivot 1 and -B_ik / b_i. A itself is
// never formed (condensed_solver.hpp): its products are T^T (K (T x)).
#pragma once

#include <petscmat.h>

#include <vector>

#include "common/contact/constraints.hpp"
#include "distributed_system.hpp"

namespace chapter09 {

struct DistributedCondensation {
  using RowsB = Eigen::SparseMatrix<double, Eigen::RowMajor, PetscInt>;
  RowsB B;  // the rows of B, global columns (every rank)
  std::vector<PetscInt> pivots;  // s_i of each row i, global dofs (every rank has all)
  std::vector<double> b;         // b_i = B(i, s_i): w_i = b_i v_{s_i}
  Mat T = nullptr;
  Vec g = nullptr, r = nullptr;
  ~DistributedCondensation();
};

// The rows of B with global columns (row-major: no storage per column), and each row's pivot.
struct GlobalRows {
  using Matrix = Eigen::SparseMatrix<double, Eigen::RowMajor, PetscInt>;
  Matrix B;
  std::vector<PetscInt> pivots;
};
// constraint_rows of the contact strip, its columns moved to the global numbering.
GlobalRows global_rows(const Part& strip, const mortar::Constraints& constraints, PetscInt num_dofs);

// B must be diagonal on the pivots (a dual basis), as condense_contact requires; G the weighted
// gap (tested_gap).
void condense(DistributedCondensation& c, const DistributedSystem& s, const GlobalRows& rows, const Eigen::VectorXd& G);

}  // namespace chapter09
