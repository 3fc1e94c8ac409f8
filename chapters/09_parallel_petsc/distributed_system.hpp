// Step 2 of chapter 9: the two bodies' stiffness as one PETSc matrix spread over the ranks.
//
// Rows are split by node (both dofs of a node on one rank: block size 2, what GAMG needs to see
// the rigid-body modes), in the course's global numbering: body 1's nodes, then body 2's. Each
// rank computes the element matrices of the triangles whose first vertex it owns and adds them
// with ADD_VALUES; PETSc sends the entries of rows owned elsewhere to their rank at assembly.
// The Dirichlet rows and columns are then zeroed (MatZeroRowsColumns) with the prescribed
// values moved to the right-hand side, which keeps the matrix symmetric positive definite.
#pragma once

#include <petscmat.h>

#include <vector>

#include "common/contact/contact_scenes.hpp"
#include "common/contact/two_bodies.hpp"

namespace chapter09 {

// The rows [first, last) of this rank, a whole number of nodes.
struct Ownership {
  PetscInt first = 0, last = 0, size = 0;  // size: all dofs
  bool owns(PetscInt dof) const { return dof >= first && dof < last; }
  PetscInt local() const { return last - first; }
};
Ownership split_by_nodes(PetscInt dofs);                  // this rank's
Ownership split_by_nodes(PetscInt dofs, int rank, int ranks);  // any rank's
// An empty square AIJ matrix on these rows, block size 2, `per_row` nonzeros expected per row
// (more are allowed, at the cost of a reallocation).
Mat create_matrix(const Ownership& rows, PetscInt per_row);

struct DistributedSystem {
  Ownership rows;
  Mat K = nullptr;  // Dirichlet rows and columns zeroed, `diagonal` on their diagonal
  Vec f = nullptr;  // loads, minus K u_d on the free rows, `diagonal` u_d on the prescribed
  Vec coordinates = nullptr;  // x, y of each owned dof's node (block size 2), for the rigid-body modes
  double diagonal = 1;        // the largest diagonal entry of K before the Dirichlet rows
  std::vector<double> prescribed;  // every dof: the prescribed value, or NaN where free
  ~DistributedSystem();
};

// Assembles K, f and the coordinates on PETSC_COMM_WORLD. `bodies` and `scene` are the whole
// problem, known to every rank; only the owned triangles are integrated.
void assemble(DistributedSystem& s, const mortar::TwoBodies& bodies, const mortar::SceneData& scene);

}  // namespace chapter09
