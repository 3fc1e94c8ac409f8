#include "common/spd_solver.hpp"

#include <Eigen/SparseCholesky>
#include <cmath>
#include <stdexcept>

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

struct SpdSolver::Impl {
  Eigen::SimplicialLDLT<SparseMatrix> ldlt;
#ifdef MORTAR_HAVE_CHOLMOD
  Eigen::CholmodSupernodalLLT<SparseMatrix> cholmod;
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
  if (backend_ == SpdBackend::simplicial_ldlt) {
    impl_->ldlt.compute(K);
    if (impl_->ldlt.info() != Eigen::Success)
      throw std::runtime_error("SpdSolver (SimplicialLDLT): factorization of the " +
                               std::to_string(K.rows()) + " x " + std::to_string(K.rows()) +
                               " matrix failed");
    // LDLT accepts semidefinite and indefinite matrices; K must be definite.
    const Eigen::VectorXd d = impl_->ldlt.vectorD();
    const double scale = d.cwiseAbs().maxCoeff();
    for (Eigen::Index i = 0; i < d.size(); ++i)
      if (!(d[i] > 1e-12 * scale))
        throw std::runtime_error("SpdSolver (SimplicialLDLT): K is not positive definite (pivot " +
                                 std::to_string(i) + " is " + std::to_string(d[i]) +
                                 "): is a body free to move rigidly?");
  } else {
#ifdef MORTAR_HAVE_CHOLMOD
    impl_->cholmod.compute(K);
    if (impl_->cholmod.info() != Eigen::Success)
      throw std::runtime_error("SpdSolver (CHOLMOD): K is not positive definite (" +
                               std::to_string(K.rows()) +
                               " unknowns): is a body free to move rigidly?");
#endif
  }
  impl_->factorized = true;
}

Eigen::VectorXd SpdSolver::solve(const Eigen::VectorXd& rhs) const {
  if (!impl_->factorized) throw std::logic_error("SpdSolver::solve called before factorize");
  if (rhs.size() != impl_->size)
    throw std::invalid_argument("SpdSolver::solve: rhs has " + std::to_string(rhs.size()) +
                                " entries, K has " + std::to_string(impl_->size) + " rows");
  Eigen::VectorXd x;
#ifdef MORTAR_HAVE_CHOLMOD
  if (backend_ == SpdBackend::cholmod) x = impl_->cholmod.solve(rhs);
  else x = impl_->ldlt.solve(rhs);
#else
  x = impl_->ldlt.solve(rhs);
#endif
  if (!x.allFinite()) throw std::runtime_error("SpdSolver: the solve produced non-finite values");
  return x;
}

}  // namespace mortar
