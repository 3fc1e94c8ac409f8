// Sparse LU for the nonsymmetric systems of chapter 8 (a Coulomb slip row couples the node's
// tangential equation to its pressure, and nothing couples back): UMFPACK (SuiteSparse) when
// built in, Eigen's SparseLU otherwise. Where the matrix stays symmetric positive definite the
// programs keep CHOLMOD (spd_solver.hpp), about twice as fast on the same matrix.
#pragma once

#include <Eigen/Dense>
#include <memory>
#include <string>

#include "common/fem/p1_elasticity.hpp"

namespace mortar {

class SparseLu {
 public:
  SparseLu();
  ~SparseLu();
  SparseLu(SparseLu&&) noexcept;
  SparseLu& operator=(SparseLu&&) noexcept;

  // Throws std::runtime_error when A is singular to working precision (a zero pivot, or
  // UMFPACK's reciprocal pivot ratio below 1e-14).
  void factorize(const SparseMatrix& A);
  // The same for a matrix with the pattern of the last one factorized (explicit zeros
  // included): UMFPACK's symbolic analysis (its column ordering) is kept and only the numerical
  // factorization runs, as chapter 8's Newton steps change values, not the pattern. Another
  // pattern, or no factorization yet, is a full factorize.
  void refactorize(const SparseMatrix& A);
  // Throws when the backward error ||A x - b|| / (||A|| ||x|| + ||b||) exceeds 1e-8.
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
  static std::string name();  // "UMFPACK" or "Eigen SparseLU"

 private:
  void check_factor();  // a singular or failed factor throws
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace mortar
