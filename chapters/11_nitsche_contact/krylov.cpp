#include "krylov.hpp"

#include <Eigen/IterativeLinearSolvers>
#include <random>

namespace chapter11 {

namespace {
// A right-hand side with a known answer: A x for x with entries in [-1, 1], a fixed seed.
Eigen::VectorXd test_rhs(const mortar::SparseMatrix& A) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> d(-1, 1);
  Eigen::VectorXd x(A.cols());
  for (Eigen::Index i = 0; i < x.size(); ++i) x[i] = d(rng);
  return A * x;
}

template <class Solver>
int iterations(Solver& solver, const mortar::SparseMatrix& A) {
  solver.setTolerance(1e-8);
  solver.setMaxIterations(20000);
  solver.compute(A);
  if (solver.info() != Eigen::Success) return -1;
  const Eigen::VectorXd x = solver.solve(test_rhs(A));
  if (solver.info() != Eigen::Success || !x.allFinite()) return -1;
  return static_cast<int>(solver.iterations());
}
}  // namespace

int krylov_iterations(const mortar::SparseMatrix& A, bool symmetric) {
  if (symmetric) {
    Eigen::ConjugateGradient<mortar::SparseMatrix, Eigen::Lower | Eigen::Upper, Eigen::IncompleteCholesky<double>> cg;
    return iterations(cg, A);
  }
  Eigen::BiCGSTAB<mortar::SparseMatrix, Eigen::IncompleteLUT<double>> bicgstab;
  return iterations(bicgstab, A);
}

}  // namespace chapter11
