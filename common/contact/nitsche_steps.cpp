#include "common/contact/nitsche_steps.hpp"

#include <algorithm>
#include <stdexcept>

#include "common/linalg/sparse_lu.hpp"
#include "common/linalg/spd_solver.hpp"

namespace mortar {

namespace {

class SparseSteps : public NitscheStepSolver {
 public:
  SparseSteps(const ReducedSystem& free, bool symmetric) : free_(free), symmetric_(symmetric) {}

  Eigen::VectorXd solve(const std::vector<Eigen::Triplet<double>>& C, const Eigen::VectorXd& r) override {
    const SparseMatrix A = free_block_plus(free_, C);
    if (symmetric_) {
      try {  // positive definite unless gamma0 is too small for theta = 1
        if (cholesky_analysed_) cholesky_.refactorize(A);
        else cholesky_.factorize(A);
        cholesky_analysed_ = true;
        name_ = backend_name(cholesky_.backend());
        return cholesky_.solve(r);
      } catch (const std::runtime_error&) {
        ++lu_fallbacks_;
        cholesky_analysed_ = false;  // a failed factorization leaves no factor to refactorize
      }
    }
    if (lu_analysed_) lu_.refactorize(A);
    else lu_.factorize(A);
    lu_analysed_ = true;
    name_ = SparseLu::name();
    return lu_.solve(r);
  }
  std::string name() const override { return name_; }

 private:
  const ReducedSystem& free_;
  bool symmetric_;
  SpdSolver cholesky_;
  SparseLu lu_;
  bool cholesky_analysed_ = false, lu_analysed_ = false;
  std::string name_;
};

class CondensedSteps : public NitscheStepSolver {
 public:
  CondensedSteps(const ReducedSystem& free, const std::vector<int>& contact, bool symmetric)
      : free_(free), symmetric_(symmetric) {
    std::vector<int> last;
    for (int d : contact)
      if (free.full_to_free[d] >= 0) last.push_back(free.full_to_free[d]);
    std::sort(last.begin(), last.end());
    last.erase(std::unique(last.begin(), last.end()), last.end());
    cholesky_.factorize_with_last(free.K, last);
    SpdSolver::TrailingFactor t = cholesky_.trailing_factor();
    c_ = std::move(t.dofs);
    const Eigen::MatrixXd& L = t.L;
    S_ = L.triangularView<Eigen::Lower>() * L.transpose();  // (K^{-1})_cc = L^{-T} L^{-1}, so S = L L^T
    position_.assign(free.K.rows(), -1);
    for (std::size_t k = 0; k < c_.size(); ++k) position_[c_[k]] = static_cast<int>(k);
  }

  Eigen::VectorXd solve(const std::vector<Eigen::Triplet<double>>& C, const Eigen::VectorXd& r) override {
    const int m = static_cast<int>(c_.size());
    Eigen::MatrixXd Cc = Eigen::MatrixXd::Zero(m, m);
    for (const auto& t : C) {
      const int i = free_.full_to_free[t.row()], j = free_.full_to_free[t.col()];
      if (i < 0 || j < 0) continue;
      if (position_[i] < 0 || position_[j] < 0) throw std::logic_error("CondensedSteps: C touches a dof outside c");
      Cc(position_[i], position_[j]) += t.value();
    }
    const Eigen::VectorXd y = cholesky_.solve(r);
    Eigen::VectorXd y_c(m);
    for (int k = 0; k < m; ++k) y_c[k] = y[c_[k]];
    const Eigen::MatrixXd M = S_ + Cc;
    const Eigen::VectorXd rhs = S_ * y_c;
    Eigen::VectorXd du_c;
    bool solved = false;
    if (symmetric_) {
      const Eigen::LLT<Eigen::MatrixXd> llt(M);
      if (llt.info() == Eigen::Success) {
        du_c = llt.solve(rhs);
        name_ = "K factorized once; dense Cholesky on Gamma_c";
        solved = true;
      } else {
        ++lu_fallbacks_;
      }
    }
    if (!solved) {
      const Eigen::PartialPivLU<Eigen::MatrixXd> lu(M);
      // as the sparse LU (sparse_lu.hpp): a reciprocal condition below 1e-14 is singular
      if (!(lu.rcond() > 1e-14))
        throw std::runtime_error("the Newton matrix on Gamma_c is singular to working precision (reciprocal condition " +
                                 std::to_string(lu.rcond()) + ")");
      du_c = lu.solve(rhs);
      name_ = "K factorized once; dense LU on Gamma_c";
    }
    Eigen::VectorXd w = Eigen::VectorXd::Zero(r.size());
    const Eigen::VectorXd Cdu = Cc * du_c;
    for (int k = 0; k < m; ++k) w[c_[k]] = Cdu[k];
    return y - cholesky_.solve(w);
  }
  std::string name() const override { return name_; }

 private:
  const ReducedSystem& free_;
  bool symmetric_;
  SpdSolver cholesky_;
  std::vector<int> c_;         // the free dofs C touches, in the factor's order
  std::vector<int> position_;  // free dof -> its place in c_, -1 elsewhere
  Eigen::MatrixXd S_;
  std::string name_;
};

}  // namespace

SparseMatrix free_block_plus(const ReducedSystem& free, const std::vector<Eigen::Triplet<double>>& C) {
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(C.size());
  for (const auto& c : C) {
    const int i = free.full_to_free[c.row()], j = free.full_to_free[c.col()];
    if (i >= 0 && j >= 0) t.emplace_back(i, j, c.value());
  }
  SparseMatrix Cf(free.K.rows(), free.K.cols());
  Cf.setFromTriplets(t.begin(), t.end());
  return free.K + Cf;
}

std::unique_ptr<NitscheStepSolver> make_step_solver(NitscheLinearSolver kind, const ReducedSystem& free,
                                                    const std::vector<int>& contact, bool symmetric) {
  // The dense factorization costs |c|^3 / 3 a step: from a few thousand contact dofs on (long,
  // thin bodies) it outgrows the sparse factorization it replaces.
  constexpr std::size_t max_condensed = 5000;
  std::vector<int> touched(contact);
  std::sort(touched.begin(), touched.end());
  touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
  if (kind == NitscheLinearSolver::condensed && cholmod_available() && touched.size() <= max_condensed) {
    try {
      return std::make_unique<CondensedSteps>(free, contact, symmetric);
    } catch (const std::runtime_error&) {
      // K_ff alone is singular where only the contact holds a body (the patch test): only
      // K_ff + C_ff, with some of Gamma_c in contact, can be factorized
    }
  }
  return std::make_unique<SparseSteps>(free, symmetric);
}

}  // namespace mortar
