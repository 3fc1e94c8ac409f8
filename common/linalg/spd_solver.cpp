#include "common/linalg/spd_solver.hpp"

#include <dlfcn.h>

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>

#include "common/timing/profile.hpp"

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

// OpenBLAS and libgomp come in as CHOLMOD's dependencies (or not at all, without CHOLMOD), so
// their controls are looked up in the running process rather than linked.
bool set_solver_threads(int threads) {
  bool set = false;
  if (auto* blas = reinterpret_cast<void (*)(int)>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"))) {
    blas(threads);
    set = true;
  }
  if (auto* omp = reinterpret_cast<void (*)(int)>(dlsym(RTLD_DEFAULT, "omp_set_num_threads"))) {
    omp(threads);
    set = true;
  }
  return set;
}

int default_solver_threads() {
  return static_cast<int>(std::clamp(std::thread::hardware_concurrency(), 1u, 64u));
}

namespace {
// A pivot that keeps less than this fraction of its matrix's diagonal entry has lost every
// digit to cancellation: the matrix is singular to working precision (a floating body, say).
// Pivots are compared with their own diagonal entry, not with the largest pivot, so stiffness
// ratios of 1e6 between two bodies do not look singular.
constexpr double singular_pivot_ratio = 1e-13;

// K's diagonal, after checking that it is positive (else K cannot be SPD).
Eigen::VectorXd positive_diagonal(const SparseMatrix& K) {
  Eigen::VectorXd diagonal = K.diagonal();
  if (!(diagonal.minCoeff() > 0))
    throw std::runtime_error("SpdSolver: K has a diagonal entry <= 0 (" + std::to_string(diagonal.minCoeff()) +
                             "): it is not positive definite");
  return diagonal;
}

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
  // `given` empty: CHOLMOD orders (automatic or AMD only); else the factor's order is `given`.
  void compute_checked(const SparseMatrix& K, SpdOrdering ordering, std::vector<int> given) {
    cholmod_common& c = cholmod();
    c.print = 0;  // the exception below says it; CHOLMOD's own line would repeat it
    {
      const ProfilePhase phase("analysis");
      c.nmethods = ordering == SpdOrdering::automatic && given.empty() ? 0 : 1;
      c.method[0].ordering = given.empty() ? CHOLMOD_AMD : CHOLMOD_GIVEN;
      if (given.empty()) analyzePattern(K);
      else analyze_given(K, given);
      check_status("analysis", K.rows());
      if (m_cholmodFactor == nullptr) fail("analysis", "no factor returned", K.rows());
    }
    refactorize_checked(K);
  }
  // The numerical factorization alone, on the analysis of the last compute_checked: K must
  // have the pattern the analysis saw.
  void refactorize_checked(const SparseMatrix& K) {
    const ProfilePhase phase("factorization");
    factorize(K);
    check_status("factorization", K.rows());
    if (m_cholmodFactor->x == nullptr && m_cholmodFactor->minor == m_cholmodFactor->n)
      fail("factorization", "no numerical values in the factor", K.rows());
  }
  std::string ordering_used() {
    const cholmod_common& c = cholmod();
    switch (c.method[c.selected].ordering) {
      case CHOLMOD_GIVEN: return "given";
      case CHOLMOD_AMD: return "amd";
      case CHOLMOD_METIS: return "metis";
      case CHOLMOD_NESDIS: return "nesdis";
      default: return "other";
    }
  }

  // AMD's ordering of the symmetric matrix whose lower triangle is A.
  std::vector<int> amd_order(const SparseMatrix& A) {
    cholmod_sparse a = Eigen::viewAsCholmod(A.selfadjointView<Eigen::Lower>());
    std::vector<int> order(static_cast<std::size_t>(A.rows()));
    if (!cholmod_amd(&a, nullptr, 0, order.data(), &cholmod())) check_status("AMD ordering", A.rows());
    return order;
  }

  // The trailing block of L on the positions of `dofs` (see SpdSolver::trailing_factor). Valid
  // only if no column of L in that set has a row outside it, i.e. the set is closed under the
  // elimination tree's parents: then L^{-1} maps vectors on the set to vectors on the set.
  SpdSolver::TrailingFactor trailing(const std::vector<int>& dofs) const {
    const cholmod_factor* L = m_cholmodFactor;
    if (L == nullptr || !L->is_super || L->itype != CHOLMOD_INT)
      throw std::logic_error("SpdSolver::trailing_factor: no supernodal factor");
    const auto* perm = static_cast<const int*>(L->Perm);
    const Eigen::Index n = static_cast<Eigen::Index>(L->n);
    std::vector<int> position(n);
    for (Eigen::Index k = 0; k < n; ++k) position[perm[k]] = static_cast<int>(k);
    std::vector<int> positions;
    for (int d : dofs) positions.push_back(position[d]);
    std::sort(positions.begin(), positions.end());
    std::vector<int> index(n, -1);  // position -> row of L_c
    SpdSolver::TrailingFactor t;
    for (std::size_t i = 0; i < positions.size(); ++i) {
      index[positions[i]] = static_cast<int>(i);
      t.dofs.push_back(perm[positions[i]]);
    }
    const int m = static_cast<int>(positions.size());
    t.L = Eigen::MatrixXd::Zero(m, m);
    const auto* super = static_cast<const int*>(L->super);
    const auto* pi = static_cast<const int*>(L->pi);
    const auto* px = static_cast<const int*>(L->px);
    const auto* rows_of = static_cast<const int*>(L->s);
    const auto* x = static_cast<const double*>(L->x);
    for (std::size_t s = 0; s < L->nsuper; ++s) {
      const int rows = pi[s + 1] - pi[s];
      for (int k = super[s]; k < super[s + 1]; ++k) {
        const int col = index[k];
        if (col < 0) continue;
        const int j = k - super[s];
        for (int r = j; r < rows; ++r) {  // the rows at and below the diagonal
          const int row = rows_of[pi[s] + r];
          const double value = x[px[s] + static_cast<std::size_t>(j) * rows + r];
          if (index[row] >= 0) t.L(index[row], col) = value;
          else if (value != 0.0)
            throw std::logic_error("SpdSolver::trailing_factor: the unknowns are not last in the factor");
        }
      }
    }
    return t;
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
  // Eigen's analyzePattern() with a given permutation (CHOLMOD's analyze_p).
  void analyze_given(const SparseMatrix& K, std::vector<int>& given) {
    if (m_cholmodFactor != nullptr) cholmod_free_factor(&m_cholmodFactor, &cholmod());
    cholmod_sparse A = Eigen::viewAsCholmod(K.selfadjointView<Eigen::Lower>());
    m_cholmodFactor = cholmod_analyze_p(&A, given.data(), nullptr, 0, &cholmod());
    m_isInitialized = true;
    m_info = Eigen::Success;
    m_analysisIsOk = true;
    m_factorizationIsOk = false;
  }
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
  std::vector<int> last;  // factorize_with_last: the unknowns ordered last
};

SpdSolver::SpdSolver(SpdBackend backend) : backend_(backend), impl_(std::make_unique<Impl>()) {
  if (backend == SpdBackend::cholmod && !cholmod_available())
    throw std::invalid_argument("SpdSolver: this build has no CHOLMOD (libsuitesparse-dev)");
}
SpdSolver::~SpdSolver() = default;
SpdSolver::SpdSolver(SpdSolver&&) noexcept = default;
SpdSolver& SpdSolver::operator=(SpdSolver&&) noexcept = default;

void SpdSolver::factorize(const SparseMatrix& K, SpdOrdering ordering) { factorize(K, ordering, {}); }

void SpdSolver::factorize_with_last(const SparseMatrix& K, const std::vector<int>& last) {
#ifdef MORTAR_HAVE_CHOLMOD
  if (backend_ == SpdBackend::cholmod) {
    const ProfilePhase phase("analysis");
    // The rest in AMD's order, computed on K restricted to the rest, then `last`.
    std::vector<int> order = amd_order_of_rest(K, last);
    order.insert(order.end(), last.begin(), last.end());
    impl_->last = last;
    factorize(K, SpdOrdering::amd, order);
    return;
  }
#endif
  factorize(K, SpdOrdering::amd, {});
}

std::vector<int> SpdSolver::amd_order_of_rest(const SparseMatrix& K, const std::vector<int>& last) {
  std::vector<int> rest_index(static_cast<std::size_t>(K.rows()), 0), rest;
  for (int d : last) rest_index.at(static_cast<std::size_t>(d)) = -1;
  for (int d = 0; d < K.rows(); ++d)
    if (rest_index[d] == 0) {
      rest_index[d] = static_cast<int>(rest.size());
      rest.push_back(d);
    }
  // The lower triangle of K on the rest, column by column (the numbering keeps the order).
  SparseMatrix K_rest(static_cast<Eigen::Index>(rest.size()), static_cast<Eigen::Index>(rest.size()));
  K_rest.reserve(K.nonZeros() / 2 + K.rows());
  for (int j = 0; j < K.outerSize(); ++j) {
    if (rest_index[j] < 0) continue;
    K_rest.startVec(rest_index[j]);
    for (SparseMatrix::InnerIterator it(K, j); it; ++it)
      if (it.row() >= j && rest_index[it.row()] >= 0) K_rest.insertBack(rest_index[it.row()], rest_index[j]) = it.value();
  }
  K_rest.finalize();
  std::vector<int> order;
#ifdef MORTAR_HAVE_CHOLMOD
  if (!rest.empty())  // `last` may be every unknown: nothing to order then
    for (int k : impl_->cholmod.amd_order(K_rest)) order.push_back(rest[k]);
#endif
  return order;
}

SpdSolver::TrailingFactor SpdSolver::trailing_factor() const {
  if (!impl_->factorized || impl_->last.empty())
    throw std::logic_error("SpdSolver::trailing_factor called without factorize_with_last");
#ifdef MORTAR_HAVE_CHOLMOD
  if (backend_ == SpdBackend::cholmod) return impl_->cholmod.trailing(impl_->last);
#endif
  throw std::logic_error("SpdSolver::trailing_factor needs CHOLMOD");
}

std::string SpdSolver::ordering_used() const {
#ifdef MORTAR_HAVE_CHOLMOD
  if (backend_ == SpdBackend::cholmod && impl_->factorized) return impl_->cholmod.ordering_used();
#endif
  return backend_ == SpdBackend::cholmod ? "none" : "amd (Eigen)";
}

void SpdSolver::factorize(const SparseMatrix& K, SpdOrdering ordering, std::vector<int> given) {
  if (K.rows() != K.cols())
    throw std::invalid_argument("SpdSolver: K is " + std::to_string(K.rows()) + " x " +
                                std::to_string(K.cols()));
  impl_->factorized = false;
  impl_->size = K.rows();
  if (given.empty()) impl_->last.clear();
  const Eigen::VectorXd diagonal = positive_diagonal(K);
  if (backend_ == SpdBackend::simplicial_ldlt) {
    {
      const ProfilePhase phase("factorization");
      impl_->ldlt.compute(K);
    }
    check_ldlt(diagonal);
  } else {
#ifdef MORTAR_HAVE_CHOLMOD
    impl_->cholmod.compute_checked(K, ordering, std::move(given));
    check_cholmod(diagonal);
#endif
  }
  impl_->factorized = true;
}

void SpdSolver::refactorize(const SparseMatrix& K) {
  if (!impl_->factorized || K.rows() != impl_->size)
    throw std::logic_error("SpdSolver::refactorize needs a factorize of a matrix of the same size first");
  impl_->factorized = false;
  const Eigen::VectorXd diagonal = positive_diagonal(K);
  if (backend_ == SpdBackend::simplicial_ldlt) {
    {
      const ProfilePhase phase("factorization");
      impl_->ldlt.factorize(K);
    }
    check_ldlt(diagonal);
  } else {
#ifdef MORTAR_HAVE_CHOLMOD
    impl_->cholmod.refactorize_checked(K);
    check_cholmod(diagonal);
#endif
  }
  impl_->factorized = true;
}

void SpdSolver::check_ldlt(const Eigen::VectorXd& diagonal) const {
  if (impl_->ldlt.info() != Eigen::Success)
    throw std::runtime_error("SpdSolver (SimplicialLDLT): factorization of the " +
                             std::to_string(impl_->size) + " x " + std::to_string(impl_->size) +
                             " matrix failed");
  // LDLT also runs through indefinite and singular matrices: check every pivot, which
  // for P K P^T = L D L^T sits at D[P(i)] for unknown i.
  const Eigen::VectorXd d = impl_->ldlt.vectorD();
  const auto& P = impl_->ldlt.permutationP().indices();
  for (Eigen::Index i = 0; i < d.size(); ++i) {
    const double ratio = d[P[i]] / diagonal[i];
    if (!(ratio > singular_pivot_ratio)) report_singular("SimplicialLDLT", i, ratio);
  }
}

void SpdSolver::check_cholmod([[maybe_unused]] const Eigen::VectorXd& diagonal) const {
#ifdef MORTAR_HAVE_CHOLMOD
  if (impl_->cholmod.info() != Eigen::Success)
    throw std::runtime_error("SpdSolver (CHOLMOD): K is not positive definite (" + std::to_string(impl_->size) +
                             " unknowns): is a body free to move rigidly?");
  // A singular K can also come through with a pivot that is pure round-off.
  const auto [ratio, dof] = impl_->cholmod.worst_pivot(diagonal);
  if (!(ratio > singular_pivot_ratio)) report_singular("CHOLMOD", dof, ratio);
#endif
}

Eigen::MatrixXd SpdSolver::solve_many(const Eigen::MatrixXd& rhs) const {
  if (!impl_->factorized) throw std::logic_error("SpdSolver::solve called before factorize");
  if (rhs.rows() != impl_->size)
    throw std::invalid_argument("SpdSolver::solve: rhs has " + std::to_string(rhs.rows()) +
                                " rows, K has " + std::to_string(impl_->size));
  const ProfilePhase phase("solves");
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
