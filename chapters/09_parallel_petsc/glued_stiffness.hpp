// The matrix chapter 9's multigrid is built on, once per level: K glued along the first active
// set P,
//
//     K_P = K + sum_{i in P} kappa_i B_i^T B_i,     kappa_i = alpha K_{s_i s_i} / b_i^2,
//
// with B_i the row i of B (its entries b_i at the pivot s_i and -M at the mortar side's dofs).
//
// Why not K itself, whose preconditioner maps to A's exactly (A^{-1} = T^{-1} K^{-1} T^{-T},
// condensed_solver.hpp)? A Newton step fixes w_i = 0 on the active pivots, and that glues the two
// bodies along the contact zone, while K holds them apart: M^{-1} of K then inverts the free
// unknowns' block of A^{-1}, not the inverse of their block of A. The two differ on the zone's
// smooth modes, and the final solve took 99 iterations at 1.7M unknowns against 38 for one solve
// with K (chapter 9's notes). In the unknowns v, T^T K_P T = A + sum_{i in P} alpha K_{s_i s_i}
// e_{s_i} e_{s_i}^T: A with the fixed pivots' diagonal raised, whose inverse tends to the inverse
// of A on the free unknowns as alpha grows. Multigrid likes a moderate alpha: at 27k unknowns the
// final solve took 32 iterations with alpha = 1 and 10, 66 with 100 and 120 with 1000, 43 on K.
//
// K_P stays in the displacements u, where GAMG's rigid-body modes (from the coordinates) are what
// they were for K; GAMG built on T^T K T itself, in the unknowns v, did worse than on K (74
// iterations at 27k). With nested iteration P is the active set predicted from the level below,
// right or nearly right; the Newton steps that follow keep this preconditioner (their sets
// differ from P by a few nodes at the zone's edges), so it is built once per level.
#pragma once

#include <petscmat.h>

#include <vector>

#include "distributed_condensation.hpp"
#include "distributed_system.hpp"

namespace chapter09 {

// K_P, with K's near-null space. `K_ss` holds K_{s_i s_i} of every row. The caller destroys it.
Mat glued_stiffness(const DistributedSystem& s, const DistributedCondensation& c, const std::vector<bool>& active,
                    const std::vector<double>& K_ss, double alpha);

}  // namespace chapter09
