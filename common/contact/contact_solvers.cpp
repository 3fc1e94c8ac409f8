#include "common/contact/contact_solvers.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <iterator>
#include <set>
#include <sstream>
#include <stdexcept>

#include "common/linalg/dual_schur.hpp"
#include "common/timing/profile.hpp"

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

// S = B K^{-1} B^T, the operator both solvers work with.
//
// With CHOLMOD, S is formed whole, as a Schur complement on the contact line: the unknowns c
// that B touches (normal dofs on Gamma_c) are ordered last in the factorization of K, so the
// trailing block L_c of the factor is the Cholesky factor of the Schur complement of K on c,
// (K^{-1})_cc = L_c^{-T} L_c^{-1}, and S = B_c (K^{-1})_cc B_c^T = W^T W with W = L_c^{-1} B_c^T:
// dense work of the size of the contact line, and no solve with K at all.
// Without CHOLMOD (Eigen's LDLT), a column S e_i costs one solve with K: columns are computed
// on demand, in blocks, and cached.
class DualOperator {
 public:
  DualOperator(const ContactProblem& p, SpdBackend backend) : B_(p.B), solver_(backend) {
    Bt_ = B_.transpose();
    if (backend == SpdBackend::cholmod) {
      factorize_for_dual_schur(solver_, p.K, B_);
      S_ = dual_schur_complement(solver_, B_);
      whole_ = true;
    } else {
      solver_.factorize(p.K);
    }
    b_ = B_ * solver_.solve(p.f) - p.G;
  }
  const Eigen::VectorXd& b() const { return b_; }
  int columns() const { return whole_ ? size() : static_cast<int>(cache_.size()); }
  int size() const { return static_cast<int>(B_.rows()); }

  // S x for x with few nonzeros: only their columns are needed.
  Eigen::VectorXd apply(const Eigen::VectorXd& x) {
    if (whole_) return S_ * x;
    std::vector<int> missing;
    for (int i = 0; i < size(); ++i)
      if (x[i] != 0.0 && cache_.find(i) == cache_.end()) missing.push_back(i);
    compute(missing);
    Eigen::VectorXd y = Eigen::VectorXd::Zero(size());
    for (int i = 0; i < size(); ++i)
      if (x[i] != 0.0) y += x[i] * cache_.at(i);
    return y;
  }
  // The dense block S_AA (computing the missing columns).
  Eigen::MatrixXd block(const std::vector<int>& rows) {
    const int a = static_cast<int>(rows.size());
    Eigen::MatrixXd S_AA(a, a);
    if (whole_) {
      for (int c = 0; c < a; ++c)
        for (int r = 0; r < a; ++r) S_AA(r, c) = S_(rows[r], rows[c]);
      return S_AA;
    }
    std::vector<int> missing;
    for (int i : rows)
      if (cache_.find(i) == cache_.end()) missing.push_back(i);
    compute(missing);
    for (int c = 0; c < a; ++c) {
      const Eigen::VectorXd& col = cache_.at(rows[c]);
      for (int r = 0; r < a; ++r) S_AA(r, c) = col[rows[r]];
    }
    return S_AA;
  }
  // ||S|| by power iteration on full vectors (each step one S x, a solve with K without S).
  double norm_estimate(int steps = 12) {
    if (size() == 0) return 0.0;
    Eigen::VectorXd x = Eigen::VectorXd::Ones(size()).normalized();
    double estimate = 0;
    for (int k = 0; k < steps; ++k) {
      const Eigen::VectorXd y = whole_ ? apply(x) : Eigen::VectorXd(B_ * solver_.solve(Eigen::VectorXd(Bt_ * x)));
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
    const ProfilePhase phase("dual operator S");
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
  bool whole_ = false;
  Eigen::MatrixXd S_;  // whole_: S
  std::map<int, Eigen::VectorXd> cache_;
};

struct Scales {
  double d = 0, lambda = 0;
};

// The unit of the gap is the largest penetration of the unconstrained bodies, max_i b_i^+:
// it comes from the data alone, so no iterate can inflate it, and the answer scales with it.
// max_i |b_i| would not do: where the contact zone is small, the open gap far from it (of the
// size of g) dwarfs the penetration (of the size of delta), and lambda = 0 passes at once.
// Only when nothing penetrates (lambda = 0 is the answer) is max_i |b_i| the unit.
Scales scales_of(const DualOperator& S, double S_norm) {
  Scales s;
  s.d = S.b().cwiseMax(0.0).maxCoeff();
  if (!(s.d > 0)) s.d = S.b().cwiseAbs().maxCoeff();
  s.lambda = S_norm > 0 ? s.d / S_norm : 0.0;
  return s;
}

std::string format(double v) {
  std::ostringstream o;
  o.precision(3);
  o << v;
  return o.str();
}

// Extreme Ritz values of a symmetric positive semidefinite A after up to `steps` Lanczos steps
// (full reorthogonalization, so no ghost copies): the smallest is >= lambda_min(A), the
// largest <= lambda_max(A). The start vector is not symmetric about the middle of Gamma_c,
// so antisymmetric eigenvectors of a symmetric scene are not missed.
struct Extremes {
  double min = 0, max = 0;
};

Extremes lanczos_extremes(const Eigen::MatrixXd& A, int steps = 30) {
  const int n = static_cast<int>(A.rows()), k = std::min(n, steps);
  Eigen::MatrixXd Q(n, k);
  std::vector<double> alpha, beta;
  Eigen::VectorXd q = Eigen::VectorXd::LinSpaced(n, 1.0, 2.0).normalized();
  for (int j = 0; j < k; ++j) {
    Q.col(j) = q;
    Eigen::VectorXd w = A * q;
    alpha.push_back(q.dot(w));
    for (int pass = 0; pass < 2; ++pass) w -= Q.leftCols(j + 1) * (Q.leftCols(j + 1).transpose() * w);
    const double next = w.norm();
    if (j + 1 == k || next <= 1e-12 * std::fabs(alpha.front())) break;  // A's span is exhausted
    beta.push_back(next);
    q = w / next;
  }
  const int m = static_cast<int>(alpha.size());
  Eigen::MatrixXd T = Eigen::MatrixXd::Zero(m, m);
  for (int j = 0; j < m; ++j) T(j, j) = alpha[j];
  for (int j = 0; j + 1 < m; ++j) T(j, j + 1) = T(j + 1, j) = beta[j];
  const Eigen::VectorXd theta = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(T, Eigen::EigenvaluesOnly).eigenvalues();
  return {theta.minCoeff(), theta.maxCoeff()};
}

std::vector<int> support(const Eigen::VectorXd& lambda) {
  std::vector<int> rows;
  for (int i = 0; i < lambda.size(); ++i)
    if (lambda[i] > 0) rows.push_back(i);
  return rows;
}

// The dual energy theta(lambda) = 1/2 lambda.S lambda - b.lambda = 1/2 lambda.(gap - b), with
// gap = S lambda - b. A projected gradient step with rho < 2 / lambda_max never raises it.
double dual_energy(const Eigen::VectorXd& lambda, const Eigen::VectorXd& gap, const Eigen::VectorXd& b) {
  return 0.5 * lambda.dot(gap - b);
}

// The step of plain Uzawa. Near the solution the nonzero multipliers A no longer change and the
// iteration is gradient descent on S_AA: its error contracts by max |1 - rho mu| over the
// eigenvalues mu of S_AA, least for rho = 2 / (mu_max + mu_min), about twice 1 / ||S|| when
// S_AA is badly conditioned. We keep lambda_max = ||S|| (so rho stays below the global limit
// 2 / ||S||, whatever A becomes later), with mu_min from Lanczos on S_AA. An overestimate of
// mu_min (what Lanczos gives) only moves rho towards 1 / ||S||, on the safe side.
class StepFromBothEnds {
 public:
  StepFromBothEnds(double S_norm, bool enabled) : S_norm_(S_norm), enabled_(enabled) {}

  // Called after each step; returns the step for the next one.
  double next_step(DualOperator& S, const Eigen::VectorXd& lambda, double rho) {
    if (!enabled_) return rho;
    std::vector<int> A = support(lambda);
    stable_ = A == last_ ? stable_ + 1 : 0;
    last_ = std::move(A);
    if (stable_ != settle_steps || last_.empty() || last_ == estimated_for_) return rho;
    estimated_for_ = last_;
    const Extremes e = lanczos_extremes(S.block(last_));
    const double top = std::max(S_norm_, e.max);
    // mu_min >= 1e-3 lambda_max keeps rho lambda_max <= 1.998 for a singular S_AA (dependent
    // rows), where the top mode would otherwise stop contracting.
    lambda_min_ = std::max(e.min, 1e-3 * top);
    return 2.0 / (top + lambda_min_);
  }
  // The dual energy rose: the step is too long for the rows now active. Back to 1 / ||S||.
  double fall_back() {
    enabled_ = false;
    fell_back_ = true;
    return 1.0 / S_norm_;
  }
  bool enabled() const { return enabled_; }
  bool fell_back() const { return fell_back_; }
  double lambda_min() const { return lambda_min_; }

 private:
  static constexpr int settle_steps = 20;  // unchanged A for this many steps counts as settled
  double S_norm_;
  bool enabled_;
  bool fell_back_ = false;
  double lambda_min_ = 0;
  int stable_ = 0;
  std::vector<int> last_, estimated_for_;
};

void check_divergence(const ContactSolution& sol, double best, double S_norm, int k) {
  // Slow is not divergent: plain Uzawa on a badly conditioned S creeps for 1e5 steps. Only a
  // residual that is no longer finite or has grown a millionfold means divergence.
  if (!std::isfinite(sol.residual) || sol.residual > 1e6 * std::max(best, 1.0))
    throw std::runtime_error(
        "Uzawa diverges: after " + std::to_string(k) + " iterations the complementarity "
        "residual has grown to " + format(sol.residual) + ", with rho = " + format(sol.rho) +
        " against an estimated limit 2 / ||B K^{-1} B^T|| = " + format(2.0 / S_norm));
}

ContactSolution uzawa(DualOperator& S, const ContactSolverOptions& o, double S_norm) {
  ContactSolution sol;
  const int m = S.size();
  const Scales sc = scales_of(S, S_norm);
  sol.rho = o.rho > 0 ? o.rho : 1.0 / S_norm;
  // rho above 2 / ||S|| cannot converge: refuse it before iterating. (||S|| is a power-
  // iteration estimate, from below; a rho just under the true limit is caught by the
  // blow-up test in the loop instead.)
  if (sol.rho >= 2.0 / S_norm)
    throw std::runtime_error("Uzawa diverges for rho = " + format(sol.rho) +
                             ": rho must stay below 2 / ||B K^{-1} B^T|| = " + format(2.0 / S_norm) +
                             " (leave --rho at 0 to choose it automatically)");
  StepFromBothEnds step(S_norm, o.rho == 0 && !o.accelerate && o.step_from_both_ends);
  Eigen::VectorXd lambda = Eigen::VectorXd::Zero(m), previous = lambda;
  double t = 1, best = std::numeric_limits<double>::infinity(), energy = 0;
  for (int k = 1; k <= o.max_iterations; ++k) {
    // Nesterov: step from the extrapolated point y, not from lambda itself
    const double t_next = 0.5 * (1 + std::sqrt(1 + 4 * t * t));
    const Eigen::VectorXd y = o.accelerate ? Eigen::VectorXd(lambda + ((t - 1) / t_next) * (lambda - previous)) : lambda;
    t = t_next;
    previous = lambda;
    lambda = (y + sol.rho * (S.b() - S.apply(y))).cwiseMax(0.0);
    const Eigen::VectorXd gap = S.apply(lambda) - S.b();  // G - B u
    const double next_energy = dual_energy(lambda, gap, S.b());
    if (step.enabled() && next_energy > energy + 1e-12 * std::fabs(energy)) {
      lambda = previous;  // undo the step, take it again with the safe rho
      sol.rho = step.fall_back();
      continue;
    }
    energy = next_energy;
    sol.residual = complementarity_residual(lambda, gap, sc.d, sc.lambda);
    sol.iterations = k;
    check_divergence(sol, best, S_norm, k);
    best = std::min(best, sol.residual);
    if (sol.residual <= o.tol) {
      sol.lambda = lambda;
      sol.lambda_min = step.lambda_min();
      sol.step_fell_back = step.fell_back();
      return sol;
    }
    sol.rho = step.next_step(S, lambda, sol.rho);
  }
  throw std::runtime_error("Uzawa did not reach the tolerance " + format(o.tol) + " in " +
                           std::to_string(o.max_iterations) + " iterations (residual " +
                           format(sol.residual) + ")");
}

// lambda_A = S_AA^{-1} b_A on the rows A, zero elsewhere.
Eigen::VectorXd solve_on(DualOperator& S, const std::vector<int>& rows) {
  Eigen::VectorXd lambda = Eigen::VectorXd::Zero(S.size());
  if (rows.empty()) return lambda;
  Eigen::VectorXd b_A(rows.size());
  for (std::size_t r = 0; r < rows.size(); ++r) b_A[r] = S.b()[rows[r]];
  const Eigen::VectorXd l_A = S.block(rows).ldlt().solve(b_A);
  for (std::size_t r = 0; r < rows.size(); ++r) lambda[rows[r]] = l_A[r];
  return lambda;
}

// The dual problem min theta(lambda) = 1/2 lambda.S lambda - b.lambda over lambda >= 0, by a
// primal active-set method (Lawson and Hanson's, for a quadratic instead of least squares).
// Every iterate is feasible and theta never rises, so no active set can come back: it ends
// after finitely many steps where PDAS may cycle. It is slower (one row enters per step), so it
// only takes over from PDAS. The free set P starts as the support of the feasible lambda given.
// Step: add the row that penetrates most, minimize over P; where that minimizer leaves
// lambda >= 0, go only as far as the first zero and drop that row from P.
ContactSolution dual_active_set(DualOperator& S, const ContactSolverOptions& o, const Scales& sc,
                                Eigen::VectorXd lambda, int iterations) {
  ContactSolution sol;
  const int m = S.size();
  std::vector<bool> free(m, false);
  for (int i = 0; i < m; ++i) free[i] = lambda[i] > 0;
  std::vector<bool> refused(m, false);  // rows whose entry round-off undid at once
  const int limit = iterations + std::min(o.max_iterations, 10 * m + 10);
  for (sol.iterations = iterations + 1; sol.iterations <= limit; ++sol.iterations) {
    // minimize over the free rows, staying feasible
    for (;;) {
      std::vector<int> P;
      for (int i = 0; i < m; ++i)
        if (free[i]) P.push_back(i);
      const Eigen::VectorXd z = solve_on(S, P);
      double alpha = 1;
      for (int i : P)
        if (z[i] <= 0) alpha = std::min(alpha, lambda[i] / (lambda[i] - z[i]));
      lambda += alpha * (z - lambda);
      if (alpha == 1) break;
      // the rows that reached zero (the blocking one, up to round-off) leave P
      const double zero = 1e-14 * lambda.cwiseAbs().maxCoeff();
      for (int i : P)
        if (lambda[i] <= zero) {
          lambda[i] = 0;
          free[i] = false;
        }
    }
    lambda = lambda.cwiseMax(0.0);
    const Eigen::VectorXd gap = S.apply(lambda) - S.b();
    sol.residual = complementarity_residual(lambda, gap, sc.d, sc.lambda);
    if (sol.residual <= o.tol) {
      sol.lambda = lambda;
      return sol;
    }
    int enter = -1;
    for (int i = 0; i < m; ++i)
      if (!free[i] && !refused[i] && gap[i] < 0 && (enter < 0 || gap[i] < gap[enter])) enter = i;
    if (enter < 0) break;  // nothing left to add: the residual is round-off
    free[enter] = true;
    std::vector<int> P;
    for (int i = 0; i < m; ++i)
      if (free[i]) P.push_back(i);
    // In exact arithmetic a penetrating row enters with a positive multiplier; where round-off
    // says otherwise, it would leave at once: try the next one instead.
    if (solve_on(S, P)[enter] <= 0) {
      free[enter] = false;
      refused[enter] = true;
    } else {
      std::fill(refused.begin(), refused.end(), false);
    }
  }
  throw std::runtime_error("pdas: the dual active-set method stopped after " + std::to_string(sol.iterations) +
                           " iterations at the residual " + format(sol.residual) + " > tol " + format(o.tol));
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
  std::set<std::vector<int>> visited{active};
  for (int k = 1; k <= std::min(o.max_iterations, 10 * m + 10); ++k) {
    // Newton step: the active rows hold with equality, the others carry no force.
    lambda = solve_on(S, active);
    const Eigen::VectorXd gap = S.apply(lambda) - S.b();
    sol.iterations = k;
    sol.active_history.push_back(active);
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
    // S is not an M-matrix (a stiff body on a soft one makes that plain), so the update can
    // return to an active set it has seen: it would cycle for ever. The dual active-set method
    // cannot, and starts from this iterate made feasible.
    std::vector<int> moved;  // both sets are sorted
    std::set_symmetric_difference(active.begin(), active.end(), next.begin(), next.end(), std::back_inserter(moved));
    sol.active_set_changes += static_cast<int>(moved.size());
    if (!visited.insert(next).second) {
      ContactSolution exact = dual_active_set(S, o, sc, lambda.cwiseMax(0.0), k);
      exact.active_set_changes = sol.active_set_changes;
      exact.active_history = std::move(sol.active_history);
      exact.cycled_at = k;
      return exact;
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
  ContactSolution sol;
  double S_norm = 0;
  {
    const ProfilePhase phase(contact_solver_name(o.kind) + " iteration");
    S_norm = S.norm_estimate();
    sol = o.kind == ContactSolverKind::uzawa ? uzawa(S, o, S_norm) : pdas(S, o, S_norm);
  }
  sol.S_norm = S_norm;
  sol.columns = S.columns();
  sol.u = S.displacement(p, sol.lambda);
  return sol;
}

}  // namespace mortar
