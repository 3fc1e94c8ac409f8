// How hard a matrix is for an iterative solver: the iterations of a preconditioned Krylov method
// to a relative residual of 1e-8, a stand-in for its condition number that a large matrix can
// afford. Conjugate gradients with incomplete Cholesky where the matrix is symmetric (K, Nitsche
// with theta = 1, penalty), BiCGSTAB with incomplete LU where it is not (theta = 0, -1).
#pragma once

#include "common/fem/p1_elasticity.hpp"

namespace chapter11 {

// -1 when the method does not reach 1e-8 within 20000 iterations (or breaks down).
int krylov_iterations(const mortar::SparseMatrix& A, bool symmetric);

}  // namespace chapter11
