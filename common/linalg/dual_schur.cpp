#include "common/linalg/dual_schur.hpp"

#include <algorithm>

#include "common/timing/profile.hpp"

namespace mortar {

std::vector<int> touched_unknowns(const SparseMatrix& B) {
  std::vector<int> c;
  for (int j = 0; j < B.outerSize(); ++j)
    if (B.col(j).nonZeros() > 0) c.push_back(j);
  return c;
}

void factorize_for_dual_schur(SpdSolver& solver, const SparseMatrix& K, const SparseMatrix& B) {
  if (solver.backend() == SpdBackend::cholmod) solver.factorize_with_last(K, touched_unknowns(B));
  else solver.factorize(K);
}

namespace {
// S = W^T W with W = L_cc^{-1} B_c^T, rows of W in the factor's order of c.
Eigen::MatrixXd from_trailing_factor(const SpdSolver& solver, const SparseMatrix& B) {
  const SpdSolver::TrailingFactor t = solver.trailing_factor();
  const int m = static_cast<int>(B.rows()), nc = static_cast<int>(t.dofs.size());
  std::vector<int> index(static_cast<std::size_t>(B.cols()), -1);
  for (int k = 0; k < nc; ++k) index[t.dofs[k]] = k;
  Eigen::MatrixXd W = Eigen::MatrixXd::Zero(nc, m);  // B_c^T, then L_cc^{-1} B_c^T
  for (int j = 0; j < B.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(B, j); it; ++it) W(index[j], it.row()) = it.value();
  t.L.triangularView<Eigen::Lower>().solveInPlace(W);
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(m, m);
  S.selfadjointView<Eigen::Lower>().rankUpdate(W.transpose());  // the lower triangle of W^T W
  S.triangularView<Eigen::StrictlyUpper>() = S.transpose();
  return S;
}

// One solve per column, in blocks: a pass through the factor serves 64 right-hand sides.
Eigen::MatrixXd from_solves(const SpdSolver& solver, const SparseMatrix& B) {
  constexpr int block = 64;
  const int m = static_cast<int>(B.rows());
  const SparseMatrix Bt = B.transpose();
  Eigen::MatrixXd S(m, m);
  for (int start = 0; start < m; start += block) {
    const int k = std::min(block, m - start);
    const Eigen::MatrixXd rhs = Bt.middleCols(start, k);
    S.middleCols(start, k) = B * solver.solve_many(rhs);
  }
  return S;
}
}  // namespace

Eigen::MatrixXd dual_schur_complement(const SpdSolver& solver, const SparseMatrix& B) {
  const ProfilePhase phase("dual operator S");
  return solver.backend() == SpdBackend::cholmod ? from_trailing_factor(solver, B) : from_solves(solver, B);
}

}  // namespace mortar
