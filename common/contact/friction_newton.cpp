#include "common/contact/friction_newton.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>

#include "common/linalg/sparse_lu.hpp"
#include "common/timing/profile.hpp"

namespace mortar {

SaddlePointProblem stack_frictional_rows(const SaddlePointProblem& p, const SaddlePointProblem& t) {
  if (p.B.rows() != t.B.rows() || p.B.cols() != t.B.cols())
    throw std::invalid_argument("stack_frictional_rows: " + std::to_string(p.B.rows()) + " normal and " +
                                std::to_string(t.B.rows()) + " tangential rows: not the same nodes");
  SaddlePointProblem s;
  s.K = p.K;
  s.f = p.f;
  const Eigen::Index m = p.B.rows();
  std::vector<Eigen::Triplet<double>> e;
  for (const auto* part : {&p, &t}) {
    const Eigen::Index shift = part == &p ? 0 : m;
    for (int k = 0; k < part->B.outerSize(); ++k)
      for (SparseMatrix::InnerIterator it(part->B, k); it; ++it) e.emplace_back(shift + it.row(), it.col(), it.value());
  }
  s.B.resize(2 * m, p.B.cols());
  s.B.setFromTriplets(e.begin(), e.end());
  s.G.resize(2 * m);
  s.G << p.G, t.G;
  s.pivots = p.pivots;
  s.pivots.insert(s.pivots.end(), t.pivots.begin(), t.pivots.end());
  return s;
}

namespace {

// lambda at pivot p: (r - A v)_p (A symmetric: row p = column p)
double multiplier_at(const CondensedContact& c, const Eigen::VectorXd& v, int p) {
  double Av = 0;
  for (SparseMatrix::InnerIterator it(c.A, p); it; ++it) Av += it.value() * v[it.row()];
  return c.rhs[p] - Av;
}

// One pivot row of the Newton system, in the unknowns v:
//   sum_q kappa_q (A v)_q + sum_q beta_q v_q = rhs,   q over the node's two pivots (n, t).
struct PivotRow {
  double kappa[2] = {0, 0}, beta[2] = {0, 0}, rhs = 0;
  bool known = false;  // v at this row's own pivot is prescribed: value
  double value = 0;
};

// The Newton row of a gradient g with right-hand side rho = g . x - C, own = 0 (normal row) or
// 1 (tangential row). lambda_q = r_q - (A v)_q, w_n = v_n, dw_t = v_t - previous.
PivotRow pivot_row(const NodalGradient& g, double rho, int own, const CondensedContact& c, int pn, int pt,
                   double previous) {
  PivotRow row;
  const double a[2] = {g.lambda_n, g.lambda_t}, b[2] = {g.w_n, g.dw_t};
  double rhs = rho + g.dw_t * previous - g.lambda_n * c.rhs[pn] - g.lambda_t * c.rhs[pt];
  // -a_q (A v)_q + b_q v_q = rhs
  if (a[own] != 0) {  // divide by -a_own: the own row of A with coefficient exactly 1
    const double scale = -a[own];
    for (int q = 0; q < 2; ++q) {
      row.kappa[q] = q == own ? 1.0 : -a[q] / scale;
      row.beta[q] = b[q] / scale;
    }
    row.rhs = rhs / scale;
    return row;
  }
  const int other = 1 - own;
  if (b[own] != 0 && a[other] == 0 && b[other] == 0) {  // b v_own = rhs
    row.known = true;
    row.value = rhs / b[own];
    return row;
  }
  if (b[own] == 0) throw std::runtime_error("frictional Newton: a nodal equation with no derivative on its own node");
  for (int q = 0; q < 2; ++q) {
    row.kappa[q] = -a[q] / b[own];
    row.beta[q] = b[q] / b[own];
  }
  row.rhs = rhs / b[own];
  return row;
}

struct Residual {
  double value = 0;
  int stick = 0, slip = 0;
};

// The round-off that lambda = (r - A v) carries at node i: a few ulps of the largest of the
// terms it sums, (|r| + |A| |v|) at the node's two pivots. No stopping test can ask for less.
double multiplier_round_off(const CondensedContact& c, const Eigen::VectorXd& v, int node) {
  const int m = c.rows() / 2;
  double terms = 0;
  for (int p : {c.pivots[node], c.pivots[m + node]}) {
    double t = std::fabs(c.rhs[p]);
    for (SparseMatrix::InnerIterator it(c.A, p); it; ++it) t += std::fabs(it.value() * v[it.row()]);
    terms = std::max(terms, t);
  }
  return 8 * std::numeric_limits<double>::epsilon() * terms;
}

// |r| measured against the size d: 0 when both vanish (an unloaded node is converged).
double against(double r, double d) { return r == 0 ? 0.0 : std::fabs(r) / d; }

// The stopping test, node by node: each equation against the node's own size
// (friction_conditions.hpp, nodal_residual), or against round_off / tolerance where the
// multipliers' round-off is larger. Every node then holds its equations to the tolerance, or to
// round-off: a slip node's |lambda_t| is its threshold to that relative accuracy, however small
// its pressure beside the largest.
Residual residual_of(const std::vector<NodalUnknowns>& x, const std::vector<NodalLaw>& laws,
                     const std::vector<double>& round_off, double tolerance) {
  Residual r;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const NodalResidual e = nodal_residual(x[i], laws[i]);
    const double floor = round_off[i] / tolerance;
    r.value = std::max({r.value, against(e.normal, std::max(e.normal_size, floor)),
                        against(e.tangential, std::max(e.tangential_size, floor))});
    const NodeStatus s = node_status(x[i], laws[i]);
    r.stick += s == NodeStatus::stick;
    r.slip += s == NodeStatus::slip;
  }
  return r;
}

}  // namespace

Eigen::VectorXd FrictionFactorizations::solve(const SparseMatrix& J, const Eigen::VectorXd& b, bool symmetric,
                                              int& lu_steps) {
  if (symmetric) {
    try {
      if (spd_ready_) spd_.refactorize(J);
      else spd_.factorize(J);
      spd_ready_ = true;
      return spd_.solve(b);
    } catch (const std::runtime_error&) {
      spd_ready_ = false;  // not positive definite: the LU below takes it
    }
  }
  const ProfilePhase phase("frictional Newton: sparse LU");
  lu_.refactorize(J);
  ++lu_steps;
  return lu_.solve(b);
}

NodalUnknowns nodal_unknowns(const CondensedContact& c, const Eigen::VectorXd& v, int node, double previous_slip) {
  const int m = c.rows() / 2, pn = c.pivots[node], pt = c.pivots[m + node];
  NodalUnknowns x;
  x.lambda_n = multiplier_at(c, v, pn);
  x.w_n = v[pn];
  x.lambda_t = multiplier_at(c, v, pt);
  x.dw_t = v[pt] - previous_slip;
  return x;
}

namespace {

// The nodal laws and the pivots' roles: what every Newton step of one problem reads.
struct NewtonProblem {
  const CondensedContact& c;
  std::vector<NodalLaw> laws;
  Eigen::VectorXd previous;  // w_t at the end of the last load step
  std::vector<int> role;     // 0 at a normal pivot, 1 at a tangential one, -1 elsewhere
  bool bounded = true;
  int nodes() const { return static_cast<int>(laws.size()); }
};

// c_n, c_t: the diagonal of A at the node's two pivots (chapter 6's c_i), in the unit of the
// multipliers per unit of w.
NewtonProblem newton_problem(const CondensedContact& c, FrictionLaw law, double friction,
                             const Eigen::VectorXd& threshold, const Eigen::VectorXd& previous, bool bounded) {
  const int m = c.rows() / 2;
  NewtonProblem p{c, std::vector<NodalLaw>(static_cast<std::size_t>(m)), previous,
                  std::vector<int>(static_cast<std::size_t>(c.A.rows()), -1), bounded};
  for (int i = 0; i < m; ++i) {
    const int pn = c.pivots[i], pt = c.pivots[m + i];
    p.laws[i] = {law, friction, law == FrictionLaw::tresca ? threshold[i] : 0.0, c.A.coeff(pn, pn), c.A.coeff(pt, pt)};
    p.role[pn] = 0;
    p.role[pt] = 1;
  }
  return p;
}

// One Newton matrix and its right-hand side. Its pattern never changes (explicit zeros hold
// the places of unused entries), so the factorizations keep their analysis from step to step.
struct NewtonSystem {
  SparseMatrix J;
  Eigen::VectorXd b;
  bool symmetric = true;
};

// The nodal rows of every node, linearized at x: grad C . x+ = grad C . x - C(x).
std::vector<PivotRow> nodal_rows(const NewtonProblem& p, const std::vector<NodalUnknowns>& x) {
  const int m = p.nodes();
  std::vector<PivotRow> rows(static_cast<std::size_t>(2 * m));
  for (int i = 0; i < m; ++i) {
    const int pn = p.c.pivots[i], pt = p.c.pivots[m + i];
    const NodalGradient gn = normal_gradient(x[i], p.laws[i]);
    const NodalGradient gt = tangential_gradient(x[i], p.laws[i], p.bounded);
    rows[i] = pivot_row(gn, gn.dot(x[i]) - normal_function(x[i], p.laws[i]), 0, p.c, pn, pt, p.previous[i]);
    rows[m + i] = pivot_row(gt, gt.dot(x[i]) - tangential_function(x[i], p.laws[i]), 1, p.c, pn, pt, p.previous[i]);
  }
  return rows;
}

// A row keeps A's symmetry when it is A's own row (kappa[own] = 1), holds no part of the other
// pivot's row, and has no entry in the other pivot's column unless that pivot is prescribed.
bool rows_keep_symmetry(const NewtonProblem& p, const std::vector<PivotRow>& rows, const std::vector<char>& known) {
  const int m = p.nodes();
  for (int i = 0; i < m; ++i)
    for (int own = 0; own < 2; ++own) {
      const PivotRow& r = rows[own * m + i];
      const int other_pivot = p.c.pivots[(1 - own) * m + i];
      if (r.known) continue;
      if (r.kappa[1 - own] != 0 || (r.beta[1 - own] != 0 && !known[other_pivot])) return false;
      if (r.kappa[own] != 1.0) return false;
    }
  return true;
}

NewtonSystem newton_system(const NewtonProblem& p, const std::vector<PivotRow>& rows) {
  const ProfilePhase phase("frictional Newton: rows");
  const CondensedContact& c = p.c;
  const int m = p.nodes();
  const Eigen::Index n = c.A.rows();
  std::vector<char> known(static_cast<std::size_t>(n), 0);
  Eigen::VectorXd known_value = Eigen::VectorXd::Zero(n);
  for (int k = 0; k < 2 * m; ++k)
    if (rows[k].known) {
      known[c.pivots[k]] = 1;
      known_value[c.pivots[k]] = rows[k].value;
    }
  NewtonSystem s;
  s.symmetric = rows_keep_symmetry(p, rows, known);
  s.b = c.rhs;
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(static_cast<std::size_t>(c.A.nonZeros()) + 40 * static_cast<std::size_t>(m));
  // Rows of A off the pivots; a prescribed column moves to the right-hand side (its place kept).
  for (Eigen::Index col = 0; col < n; ++col)
    for (SparseMatrix::InnerIterator it(c.A, col); it; ++it) {
      if (p.role[it.row()] >= 0) continue;
      if (known[col]) s.b[it.row()] -= it.value() * known_value[col];
      t.emplace_back(it.row(), col, known[col] ? 0.0 : it.value());
    }
  // The pivot rows: kappa_q times row q of A plus beta_q at q, over the node's pivots q; a
  // prescribed pivot is an identity row. Every place of both rows of A is written.
  for (int k = 0; k < 2 * m; ++k) {
    const int i = k % m, pivot = c.pivots[k];
    const int q_dof[2] = {c.pivots[i], c.pivots[m + i]};
    const PivotRow& r = rows[k];
    t.emplace_back(pivot, pivot, r.known ? 1.0 : 0.0);
    s.b[pivot] = r.known ? r.value : r.rhs;
    for (int q = 0; q < 2; ++q) {
      const double kappa = r.known ? 0.0 : r.kappa[q], beta = r.known ? 0.0 : r.beta[q];
      for (SparseMatrix::InnerIterator it(c.A, q_dof[q]); it; ++it) {
        if (known[it.row()]) s.b[pivot] -= kappa * it.value() * known_value[it.row()];
        t.emplace_back(pivot, it.row(), known[it.row()] ? 0.0 : kappa * it.value());
      }
      if (known[q_dof[q]]) s.b[pivot] -= beta * known_value[q_dof[q]];
      t.emplace_back(pivot, q_dof[q], known[q_dof[q]] ? 0.0 : beta);
    }
  }
  s.J.resize(n, n);
  s.J.setFromTriplets(t.begin(), t.end());
  return s;
}

// How a run of Newton steps ended.
struct Attempt {
  bool converged = false;
  bool cycled = false;  // a set of statuses came back after another one: the iteration cycles
  std::vector<NodalUnknowns> x;
  Eigen::VectorXd v;
  Residual last;
};

std::vector<NodeStatus> statuses(const NewtonProblem& p, const std::vector<NodalUnknowns>& x) {
  std::vector<NodeStatus> s(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) s[i] = node_status(x[i], p.laws[i]);
  return s;
}

// At most max_steps Newton steps from the linearization point x, each recorded in sol. Stops
// early when the statuses cycle, or when ten steps in a row bring no smaller residual.
Attempt newton_steps(const NewtonProblem& p, std::vector<NodalUnknowns> x, int max_steps, double tolerance,
                     FrictionFactorizations& solves, FrictionSolution& sol) {
  const CondensedContact& c = p.c;
  const int m = p.nodes();
  Attempt a;
  std::vector<std::vector<NodeStatus>> seen;
  double best = std::numeric_limits<double>::infinity();
  int best_step = 0;
  for (int step = 1; step <= max_steps; ++step) {
    const NewtonSystem system = newton_system(p, nodal_rows(p, x));
    a.v = solves.solve(system.J, system.b, system.symmetric, sol.lu_steps);
    ++sol.steps;
    std::vector<double> round_off(static_cast<std::size_t>(m));
    for (int i = 0; i < m; ++i) {
      x[i] = nodal_unknowns(c, a.v, i, p.previous[i]);
      round_off[i] = multiplier_round_off(c, a.v, i);
    }
    a.last = residual_of(x, p.laws, round_off, tolerance);
    sol.residuals.push_back(a.last.value);
    sol.stick.push_back(a.last.stick);
    sol.slip.push_back(a.last.slip);
    if (a.last.value <= tolerance) {
      a.converged = true;
      break;
    }
    std::vector<NodeStatus> now = statuses(p, x);
    a.cycled = !seen.empty() && now != seen.back() && std::find(seen.begin(), seen.end(), now) != seen.end();
    seen.push_back(std::move(now));
    if (a.last.value < best) {
      best = a.last.value;
      best_step = step;
    }
    if (a.cycled || step - best_step >= 10) break;
  }
  a.x = std::move(x);
  return a;
}

std::string failure_message(const Attempt& a, const FrictionSolution& sol, double tolerance) {
  char text[400];
  std::snprintf(text, sizeof text,
                "frictional Newton: residual %.3e after %d steps, from the given start and from the no-slip "
                "solution (tolerance %.1e; %d nodes stick, %d slip%s)",
                a.last.value, sol.steps, tolerance, a.last.stick, a.last.slip,
                a.cycled ? "; the statuses cycle: the discrete problem may have several solutions" : "");
  return text;
}

}  // namespace

FrictionSolution solve_frictional_contact(const CondensedContact& c, const FrictionOptions& o) {
  if (c.rows() % 2 != 0) throw std::invalid_argument("solve_frictional_contact: the rows are not [B_n; B_t]");
  const int m = c.rows() / 2;
  const Eigen::VectorXd previous = o.previous_slip.size() == m ? o.previous_slip : Eigen::VectorXd::Zero(m);
  if (o.law == FrictionLaw::tresca && o.threshold.size() != m)
    throw std::invalid_argument("solve_frictional_contact: Tresca needs one threshold per node (" + std::to_string(m) + ")");
  if (!o.start.empty() && static_cast<int>(o.start.size()) != m)
    throw std::invalid_argument("solve_frictional_contact: the start has the wrong number of nodes");
  const std::vector<NodalUnknowns> start = o.start.empty() ? std::vector<NodalUnknowns>(static_cast<std::size_t>(m)) : o.start;

  const NewtonProblem problem = newton_problem(c, o.law, o.friction, o.threshold, previous, o.bounded_gradient);
  const std::shared_ptr<FrictionFactorizations> solves =
      o.factorizations ? o.factorizations : std::make_shared<FrictionFactorizations>(o.backend);
  FrictionSolution sol;
  Attempt a;
  try {
    a = newton_steps(problem, start, o.max_steps, o.tolerance, *solves, sol);
  } catch (const std::runtime_error&) {
    // a singular step (a body held in x by friction alone, every node slipping): the restart below
  }
  if (!a.converged) {
    // The globalization: the same loads with no slip allowed (Tresca with infinite thresholds,
    // a convex problem whose steps are symmetric), then the law again from its solution, where
    // every node in contact sticks. A Newton step from a point whose statuses are wrong can slip
    // a node that alone holds a body, or couple F times a stray slip into the pressure; from the
    // no-slip solution the law has only to release the nodes that slip.
    const Eigen::VectorXd no_slip = Eigen::VectorXd::Constant(m, std::numeric_limits<double>::infinity());
    const NewtonProblem stuck = newton_problem(c, FrictionLaw::tresca, 0.0, no_slip, previous, o.bounded_gradient);
    const Attempt glued = newton_steps(stuck, start, o.max_steps, o.tolerance, *solves, sol);
    if (!glued.converged) throw std::runtime_error(failure_message(glued, sol, o.tolerance));
    ++sol.restarts;
    a = newton_steps(problem, glued.x, o.max_steps, o.tolerance, *solves, sol);
    if (!a.converged) throw std::runtime_error(failure_message(a, sol, o.tolerance));
  }

  sol.u = c.displacement(a.v);
  sol.nodes = a.x;
  sol.lambda_n.resize(m);
  sol.lambda_t.resize(m);
  sol.w_n.resize(m);
  sol.w_t.resize(m);
  for (int i = 0; i < m; ++i) {
    sol.lambda_n[i] = a.x[i].lambda_n;
    sol.lambda_t[i] = a.x[i].lambda_t;
    sol.w_n[i] = a.x[i].w_n;
    sol.w_t[i] = a.x[i].dw_t + previous[i];
    sol.status.push_back(node_status(a.x[i], problem.laws[i]));
  }
  return sol;
}

FixedPointSolution solve_coulomb_by_fixed_point(const CondensedContact& c, const FrictionOptions& o, int max_outer,
                                                double tolerance) {
  const int m = c.rows() / 2;
  FixedPointSolution out;
  FrictionOptions tresca = o;
  tresca.law = FrictionLaw::tresca;
  tresca.threshold = o.fixed_point_start.size() == m
                         ? o.fixed_point_start
                         : Eigen::VectorXd::Constant(m, std::numeric_limits<double>::infinity());
  for (int k = 1; k <= max_outer; ++k) {
    out.last = solve_frictional_contact(c, tresca);
    out.outer = k;
    out.total_steps += out.last.steps;
    tresca.start = out.last.nodes;
    const Eigen::VectorXd next = o.friction * out.last.lambda_n.cwiseMax(0.0);
    const double change = (next - tresca.threshold).cwiseAbs().maxCoeff();
    const double scale = std::max(next.cwiseAbs().maxCoeff(), 1e-300);
    out.threshold_changes.push_back(change / scale);
    tresca.threshold = next;
    if (change <= tolerance * scale) return out;
  }
  throw std::runtime_error("Coulomb by fixed point: the thresholds still changed by " +
                           std::to_string(out.threshold_changes.back()) + " (relative) after " +
                           std::to_string(max_outer) + " Tresca problems");
}

}  // namespace mortar
