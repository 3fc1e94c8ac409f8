#include "common/contact/saddle_point.hpp"

#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>

#include "common/linalg/dual_schur.hpp"
#include "common/linalg/sparse_lu.hpp"
#include "common/timing/profile.hpp"


namespace mortar {

namespace {
[[noreturn]] void report_singular_saddle(const std::string& how) {
  throw std::runtime_error("saddle point (LU): the matrix [K B^T; B 0] is singular to working "
                           "precision (" + how + "): is a body free to move rigidly in a "
                           "direction the constraints do not hold, such as sliding along Gamma_c?");
}

// T^T K T without a product of two mesh-size sparse matrices. In the (r, s) split, T = [I; X_r],
//     T^T K T = K_rr + E,   E = K_rs X_r + X_r^T K_sr + X_r^T K_ss X_r:
// E lives next to the contact line (K_rs has entries only in the rows next to the pivots, X_r
// only in the touched columns, where it is the dense X), and K_rr + E is written in one pass
// over K, column by column.
SparseMatrix reduced_stiffness(const SparseMatrix& K, const std::vector<int>& pivots,
                               const std::vector<int>& r_index, const Eigen::MatrixXd& X,
                               const std::vector<int>& touched, const SparseMatrix& X_r) {
  const Eigen::Index m = X_r.rows(), nr = X_r.cols();
  // K_rs and K_ss from the pivot columns of K (K is stored whole, so column = row).
  std::vector<Eigen::Triplet<double>> rs, ss;
  std::vector<int> pivot_of(static_cast<std::size_t>(K.rows()), -1);
  for (int k = 0; k < m; ++k) pivot_of[pivots[k]] = k;
  for (int k = 0; k < m; ++k)
    for (SparseMatrix::InnerIterator it(K, pivots[k]); it; ++it) {
      const int i = static_cast<int>(it.row());
      if (r_index[i] >= 0) rs.emplace_back(r_index[i], k, it.value());
      else ss.emplace_back(pivot_of[i], k, it.value());
    }
  SparseMatrix K_rs(nr, m), K_ss(m, m);
  K_rs.setFromTriplets(rs.begin(), rs.end());
  K_ss.setFromTriplets(ss.begin(), ss.end());

  const SparseMatrix C = K_rs * X_r;
  const Eigen::MatrixXd D = X.transpose() * (K_ss * X);  // X_r^T K_ss X_r on the touched columns
  std::vector<Eigen::Triplet<double>> e;
  e.reserve(2 * static_cast<std::size_t>(C.nonZeros()) + static_cast<std::size_t>(D.size()));
  for (int j = 0; j < C.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(C, j); it; ++it) {
      e.emplace_back(it.row(), j, it.value());
      e.emplace_back(j, it.row(), it.value());
    }
  for (std::size_t b = 0; b < touched.size(); ++b)
    for (std::size_t a = 0; a < touched.size(); ++a)
      e.emplace_back(touched[a], touched[b], D(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b)));
  SparseMatrix E(nr, nr);
  E.setFromTriplets(e.begin(), e.end());

  // K_rr + E, merging the sorted rows of both in each column (the r numbering keeps the
  // order of the dofs, so the rows of K_rr come sorted).
  SparseMatrix R(nr, nr);
  R.reserve(K.nonZeros() + E.nonZeros());
  for (int j = 0; j < K.outerSize(); ++j) {
    const int jr = r_index[j];
    if (jr < 0) continue;
    R.startVec(jr);
    SparseMatrix::InnerIterator a(K, j), b(E, jr);
    while (a && r_index[a.row()] < 0) ++a;
    while (a || b) {
      const Eigen::Index ra = a ? r_index[a.row()] : nr, rb = b ? b.row() : nr;
      const Eigen::Index row = std::min(ra, rb);
      double value = 0;
      if (ra == row) {
        value += a.value();
        do ++a; while (a && r_index[a.row()] < 0);
      }
      if (rb == row) {
        value += b.value();
        ++b;
      }
      R.insertBack(row, jr) = value;
    }
  }
  R.finalize();
  return R;
}

// T^T v = v_r + X_r^T v_s.
Eigen::VectorXd apply_T_transpose(const Eigen::VectorXd& v, const std::vector<int>& pivot_of,
                                  const std::vector<int>& r_index, const SparseMatrix& X_r) {
  Eigen::VectorXd v_r(X_r.cols()), v_s(X_r.rows());
  for (Eigen::Index d = 0; d < v.size(); ++d) {
    if (r_index[d] >= 0) v_r[r_index[d]] = v[d];
    else v_s[pivot_of[d]] = v[d];
  }
  return v_r + X_r.transpose() * v_s;
}

}  // namespace

SaddleSolver parse_saddle_solver(const std::string& name) {
  if (name == "lu") return SaddleSolver::lu;
  if (name == "elimination") return SaddleSolver::elimination;
  if (name == "schur") return SaddleSolver::schur;
  throw std::invalid_argument("unknown saddle-point solver '" + name + "' (lu, elimination or schur)");
}

std::string saddle_solver_name(SaddleSolver s) {
  return s == SaddleSolver::lu ? "lu" : s == SaddleSolver::elimination ? "elimination" : "schur";
}

SaddlePointProblem reduce_to_free_dofs(const ReducedSystem& system, const Constraints& c,
                                       const Eigen::VectorXd& G) {
  const ProfilePhase phase("Dirichlet elimination");
  SaddlePointProblem p;
  p.K = system.K;
  p.f = system.rhs;
  p.G = G - c.B * system.prescribed;
  std::vector<Eigen::Triplet<double>> entries;
  const Eigen::SparseMatrix<double, Eigen::RowMajor> B = c.B;
  for (int row = 0; row < B.rows(); ++row)
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(B, row); it; ++it)
      if (system.full_to_free[it.col()] >= 0)
        entries.emplace_back(row, system.full_to_free[it.col()], it.value());
  p.B.resize(B.rows(), static_cast<Eigen::Index>(system.free_dofs.size()));
  p.B.setFromTriplets(entries.begin(), entries.end());
  for (int dof : c.pivot_dof) p.pivots.push_back(system.full_to_free[dof]);  // -1 if prescribed
  return p;
}

SaddlePointSolution solve_saddle_point(const SaddlePointProblem& p, SaddleSolver solver,
                                       SpdBackend backend) {
  if (solver == SaddleSolver::lu) return solve_saddle_point_lu(p);
  return solver == SaddleSolver::elimination ? solve_by_elimination(p, backend) : solve_by_dual_schur(p, backend);
}

SaddlePointSolution solve_saddle_point_lu(const SaddlePointProblem& p) {
  const ProfilePhase phase("saddle-point LU");
  const Eigen::Index n = p.K.rows(), m = p.B.rows();
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(p.K.nonZeros() + 2 * p.B.nonZeros());
  for (int k = 0; k < p.K.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(p.K, k); it; ++it) entries.emplace_back(it.row(), it.col(), it.value());
  for (int k = 0; k < p.B.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(p.B, k); it; ++it) {
      entries.emplace_back(n + it.row(), it.col(), it.value());
      entries.emplace_back(it.col(), n + it.row(), it.value());
    }
  SparseMatrix A(n + m, n + m);
  A.setFromTriplets(entries.begin(), entries.end());
  Eigen::VectorXd rhs(n + m);
  rhs << p.f, p.G;

  // One sparse LU (linalg/sparse_lu.hpp); it refuses a matrix singular to working precision.
  try {
    SparseLu lu;
    lu.factorize(A);
    const Eigen::VectorXd x = lu.solve(rhs);
    return {x.head(n), x.tail(m)};
  } catch (const std::runtime_error& e) {
    report_singular_saddle(e.what());
  }
}

SaddlePointSolution solve_by_elimination(const SaddlePointProblem& p, SpdBackend backend) {
  const int n = static_cast<int>(p.K.rows()), m = static_cast<int>(p.B.rows());
  // Split the unknowns: s = the pivots (one per row), r = the rest, numbered 0 .. n-m-1.
  std::optional<ProfilePhase> phase(std::in_place, "constraint elimination (T)");
  std::vector<int> pivot_of(n, -1), r_index(n, -1);
  for (int k = 0; k < m; ++k) {
    const int d = p.pivots.at(k);
    if (d < 0)
      throw std::invalid_argument("elimination: constraint row " + std::to_string(k) +
                                  " has its non-mortar normal dof prescribed; use the lu solver");
    if (pivot_of[d] >= 0)
      throw std::invalid_argument("elimination: two rows share the pivot dof " + std::to_string(d));
    pivot_of[d] = k;
  }
  int nr = 0;
  for (int d = 0; d < n; ++d)
    if (pivot_of[d] < 0) r_index[d] = nr++;

  // B = [B_s B_r] in (s, r) numbering.
  std::vector<Eigen::Triplet<double>> s_entries, r_entries;
  for (int k = 0; k < p.B.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(p.B, k); it; ++it) {
      if (pivot_of[it.col()] >= 0) s_entries.emplace_back(it.row(), pivot_of[it.col()], it.value());
      else r_entries.emplace_back(it.row(), r_index[it.col()], it.value());
    }
  SparseMatrix Bs(m, m), Br(m, nr);
  Bs.setFromTriplets(s_entries.begin(), s_entries.end());
  Br.setFromTriplets(r_entries.begin(), r_entries.end());
  Eigen::SparseLU<SparseMatrix> Bs_lu(Bs);
  if (Bs_lu.info() != Eigen::Success)
    throw std::runtime_error("elimination: the pivot block B_s is singular");

  // X = -B_s^{-1} B_r, dense only in the columns B_r touches (the mortar side's normal dofs).
  std::vector<int> touched;
  for (int j = 0; j < Br.outerSize(); ++j)
    if (Br.col(j).nonZeros() > 0) touched.push_back(j);
  Eigen::MatrixXd Br_touched = Eigen::MatrixXd::Zero(m, static_cast<Eigen::Index>(touched.size()));
  for (std::size_t c = 0; c < touched.size(); ++c) Br_touched.col(c) = Br.col(touched[c]);
  const Eigen::MatrixXd X = -Bs_lu.solve(Br_touched);
  const Eigen::VectorXd g_s = Bs_lu.solve(p.G);

  // u = T u_r + g: T is the identity on r and X on s, here X_r = X in the r numbering
  // (m x n_r, nonzero only in the touched columns).
  std::vector<Eigen::Triplet<double>> x_entries;
  x_entries.reserve(X.size());
  for (std::size_t c = 0; c < touched.size(); ++c)
    for (int k = 0; k < m; ++k)
      if (X(k, static_cast<Eigen::Index>(c)) != 0.0) x_entries.emplace_back(k, touched[c], X(k, static_cast<Eigen::Index>(c)));
  SparseMatrix X_r(m, nr);
  X_r.setFromTriplets(x_entries.begin(), x_entries.end());
  Eigen::VectorXd g = Eigen::VectorXd::Zero(n);
  for (int k = 0; k < m; ++k) g[p.pivots[k]] = g_s[k];

  phase.emplace("T^T K T product");
  const SparseMatrix K_reduced = reduced_stiffness(p.K, p.pivots, r_index, X, touched, X_r);
  const Eigen::VectorXd f_reduced = apply_T_transpose(Eigen::VectorXd(p.f - p.K * g), pivot_of, r_index, X_r);
  phase.reset();
  // The ordering is chosen once: AMD (spd_solver.hpp), as for the limit. CHOLMOD's automatic
  // choice would also try METIS and nested dissection on T^T K T, several times the limit's
  // whole analysis, and then keep AMD anyway.
  SpdSolver solver(backend);
  solver.factorize(K_reduced, SpdOrdering::amd);
  const Eigen::VectorXd u_r = solver.solve(f_reduced);
  phase.emplace("multipliers");

  SaddlePointSolution sol;
  sol.u = g;  // u = T u_r + g
  const Eigen::VectorXd u_s = X_r * u_r;
  for (int d = 0; d < n; ++d) sol.u[d] += r_index[d] >= 0 ? u_r[r_index[d]] : u_s[pivot_of[d]];
  // K u + B^T lambda = f on the pivot rows: B_s^T lambda = (f - K u)_s.
  const Eigen::VectorXd residual = p.f - p.K * sol.u;
  Eigen::VectorXd residual_s(m);
  for (int k = 0; k < m; ++k) residual_s[k] = residual[p.pivots[k]];
  Eigen::SparseLU<SparseMatrix> BsT_lu(SparseMatrix(Bs.transpose()));
  sol.lambda = BsT_lu.solve(residual_s);
  return sol;
}

SaddlePointSolution solve_by_dual_schur(const SaddlePointProblem& p, SpdBackend backend) {
  SpdSolver solver(backend);
  factorize_for_dual_schur(solver, p.K, p.B);
  const Eigen::MatrixXd S = dual_schur_complement(solver, p.B);
  const Eigen::VectorXd b = p.B * solver.solve(p.f) - p.G;
  const ProfilePhase phase("multipliers");
  // S is SPD when the rows of B are independent (the inf-sup condition, discretely).
  const Eigen::LLT<Eigen::MatrixXd> llt(S);
  if (llt.info() != Eigen::Success)
    throw std::runtime_error("schur: S = B K^{-1} B^T is not positive definite: dependent constraint rows?");
  SaddlePointSolution sol;
  sol.lambda = llt.solve(b);
  sol.u = solver.solve(Eigen::VectorXd(p.f - p.B.transpose() * sol.lambda));
  return sol;
}

}  // namespace mortar
