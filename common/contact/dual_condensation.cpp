#include "common/contact/dual_condensation.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "common/contact/contact_solvers.hpp"
#include "common/timing/profile.hpp"

namespace mortar {

namespace {
// Entries of B on another row's pivot above this fraction of the row's own pivot mean the
// basis is not dual; below it they are the quadrature's round-off (about 1e-16).
constexpr double dual_tolerance = 1e-10;

using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

// The columns `cols` of K as an n x |cols| matrix.
SparseMatrix columns_of(const SparseMatrix& K, const std::vector<int>& cols) {
  SparseMatrix out(K.rows(), static_cast<Eigen::Index>(cols.size()));
  out.reserve(Eigen::VectorXi::Constant(static_cast<Eigen::Index>(cols.size()), 32));
  for (std::size_t k = 0; k < cols.size(); ++k)
    for (SparseMatrix::InnerIterator it(K, cols[k]); it; ++it) out.insert(it.row(), static_cast<Eigen::Index>(k)) = it.value();
  out.makeCompressed();
  return out;
}

// The entries of A in the rows and columns of the pivots (diagonal excluded), by their place
// in A's value array, with their values: the active set zeroes them, the next one restores them.
class PivotCrosses {
 public:
  PivotCrosses(SparseMatrix& A, const std::vector<int>& pivots) : A_(A), slots_(pivots.size()), values_(pivots.size()) {
    for (std::size_t i = 0; i < pivots.size(); ++i) {
      const int s = pivots[i];
      for (SparseMatrix::InnerIterator it(A, s); it; ++it) {
        if (it.row() == s) continue;
        slots_[i].push_back(position(s, it.row()));          // (j, s) in column s
        slots_[i].push_back(position(static_cast<int>(it.row()), s));  // (s, j) in column j
      }
      for (Eigen::Index slot : slots_[i]) values_[i].push_back(A.valuePtr()[slot]);
    }
  }
  // Rows and columns of the active pivots zeroed, the others as in T^T K T. Two pivots next
  // to each other share the entries between them: restore everything first, then zero, so an
  // inactive neighbour cannot give an active pivot's entry back.
  void apply(const std::vector<bool>& active) {
    restore();
    for (std::size_t i = 0; i < slots_.size(); ++i)
      if (active[i])
        for (Eigen::Index slot : slots_[i]) A_.valuePtr()[slot] = 0.0;
  }
  void restore() {
    for (std::size_t i = 0; i < slots_.size(); ++i)
      for (std::size_t k = 0; k < slots_[i].size(); ++k) A_.valuePtr()[slots_[i][k]] = values_[i][k];
  }

 private:
  Eigen::Index position(int column, Eigen::Index row) const {
    const Eigen::Index begin = A_.outerIndexPtr()[column], end = A_.outerIndexPtr()[column + 1];
    const auto* rows = A_.innerIndexPtr();
    return std::lower_bound(rows + begin, rows + end, static_cast<int>(row)) - rows;
  }
  SparseMatrix& A_;
  std::vector<std::vector<Eigen::Index>> slots_;
  std::vector<std::vector<double>> values_;
};
}  // namespace

Eigen::VectorXd CondensedContact::displacement(const Eigen::VectorXd& v) const {
  Eigen::VectorXd u = v + g;
  const Eigen::VectorXd Zv = Z * v;
  for (int i = 0; i < rows(); ++i) u[pivots[i]] = g[pivots[i]] + Zv[i];
  return u;
}

Eigen::VectorXd CondensedContact::weighted_gap(const Eigen::VectorXd& v) const {
  Eigen::VectorXd w(rows());
  for (int i = 0; i < rows(); ++i) w[i] = v[pivots[i]];
  return w;
}

CondensedContact condense_contact(const SaddlePointProblem& p) {
  const ProfilePhase phase("condensation T^T K T");
  const Eigen::Index n = p.K.rows(), m = p.B.rows();
  CondensedContact c;
  c.pivots = p.pivots;
  std::vector<int> row_of(static_cast<std::size_t>(n), -1);
  for (Eigen::Index i = 0; i < m; ++i) {
    if (c.pivots[i] < 0)
      throw std::invalid_argument("condense_contact: row " + std::to_string(i) + " has its pivot on a prescribed dof");
    row_of[c.pivots[i]] = static_cast<int>(i);
  }
  // Z: row s_i of T, u_{s_i} = (G_i + w_i - (B_r u)_i) / b_i.
  const RowMatrix B = p.B;
  c.b.resize(m);
  std::vector<Eigen::Triplet<double>> z;
  for (Eigen::Index i = 0; i < m; ++i) {
    c.b[i] = B.coeff(i, c.pivots[i]);
    if (!(std::fabs(c.b[i]) > 0)) throw std::invalid_argument("condense_contact: row " + std::to_string(i) + " has a zero pivot");
    z.emplace_back(i, c.pivots[i], 1.0 / c.b[i]);
    for (RowMatrix::InnerIterator it(B, i); it; ++it) {
      const int k = row_of[it.col()];
      if (k == i) continue;
      if (k >= 0) {  // on another row's pivot: D off its diagonal
        const double size = std::fabs(it.value() / c.b[i]);
        if (size > dual_tolerance)
          throw std::invalid_argument("condense_contact: B is not diagonal on the pivots (row " + std::to_string(i) +
                                      " has " + std::to_string(size) + " of its pivot on row " + std::to_string(k) +
                                      "'s): the multiplier basis is not dual");
        c.dropped_max = std::max(c.dropped_max, size);
        continue;
      }
      z.emplace_back(i, it.col(), -it.value() / c.b[i]);
    }
  }
  c.Z.resize(m, n);
  c.Z.setFromTriplets(z.begin(), z.end());

  // A = T^T K T with T = I_r + P Z (I_r: the identity with zeros at the pivots; P puts row i
  // at s_i): K_rr + K_rs Z + (K_rs Z)^T + Z^T K_ss Z, where K_rs = the pivot columns of K
  // without their pivot rows. Written as T = I + P (Z - I) instead, the pivot's own entry
  // 1/b_i - 1 would cancel against K_ss to 1/b_i^2: with b_i ~ h, in kilometres (h = 1e5 m)
  // that cancellation cost 5 of the 16 digits. Everything but K_rr lives next to the line.
  const SparseMatrix K_s = columns_of(p.K, c.pivots);  // n x m
  SparseMatrix K_rs(n, m), K_ss(m, m);
  {
    std::vector<Eigen::Triplet<double>> rs, ss;
    for (int k = 0; k < K_s.outerSize(); ++k)
      for (SparseMatrix::InnerIterator it(K_s, k); it; ++it) {
        if (row_of[it.row()] >= 0) ss.emplace_back(row_of[it.row()], k, it.value());
        else rs.emplace_back(it.row(), k, it.value());
      }
    K_rs.setFromTriplets(rs.begin(), rs.end());
    K_ss.setFromTriplets(ss.begin(), ss.end());
  }
  SparseMatrix K_rr = p.K;  // the pivot rows and columns zeroed, K's pattern kept
  for (int j = 0; j < K_rr.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(K_rr, j); it; ++it)
      if (row_of[j] >= 0 || row_of[it.row()] >= 0) it.valueRef() = 0.0;
  const SparseMatrix Zc = c.Z;  // column-major copy
  const SparseMatrix KZ = K_rs * Zc;  // n x n
  const SparseMatrix ZtKZ = SparseMatrix(Zc.transpose()) * (K_ss * Zc);
  const SparseMatrix E = SparseMatrix(KZ + SparseMatrix(KZ.transpose())) + ZtKZ;
  c.A = K_rr + E;

  update_condensed_loads(c, p.K, p.f, p.G);
  return c;
}

void update_condensed_loads(CondensedContact& c, const SparseMatrix& K, const Eigen::VectorXd& f,
                            const Eigen::VectorXd& G) {
  const int m = c.rows();
  if (G.size() != m || f.size() != K.rows())
    throw std::invalid_argument("update_condensed_loads: sizes do not match the condensed problem");
  c.g = Eigen::VectorXd::Zero(K.rows());
  for (int i = 0; i < m; ++i) c.g[c.pivots[i]] = G[i] / c.b[i];
  // r = T^T (f - K g) = I_r y + Z^T y_s
  Eigen::VectorXd y = f - K * c.g;
  Eigen::VectorXd y_s(m);
  for (int i = 0; i < m; ++i) {
    y_s[i] = y[c.pivots[i]];
    y[c.pivots[i]] = 0;
  }
  c.rhs = y + c.Z.transpose() * y_s;
}

DualContactSolution solve_dual_contact(CondensedContact& c, const DualContactOptions& o) {
  const int m = c.rows();
  DualContactSolution sol;
  sol.active = o.unilateral ? o.initial_active : std::vector<bool>(m, true);
  if (sol.active.empty()) sol.active.assign(m, false);
  if (static_cast<int>(sol.active.size()) != m)
    throw std::invalid_argument("solve_dual_contact: initial_active has " + std::to_string(sol.active.size()) +
                                " entries for " + std::to_string(m) + " rows");
  Eigen::VectorXd diagonal(m);  // c_i of the active-set guess, and the scale of row i
  for (int i = 0; i < m; ++i) diagonal[i] = c.A.coeff(c.pivots[i], c.pivots[i]);
  PivotCrosses crosses(c.A, c.pivots);
  SpdSolver solver(o.backend);
  double d_scale = 0;
  for (int step = 1; step <= o.max_iterations; ++step) {
    // One Newton step: w_A = 0 (identity rows), w free elsewhere, one solve.
    crosses.apply(sol.active);
    Eigen::VectorXd rhs = c.rhs;
    for (int i = 0; i < m; ++i)
      if (sol.active[i]) rhs[c.pivots[i]] = 0;
    if (step == 1) solver.factorize(c.A);
    else solver.refactorize(c.A);
    const Eigen::VectorXd v = solver.solve(rhs);
    crosses.restore();
    sol.iterations = step;
    sol.active_sizes.push_back(static_cast<int>(std::count(sol.active.begin(), sol.active.end(), true)));
    sol.active_history.emplace_back();
    for (int i = 0; i < m; ++i)
      if (sol.active[i]) sol.active_history.back().push_back(i);

    // lambda = (r - A v) at the pivots of the active rows, zero elsewhere; w = v at the pivots.
    {
      const ProfilePhase phase("multipliers");
      sol.w = c.weighted_gap(v);
      sol.lambda = Eigen::VectorXd::Zero(m);
      for (int i = 0; i < m; ++i) {
        if (!sol.active[i]) continue;
        double Av = 0;
        for (SparseMatrix::InnerIterator it(c.A, c.pivots[i]); it; ++it) Av += it.value() * v[it.row()];
        sol.lambda[i] = c.rhs[c.pivots[i]] - Av;
      }
    }
    sol.u = c.displacement(v);
    for (int i = 0; i < m; ++i) d_scale = std::max(d_scale, sol.w[i]);
    if (!o.unilateral) break;
    std::vector<bool> next(static_cast<std::size_t>(m));
    for (int i = 0; i < m; ++i) next[i] = sol.lambda[i] + diagonal[i] * sol.w[i] > 0;
    if (next == sol.active) break;
    for (int i = 0; i < m; ++i) sol.active_set_changes += next[i] != sol.active[i];
    if (step == o.max_iterations)
      throw std::runtime_error("semismooth Newton: the active set still changed after " + std::to_string(step) +
                               " steps");
    sol.active = std::move(next);
  }
  const double lambda_scale = sol.lambda.size() > 0 ? std::max(sol.lambda.cwiseAbs().maxCoeff(), 1e-300) : 1.0;
  sol.residual = complementarity_residual(sol.lambda, -sol.w, d_scale > 0 ? d_scale : 1.0, lambda_scale);
  return sol;
}

}  // namespace mortar
