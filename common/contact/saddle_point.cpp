#include "common/contact/saddle_point.hpp"

#include <Eigen/SparseLU>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#ifdef MORTAR_HAVE_UMFPACK
#include <Eigen/UmfPackSupport>
#endif

namespace mortar {

namespace {
// An LU runs through a singular matrix whenever round-off leaves a tiny pivot, and with a
// consistent right-hand side the residual even looks fine. Singular to working precision
// means: UMFPACK's reciprocal pivot ratio min |U_ii| / max |U_ii| below this (after its row
// scaling), or, with Eigen's SparseLU, a solve that cannot give back a known vector.
constexpr double singular_rcond = 1e-14;
// The backward error a solve may leave, ||A x - b|| / (||A|| ||x|| + ||b||): a stable LU gives
// a small multiple of eps; far above that, the factors do not describe A.
constexpr double backward_tol = 1e-8;

std::string sci(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3e", v);
  return text;
}

// max_i sum_j |A_ij|
double infinity_norm(const SparseMatrix& A) {
  Eigen::VectorXd row_sums = Eigen::VectorXd::Zero(A.rows());
  for (int k = 0; k < A.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(A, k); it; ++it) row_sums[it.row()] += std::fabs(it.value());
  return row_sums.size() > 0 ? row_sums.maxCoeff() : 0.0;
}

[[noreturn]] void report_singular_saddle(const std::string& how) {
  throw std::runtime_error("saddle point (LU): the matrix [K B^T; B 0] is singular to working "
                           "precision (" + how + "): is a body free to move rigidly in a "
                           "direction the constraints do not hold, such as sliding along Gamma_c?");
}

#ifdef MORTAR_HAVE_UMFPACK
class UmfPackLU : public Eigen::UmfPackLU<SparseMatrix> {
 public:
  using Eigen::UmfPackLU<SparseMatrix>::UmfPackLU;
  double rcond() const { return m_umfpackInfo[UMFPACK_RCOND]; }
};
#endif
}  // namespace

SaddleSolver parse_saddle_solver(const std::string& name) {
  if (name == "lu") return SaddleSolver::lu;
  if (name == "elimination") return SaddleSolver::elimination;
  throw std::invalid_argument("unknown saddle-point solver '" + name + "' (lu or elimination)");
}

std::string saddle_solver_name(SaddleSolver s) { return s == SaddleSolver::lu ? "lu" : "elimination"; }

SaddlePointProblem reduce_to_free_dofs(const ReducedSystem& system, const Constraints& c,
                                       const Eigen::VectorXd& G) {
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
  return solver == SaddleSolver::lu ? solve_saddle_point_lu(p) : solve_by_elimination(p, backend);
}

SaddlePointSolution solve_saddle_point_lu(const SaddlePointProblem& p) {
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

#ifdef MORTAR_HAVE_UMFPACK
  UmfPackLU lu(A);
  if (lu.info() != Eigen::Success) report_singular_saddle("UMFPACK found a zero pivot");
  if (!(lu.rcond() > singular_rcond))
    report_singular_saddle("UMFPACK pivot ratio " + sci(lu.rcond()));
#else
  Eigen::SparseLU<SparseMatrix> lu(A);
  if (lu.info() != Eigen::Success) report_singular_saddle("SparseLU found a zero pivot");
  const Eigen::VectorXd probe = Eigen::VectorXd::LinSpaced(n + m, 1.0, 2.0);
  const Eigen::VectorXd back = lu.solve(A * probe);
  if (!((back - probe).norm() < 1e-6 * probe.norm()))
    report_singular_saddle("a solve of A x = A v missed v by " +
                           sci((back - probe).norm() / probe.norm()));
#endif
  const Eigen::VectorXd x = lu.solve(rhs);
  // Backward error (infinity norms): a stable LU leaves ||A x - b|| of the size
  // eps (||A|| ||x|| + ||b||). Against ||b|| alone, a stiff body (entries of K near E) under a
  // small load looks inaccurate although the solve is as good as the data.
  const double r = (A * x - rhs).lpNorm<Eigen::Infinity>();
  const double scale = infinity_norm(A) * x.lpNorm<Eigen::Infinity>() + rhs.lpNorm<Eigen::Infinity>();
  if (!x.allFinite() || !(r <= backward_tol * scale))
    throw std::runtime_error("saddle point (LU): the solve is not accurate: residual " + sci(r) +
                             " > " + sci(backward_tol) + " x (||A|| ||x|| + ||b||) = " +
                             sci(backward_tol * scale) +
                             ": the matrix is singular to working precision");
  return {x.head(n), x.tail(m)};
}

SaddlePointSolution solve_by_elimination(const SaddlePointProblem& p, SpdBackend backend) {
  const int n = static_cast<int>(p.K.rows()), m = static_cast<int>(p.B.rows());
  // Split the unknowns: s = the pivots (one per row), r = the rest, numbered 0 .. n-m-1.
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

  // u = T u_r + g: T is the identity on r and X on s.
  std::vector<Eigen::Triplet<double>> t_entries;
  t_entries.reserve(nr + X.size());
  Eigen::VectorXd g = Eigen::VectorXd::Zero(n);
  for (int d = 0; d < n; ++d) {
    if (r_index[d] >= 0) {
      t_entries.emplace_back(d, r_index[d], 1.0);
    } else {
      const int k = pivot_of[d];
      g[d] = g_s[k];
      for (std::size_t c = 0; c < touched.size(); ++c)
        if (X(k, c) != 0.0) t_entries.emplace_back(d, touched[c], X(k, c));
    }
  }
  SparseMatrix T(n, nr);
  T.setFromTriplets(t_entries.begin(), t_entries.end());

  const SparseMatrix KT = p.K * T;
  const SparseMatrix K_reduced = SparseMatrix(T.transpose()) * KT;
  SpdSolver solver(backend);
  solver.factorize(K_reduced);
  const Eigen::VectorXd u_r = solver.solve(T.transpose() * (p.f - p.K * g));

  SaddlePointSolution sol;
  sol.u = T * u_r + g;
  // K u + B^T lambda = f on the pivot rows: B_s^T lambda = (f - K u)_s.
  const Eigen::VectorXd residual = p.f - p.K * sol.u;
  Eigen::VectorXd residual_s(m);
  for (int k = 0; k < m; ++k) residual_s[k] = residual[p.pivots[k]];
  Eigen::SparseLU<SparseMatrix> BsT_lu(SparseMatrix(Bs.transpose()));
  sol.lambda = BsT_lu.solve(residual_s);
  return sol;
}

}  // namespace mortar
