// The physical limit of one level (README.md, "Speed"): assembling K plus one factorization
// and one solve of K with the fastest sparse Cholesky available, timed in the same run on the
// same matrix, with no coupling and no iteration. Programs report their own time as a ratio
// to it.
#pragma once

#include <functional>

#include "common/fem/p1_elasticity.hpp"

namespace mortar {

// assemble_K builds the SPD matrix of the level (both bodies, Dirichlet dofs eliminated).
// Returns seconds for assemble_K() + factorize + one solve.
double measure_physical_limit(const std::function<SparseMatrix()>& assemble_K);

}  // namespace mortar
