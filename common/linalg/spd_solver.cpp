#include "common/linalg/spd_solver.hpp"

#include <Eigen/SparseCholesky>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#ifdef MORTAR_HAVE_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

namespace mortar {

bool cholmod_available() {
#ifdef MORTAR_HAVE_CHOLMOD
  return true;
#else
  return false;
#endif
}

SpdBackend fastest_spd_backend() {
  return cholmod_available() ? SpdBackend::cholmod : SpdBackend::simplicial_ldlt;
}

std::string backend_name(SpdBackend backend) {
  return backend == SpdBackend::cholmod ? "cholmod" : "simplicial_ldlt";
}

namespace {
// A pivot that keeps less than this fraction of its matrix's diagonal entry has lost every
// digit to cancellation: the matrix is singular to working precision (a floating body, say).
// Pivots are compared with their own diagonal entry, not with the largest pivot, so stiffness
// ratios of 1e6 between two bodies do not look singular.
constexpr double singular_pivot_ratio = 1e-13;

[[noreturn]] void report_singular(const std::string& backend, Eigen::Index dof, double ratio) {
  throw std::runtime_error("SpdSolver (" + backend + "): K is singular to working precision: the "
                           "pivot of unknown " + std::to_string(dof) + " keeps only " +
                           std::to_string(ratio) + " of its diagonal entry. Is a body free to "
                           "move rigidly (no Dirichlet data in some direction)?");
}

#ifdef MORTAR_HAVE_CHOLMOD
// CHOLMOD's supernodal LL^T, with access to the factor's diagonal for the pivot check.
class CholmodLLT : public Eigen::CholmodSupernodalLLT<SparseMatrix> {
 public:
  // Eigen's compute() only compares L->minor with n, so an analysis or factorization that ran
  // out of memory (L NULL, or L without numerical values) would pass as a success and crash on
  // the first read of L->x. CHOLMOD reports such failures in cholmod_common::status: check it
  // after each step and throw with the size and what failed.
  void compute_checked(const SparseMatrix& K) {
    cholmod().print = 0;  // the exception below says it; CHOLMOD's own line would repeat it
    analyzePattern(K);
    check_status("analysis", K.rows());
    if (m_cholmodFactor == nullptr) fail("analysis", "no factor returned", K.rows());
    factorize(K);
    check_status("factorization", K.rows());
    if (m_cholmodFactor->x == nullptr && m_cholmodFactor->minor == m_cholmodFactor->n)
      fail("factorization", "no numerical values in the factor", K.rows());
  }
  // After a solve: the solve itself can run out of memory (Eigen then leaves x untouched).
  void check_solve(Eigen::Index n) {
    check_status("solve", n);
    if (info() != Eigen::Success) fail("solve", "no solution returned", n);
  }

  // Smallest L_kk^2 / K_pp over all pivots k (p = Perm[k]) and the unknown where it occurs.
  std::pair<double, Eigen::Index> worst_pivot(const Eigen::VectorXd& diagonal) const {
    const cholmod_factor* L = m_cholmodFactor;
    return L->itype == CHOLMOD_INT ? worst_pivot<int>(L, diagonal)
                                   : worst_pivot<SuiteSparse_long>(L, diagonal);
  }

 private:
  void check_status(const char* step, Eigen::Index n) {
    const int status = cholmod().status;
    if (status == CHOLMOD_OUT_OF_MEMORY)
      fail(step, "out of memory (CHOLMOD_OUT_OF_MEMORY; the machine or `ulimit -v` has not the "
                 "memory this size needs: try fewer levels)", n);
    if (status == CHOLMOD_TOO_LARGE) fail(step, "the problem is too large for CHOLMOD's integers", n);
    if (status < 0)
      fail(step, "CHOLMOD status " + std::to_string(status), n);
  }
  [[noreturn]] static void fail(const char* step, const std::string& what, Eigen::Index n) {
    throw std::runtime_error("SpdSolver (CHOLMOD): " + std::string(step) + " of the " + std::to_string(n) +
                             " x " + std::to_string(n) + " matrix failed: " + what);
  }

  // Supernode s holds columns super[s] .. super[s+1]-1 of L as a dense column-major block of
  // pi[s+1] - pi[s] rows starting at x[px[s]]; its diagonal entries are at (j, j).
  template <typename Index>
  static std::pair<double, Eigen::Index> worst_pivot(const cholmod_factor* L,
                                                     const Eigen::VectorXd& diagonal) {
    const auto* super = static_cast<const Index*>(L->super);
    const auto* pi = static_cast<const Index*>(L->pi);
    const auto* px = static_cast<const Index*>(L->px);
    const auto* perm = static_cast<const Index*>(L->Perm);
    const auto* x = static_cast<const double*>(L->x);
    std::pair<double, Eigen::Index> worst{1.0, 0};
    for (std::size_t s = 0; s < L->nsuper; ++s) {
      const Index rows = pi[s + 1] - pi[s];
      for (Index k = super[s]; k < super[s + 1]; ++k) {
        const Index j = k - super[s];
        const double l = x[px[s] + j * rows + j];
        const double ratio = l * l / diagonal[perm[k]];
        if (!(ratio >= worst.first)) worst = {ratio, perm[k]};
      }
    }
    return worst;
  }
};
#endif
}  // namespace

struct SpdSolver::Impl {
  Eigen::SimplicialLDLT<SparseMatrix> ldlt;
#ifdef MORTAR_HAVE_CHOLMOD
  CholmodLLT cholmod;
#endif
  bool factorized = false;
  Eigen::Index size = 0;
};

SpdSolver::SpdSolver(SpdBackend backend) : backend_(backend), impl_(std::make_unique<Impl>()) {
  if (backend == SpdBackend::cholmod && !cholmod_available())
    throw std::invalid_argument("SpdSolver: this build has no CHOLMOD (libsuitesparse-dev)");
}
SpdSolver::~SpdSolver() = default;
SpdSolver::SpdSolver(SpdSolver&&) noexcept = default;
SpdSolver& SpdSolver::operator=(SpdSolver&&) noexcept = default;

void SpdSolver::factorize(const SparseMatrix& K) {
  if (K.rows() != K.cols())
    throw std::invalid_argument("SpdSolver: K is " + std::to_string(K.rows()) + " x " +
                                std::to_string(K.cols()));
  impl_->factorized = false;
  impl_->size = K.rows();
  const Eigen::VectorXd diagonal = K.diagonal();
  if (!(diagonal.minCoeff() > 0))
    throw std::runtime_error("SpdSolver: K has a diagonal entry <= 0 (" +
                             std::to_string(diagonal.minCoeff()) + "): it is not positive definite");
  if (backend_ == SpdBackend::simplicial_ldlt) {
    impl_->ldlt.compute(K);
    if (impl_->ldlt.info() != Eigen::Success)
      throw std::runtime_error("SpdSolver (SimplicialLDLT): factorization of the " +
                               std::to_string(K.rows()) + " x " + std::to_string(K.rows()) +
                               " matrix failed");
    // LDLT also runs through indefinite and singular matrices: check every pivot, which
    // for P K P^T = L D L^T sits at D[P(i)] for unknown i.
    const Eigen::VectorXd d = impl_->ldlt.vectorD();
    const auto& P = impl_->ldlt.permutationP().indices();
    for (Eigen::Index i = 0; i < d.size(); ++i) {
      const double ratio = d[P[i]] / diagonal[i];
      if (!(ratio > singular_pivot_ratio)) report_singular("SimplicialLDLT", i, ratio);
    }
  } else {
#ifdef MORTAR_HAVE_CHOLMOD
    impl_->cholmod.compute_checked(K);
    if (impl_->cholmod.info() != Eigen::Success)
      throw std::runtime_error("SpdSolver (CHOLMOD): K is not positive definite (" +
                               std::to_string(K.rows()) +
                               " unknowns): is a body free to move rigidly?");
    // A singular K can also come through with a pivot that is pure round-off.
    const auto [ratio, dof] = impl_->cholmod.worst_pivot(diagonal);
    if (!(ratio > singular_pivot_ratio)) report_singular("CHOLMOD", dof, ratio);
#endif
  }
  impl_->factorized = true;
}

Eigen::MatrixXd SpdSolver::solve_many(const Eigen::MatrixXd& rhs) const {
  if (!impl_->factorized) throw std::logic_error("SpdSolver::solve called before factorize");
  if (rhs.rows() != impl_->size)
    throw std::invalid_argument("SpdSolver::solve: rhs has " + std::to_string(rhs.rows()) +
                                " rows, K has " + std::to_string(impl_->size));
  Eigen::MatrixXd x;
#ifdef MORTAR_HAVE_CHOLMOD
  if (backend_ == SpdBackend::cholmod) {
    x = impl_->cholmod.solve(rhs);
    impl_->cholmod.check_solve(impl_->size);
  } else {
    x = impl_->ldlt.solve(rhs);
  }
#else
  x = impl_->ldlt.solve(rhs);
#endif
  if (!x.allFinite()) throw std::runtime_error("SpdSolver: the solve produced non-finite values");
  return x;
}

Eigen::VectorXd SpdSolver::solve(const Eigen::VectorXd& rhs) const {
  return solve_many(rhs);  // one right-hand side is a matrix of one column
}

}  // namespace mortar
