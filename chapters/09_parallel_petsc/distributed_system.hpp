// Step 2 of chapter 9: the two bodies' stiffness as one PETSc matrix spread over the ranks.
//
// Rows are split by whole cell rows (rank_part.hpp; both dofs of a node on one rank: block size
// 2, what GAMG needs to see the rigid-body modes). Each rank computes the element matrices of
// its own band's triangles and adds them with ADD_VALUES; the entries of the row of nodes just
// above a band belong to the next rank, and PETSc sends them there at assembly.
// The Dirichlet rows and columns are then zeroed (MatZeroRowsColumns) with the prescribed
// values moved to the right-hand side, which keeps the matrix symmetric positive definite.
#pragma once

#include <petscmat.h>

#include <vector>

#include "common/contact/contact_scenes.hpp"
#include "rank_part.hpp"

namespace chapter09 {

// An empty square AIJ matrix on these rows, block size 2, `per_row` nonzeros expected per row
// (more are allowed, at the cost of a reallocation).
Mat create_matrix(const Ownership& rows, PetscInt per_row);

struct DistributedSystem {
  Ownership rows;
  Mat K = nullptr;  // Dirichlet rows and columns zeroed, `diagonal` on their diagonal
  Vec f = nullptr;  // loads, minus K u_d on the free rows, `diagonal` u_d on the prescribed
  Vec coordinates = nullptr;  // x, y of each owned dof's node (block size 2), for the rigid-body modes
  double diagonal = 1;        // the largest diagonal entry of K before the Dirichlet rows
  ~DistributedSystem();
};

// Assembles K, f and the coordinates on PETSC_COMM_WORLD from this rank's part and its scene
// (loads and prescribed values in the part's numbering): nothing of the other ranks' parts.
void assemble(DistributedSystem& s, const Ownership& rows, const Part& part, const mortar::SceneData& scene);

}  // namespace chapter09
