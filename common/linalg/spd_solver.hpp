// Sparse symmetric positive definite solves: CHOLMOD supernodal Cholesky over OpenBLAS when
// available (the fast path), Eigen's SimplicialLDLT otherwise (the readable fallback).
// One factorization serves any number of right-hand sides.
#pragma once

#include <Eigen/Dense>
#include <memory>
#include <string>

#include "common/fem/p1_elasticity.hpp"

namespace mortar {

enum class SpdBackend { cholmod, simplicial_ldlt };

bool cholmod_available();
SpdBackend fastest_spd_backend();  // CHOLMOD when built in, else SimplicialLDLT
std::string backend_name(SpdBackend backend);

class SpdSolver {
 public:
  explicit SpdSolver(SpdBackend backend = fastest_spd_backend());
  ~SpdSolver();
  SpdSolver(SpdSolver&&) noexcept;
  SpdSolver& operator=(SpdSolver&&) noexcept;

  // Factorizes K (lower triangle is read). Throws std::runtime_error naming the problem when
  // K is not positive definite, e.g. a body left free to move rigidly.
  void factorize(const SparseMatrix& K);
  Eigen::VectorXd solve(const Eigen::VectorXd& rhs) const;
  // Several right-hand sides at once (the columns of rhs): one pass through the factor.
  Eigen::MatrixXd solve_many(const Eigen::MatrixXd& rhs) const;
  SpdBackend backend() const { return backend_; }

 private:
  struct Impl;
  SpdBackend backend_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace mortar
