#include "common/contact_solvers.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>

namespace mortar {

ContactSolverKind parse_contact_solver(const std::string& name) {
  if (name == "uzawa") return ContactSolverKind::uzawa;
  if (name == "pdas") return ContactSolverKind::pdas;
  throw std::invalid_argument("unknown contact solver '" + name + "' (uzawa or pdas)");
}

std::string contact_solver_name(ContactSolverKind kind) {
  return kind == ContactSolverKind::uzawa ? "uzawa" : "pdas";
}

double complementarity_residual(const Eigen::VectorXd& lambda, const Eigen::VectorXd& gap,
                                double d_scale, double lambda_scale) {
  if (!(d_scale > 0)) return 0.0;
  double r = 0;
  for (Eigen::Index i = 0; i < lambda.size(); ++i)
    r = std::max(r, std::fabs(std::min(lambda[i] / lambda_scale, gap[i] / d_scale)));
  return r;
}

namespace {

// S = B K^{-1} B^T, applied through cached columns (one K solve per column, in blocks).
class DualOperator {
 public:
  DualOperator(const ContactProblem& p, SpdBackend backend) : B_(p.B), solver_(backend) {
    solver_.factorize(p.K);
    b_ = B_ * solver_.solve(p.f) - p.G;
    Bt_ = B_.transpose();
  }
  const Eigen::VectorXd& b() const { return b_; }
  int columns() const { return static_cast<int>(cache_.size()); }
  int size() const { return static_cast<int>(B_.rows()); }

  // S x for x with few nonzeros: only their columns are needed.
  Eigen::VectorXd apply(const Eigen::VectorXd& x) {
    std::vector<int> missing;
    for (int i = 0; i < size(); ++i)
      if (x[i] != 0.0 && cache_.find(i) == cache_.end()) missing.push_back(i);
    compute(missing);
    Eigen::VectorXd y = Eigen::VectorXd::Zero(size());
    for (int i = 0; i < size(); ++i)
      if (x[i] != 0.0) y += x[i] * cache_.at(i);
    return y;
  }
  // Makes sure the columns of these rows are cached, computing the missing ones in blocks.
  void prefetch(const std::vector<int>& rows) {
    std::vector<int> missing;
    for (int i : rows)
      if (cache_.find(i) == cache_.end()) missing.push_back(i);
    compute(missing);
  }
  const Eigen::VectorXd& column(int i) {
    if (cache_.find(i) == cache_.end()) compute({i});
    return cache_.at(i);
  }
  // ||S|| by power iteration on full vectors: each step one solve with K.
  double norm_estimate(int steps = 12) {
    if (size() == 0) return 0.0;
    Eigen::VectorXd x = Eigen::VectorXd::Ones(size()).normalized();
    double estimate = 0;
    for (int k = 0; k < steps; ++k) {
      const Eigen::VectorXd y = B_ * solver_.solve(Eigen::VectorXd(Bt_ * x));
      estimate = x.dot(y);
      if (!(y.norm() > 0)) break;
      x = y.normalized();
    }
    return estimate;
  }
  Eigen::VectorXd displacement(const ContactProblem& p, const Eigen::VectorXd& lambda) const {
    return solver_.solve(Eigen::VectorXd(p.f - Bt_ * lambda));
  }

 private:
  void compute(const std::vector<int>& rows) {
    constexpr int block = 64;  // right-hand sides per pass through the factor
    for (std::size_t start = 0; start < rows.size(); start += block) {
      const int k = static_cast<int>(std::min<std::size_t>(block, rows.size() - start));
      Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(B_.cols(), k);
      for (int c = 0; c < k; ++c) rhs.col(c) = Bt_.col(rows[start + c]);
      const Eigen::MatrixXd S_cols = B_ * solver_.solve_many(rhs);
      for (int c = 0; c < k; ++c) cache_[rows[start + c]] = S_cols.col(c);
    }
  }

  SparseMatrix B_, Bt_;
  SpdSolver solver_;
  Eigen::VectorXd b_;
  std::map<int, Eigen::VectorXd> cache_;
};

struct Scales {
  double d = 0, lambda = 0;
};

Scales scales_of(const DualOperator& S, double S_norm) {
  Scales s;
  s.d = S.b().cwiseAbs().maxCoeff();
  s.lambda = S_norm > 0 ? s.d / S_norm : 0.0;
  return s;
}

std::string format(double v) {
  std::ostringstream o;
  o.precision(3);
  o << v;
  return o.str();
}

ContactSolution uzawa(DualOperator& S, const ContactSolverOptions& o, double S_norm) {
  ContactSolution sol;
  const int m = S.size();
  const Scales sc = scales_of(S, S_norm);
  sol.rho = o.rho > 0 ? o.rho : 1.0 / S_norm;
  Eigen::VectorXd lambda = Eigen::VectorXd::Zero(m), previous = lambda;
  double t = 1, best = std::numeric_limits<double>::infinity();
  // rho above 2 / ||S|| cannot converge: refuse it before iterating. (||S|| is a power-
  // iteration estimate, from below; a rho just under the true limit is caught by the
  // blow-up test in the loop instead.)
  if (sol.rho * S_norm >= 2.0)
    throw std::runtime_error("Uzawa diverges for rho = " + format(sol.rho) +
                             ": rho must stay below 2 / ||B K^{-1} B^T|| = " + format(2.0 / S_norm) +
                             " (leave --rho at 0 to choose it automatically)");
  for (int k = 1; k <= o.max_iterations; ++k) {
    // Nesterov: step from the extrapolated point y, not from lambda itself
    const double t_next = 0.5 * (1 + std::sqrt(1 + 4 * t * t));
    const Eigen::VectorXd y = o.accelerate ? Eigen::VectorXd(lambda + ((t - 1) / t_next) * (lambda - previous)) : lambda;
    t = t_next;
    previous = lambda;
    lambda = (y + sol.rho * (S.b() - S.apply(y))).cwiseMax(0.0);
    const Eigen::VectorXd gap = S.apply(lambda) - S.b();  // G - B u
    sol.residual = complementarity_residual(lambda, gap, sc.d, sc.lambda);
    sol.iterations = k;
    // Slow is not divergent: plain Uzawa on a badly conditioned S creeps for 1e5 steps. Only a
    // residual that is no longer finite or has grown a millionfold means divergence.
    if (!std::isfinite(sol.residual) || sol.residual > 1e6 * std::max(best, 1.0))
      throw std::runtime_error(
          "Uzawa diverges: after " + std::to_string(k) + " iterations the complementarity "
          "residual has grown to " + format(sol.residual) + ", with rho = " + format(sol.rho) +
          " against an estimated limit 2 / ||B K^{-1} B^T|| = " + format(2.0 / S_norm));
    best = std::min(best, sol.residual);
    if (sol.residual <= o.tol) {
      sol.lambda = lambda;
      return sol;
    }
  }
  throw std::runtime_error("Uzawa did not reach the tolerance " + format(o.tol) + " in " +
                           std::to_string(o.max_iterations) + " iterations (residual " +
                           format(sol.residual) + ")");
}

ContactSolution pdas(DualOperator& S, const ContactSolverOptions& o, double S_norm) {
  ContactSolution sol;
  const int m = S.size();
  const Scales sc = scales_of(S, S_norm);
  const double c = S_norm > 0 ? 1.0 / S_norm : 1.0;  // puts lambda and the gap in one unit
  Eigen::VectorXd lambda = Eigen::VectorXd::Zero(m);
  std::vector<int> active;
  for (int i = 0; i < m; ++i)
    if (S.b()[i] > 0) active.push_back(i);  // where the unconstrained bodies would penetrate
  for (int k = 1; k <= std::min(o.max_iterations, 10 * m + 10); ++k) {
    // Newton step: the active rows hold with equality, the others carry no force.
    const int a = static_cast<int>(active.size());
    S.prefetch(active);
    Eigen::MatrixXd S_AA(a, a);
    Eigen::VectorXd b_A(a);
    for (int c2 = 0; c2 < a; ++c2) {
      const Eigen::VectorXd& col = S.column(active[c2]);
      for (int r = 0; r < a; ++r) S_AA(r, c2) = col[active[r]];
      b_A[c2] = S.b()[active[c2]];
    }
    lambda.setZero();
    if (a > 0) {
      const Eigen::VectorXd l_A = S_AA.ldlt().solve(b_A);
      for (int r = 0; r < a; ++r) lambda[active[r]] = l_A[r];
    }
    const Eigen::VectorXd gap = S.apply(lambda) - S.b();
    sol.iterations = k;
    sol.residual = complementarity_residual(lambda, gap, sc.d, sc.lambda);
    std::vector<int> next;
    for (int i = 0; i < m; ++i)
      if (lambda[i] - c * gap[i] > 0) next.push_back(i);
    if (next == active) {
      if (sol.residual > o.tol)
        throw std::runtime_error("pdas: the active set settled but the residual is " +
                                 format(sol.residual) + " > tol " + format(o.tol) +
                                 " (dependent constraint rows?)");
      sol.lambda = lambda;
      return sol;
    }
    active = next;
  }
  throw std::runtime_error("pdas: the active set is still changing after " +
                           std::to_string(sol.iterations) + " iterations (residual " +
                           format(sol.residual) + ")");
}

}  // namespace

ContactSolution solve_contact(const ContactProblem& p, const ContactSolverOptions& o) {
  if (p.B.rows() != p.G.size() || p.B.cols() != p.K.rows() || p.f.size() != p.K.rows())
    throw std::invalid_argument("solve_contact: the sizes of K, f, B and G disagree");
  DualOperator S(p, o.backend);
  const double S_norm = S.norm_estimate();
  ContactSolution sol = o.kind == ContactSolverKind::uzawa ? uzawa(S, o, S_norm) : pdas(S, o, S_norm);
  sol.S_norm = S_norm;
  sol.columns = S.columns();
  sol.u = S.displacement(p, sol.lambda);
  return sol;
}

}  // namespace mortar
