#include "common/linalg/sparse_lu.hpp"

#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

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
// a small multiple of eps; far above that, the factors do not describe A. Against ||b|| alone,
// a stiff body (entries of K near E) under a small load would look inaccurate although the
// solve is as good as the data.
constexpr double backward_tol = 1e-8;

std::string sci(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3e", v);
  return text;
}

double infinity_norm(const SparseMatrix& A) {
  Eigen::VectorXd row_sums = Eigen::VectorXd::Zero(A.rows());
  for (int k = 0; k < A.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(A, k); it; ++it) row_sums[it.row()] += std::fabs(it.value());
  return row_sums.size() > 0 ? row_sums.maxCoeff() : 0.0;
}

#ifdef MORTAR_HAVE_UMFPACK
// UMFPACK with 64-bit indices (umfpack_dl): its 32-bit version counts its memory in int and
// ran out at 1.65M unknowns (chapter 8, h2/h1 = 1/10) on a machine with 24 GB. The matrix is
// copied with long indices once per factorization, a small cost beside the factor.
using LongMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, SuiteSparse_long>;
// UMFPACK's own estimate of the reciprocal condition (min |U_ii| / max |U_ii|), which Eigen
// keeps but does not show.
class UmfPackLU : public Eigen::UmfPackLU<LongMatrix> {
 public:
  double rcond() const { return m_umfpackInfo[UMFPACK_RCOND]; }
  int status() const { return static_cast<int>(m_umfpackInfo[UMFPACK_STATUS]); }
};
#endif
}  // namespace

struct SparseLu::Impl {
  SparseMatrix A;  // kept for the backward error of each solve
#ifdef MORTAR_HAVE_UMFPACK
  LongMatrix A_long;
  UmfPackLU lu;
#else
  Eigen::SparseLU<SparseMatrix> lu;
#endif
};

SparseLu::SparseLu() : impl_(std::make_unique<Impl>()) {}
SparseLu::~SparseLu() = default;
SparseLu::SparseLu(SparseLu&&) noexcept = default;
SparseLu& SparseLu::operator=(SparseLu&&) noexcept = default;

std::string SparseLu::name() {
#ifdef MORTAR_HAVE_UMFPACK
  return "UMFPACK";
#else
  return "Eigen SparseLU";
#endif
}

namespace {
bool same_pattern(const SparseMatrix& a, const SparseMatrix& b) {
  if (a.rows() != b.rows() || a.cols() != b.cols() || a.nonZeros() != b.nonZeros()) return false;
  if (!a.isCompressed() || !b.isCompressed()) return false;
  return std::equal(a.outerIndexPtr(), a.outerIndexPtr() + a.outerSize() + 1, b.outerIndexPtr()) &&
         std::equal(a.innerIndexPtr(), a.innerIndexPtr() + a.nonZeros(), b.innerIndexPtr());
}
}  // namespace

void SparseLu::factorize(const SparseMatrix& A) {
  impl_->A = A;
#ifdef MORTAR_HAVE_UMFPACK
  impl_->A_long = A;  // kept: Eigen's wrapper points into it
  impl_->lu.compute(impl_->A_long);
#else
  impl_->lu.compute(impl_->A);
#endif
  check_factor();
}

void SparseLu::refactorize(const SparseMatrix& A) {
  if (impl_->A.rows() == 0 || !same_pattern(A, impl_->A)) {
    factorize(A);
    return;
  }
  impl_->A = A;
#ifdef MORTAR_HAVE_UMFPACK
  impl_->A_long = A;
  impl_->lu.factorize(impl_->A_long);
#else
  impl_->lu.factorize(impl_->A);
#endif
  check_factor();
}

void SparseLu::check_factor() {
  const SparseMatrix& A = impl_->A;
#ifdef MORTAR_HAVE_UMFPACK
  // Eigen calls every failure a numerical issue; UMFPACK's status tells a singular matrix from
  // a factor too large for its 32-bit indices or for the memory.
  const int status = impl_->lu.status();
  if (status == UMFPACK_ERROR_out_of_memory)
    throw std::runtime_error("sparse LU (UMFPACK): out of memory at " + std::to_string(A.rows()) +
                             " unknowns (its factor outgrew the memory or its 32-bit indices): use fewer levels");
  if (status < 0) throw std::runtime_error("sparse LU (UMFPACK): failed with status " + std::to_string(status));
#endif
  if (impl_->lu.info() != Eigen::Success) throw std::runtime_error("sparse LU (" + name() + "): a zero pivot: the matrix is singular");
#ifdef MORTAR_HAVE_UMFPACK
  if (!(impl_->lu.rcond() > singular_rcond))
    throw std::runtime_error("sparse LU (UMFPACK): pivot ratio " + sci(impl_->lu.rcond()) +
                             ": the matrix is singular to working precision");
#else
  // SparseLU runs through a tiny pivot: a solve that cannot give back a known vector tells
  const Eigen::VectorXd probe = Eigen::VectorXd::LinSpaced(A.rows(), 1.0, 2.0);
  const Eigen::VectorXd back = impl_->lu.solve(A * probe);
  if (!((back - probe).norm() < 1e-6 * probe.norm()))
    throw std::runtime_error("sparse LU (Eigen SparseLU): a solve of A x = A v missed v by " +
                             sci((back - probe).norm() / probe.norm()) + ": the matrix is singular to working precision");
#endif
}

Eigen::VectorXd SparseLu::solve(const Eigen::VectorXd& b) const {
  const Eigen::VectorXd x = impl_->lu.solve(b);
  const double r = (impl_->A * x - b).lpNorm<Eigen::Infinity>();
  const double scale = infinity_norm(impl_->A) * x.lpNorm<Eigen::Infinity>() + b.lpNorm<Eigen::Infinity>();
  if (!x.allFinite() || !(r <= backward_tol * scale))
    throw std::runtime_error("sparse LU (" + name() + "): residual " + sci(r) + " > " + sci(backward_tol) +
                             " x (||A|| ||x|| + ||b||): the matrix is singular to working precision");
  return x;
}

}  // namespace mortar
