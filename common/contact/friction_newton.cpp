#include "common/contact/friction_newton.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
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

// max |C_n| / Lambda and max |C_t| / Lambda^2, Lambda the largest of the multipliers and of
// c w (the same unit: where every node is open, the multipliers are round-off).
Residual residual_of(const std::vector<NodalUnknowns>& x, const std::vector<NodalLaw>& laws) {
  double scale = 0;
  for (std::size_t i = 0; i < x.size(); ++i)
    scale = std::max({scale, std::fabs(x[i].lambda_n), std::fabs(x[i].lambda_t), laws[i].c_n * std::fabs(x[i].w_n),
                      laws[i].c_t * std::fabs(x[i].dw_t)});
  if (!(scale > 0)) scale = 1;
  Residual r;
  for (std::size_t i = 0; i < x.size(); ++i) {
    r.value = std::max({r.value, std::fabs(normal_function(x[i], laws[i])) / scale,
                        std::fabs(tangential_function(x[i], laws[i])) / (scale * scale)});
    const NodeStatus s = node_status(x[i], laws[i]);
    r.stick += s == NodeStatus::stick;
    r.slip += s == NodeStatus::slip;
  }
  return r;
}

}  // namespace

NodalUnknowns nodal_unknowns(const CondensedContact& c, const Eigen::VectorXd& v, int node, double previous_slip) {
  const int m = c.rows() / 2, pn = c.pivots[node], pt = c.pivots[m + node];
  NodalUnknowns x;
  x.lambda_n = multiplier_at(c, v, pn);
  x.w_n = v[pn];
  x.lambda_t = multiplier_at(c, v, pt);
  x.dw_t = v[pt] - previous_slip;
  return x;
}

FrictionSolution solve_frictional_contact(const CondensedContact& c, const FrictionOptions& o) {
  if (c.rows() % 2 != 0) throw std::invalid_argument("solve_frictional_contact: the rows are not [B_n; B_t]");
  const int m = c.rows() / 2;
  const Eigen::Index n = c.A.rows();
  const Eigen::VectorXd previous = o.previous_slip.size() == m ? o.previous_slip : Eigen::VectorXd::Zero(m);
  if (o.law == FrictionLaw::tresca && o.threshold.size() != m)
    throw std::invalid_argument("solve_frictional_contact: Tresca needs one threshold per node (" + std::to_string(m) + ")");
  if (!o.start.empty() && static_cast<int>(o.start.size()) != m)
    throw std::invalid_argument("solve_frictional_contact: the start has the wrong number of nodes");

  std::vector<NodalLaw> laws(static_cast<std::size_t>(m));
  std::vector<int> node_of(static_cast<std::size_t>(n), -1), role(static_cast<std::size_t>(n), -1);
  for (int i = 0; i < m; ++i) {
    const int pn = c.pivots[i], pt = c.pivots[m + i];
    laws[i] = {o.law, o.friction, o.law == FrictionLaw::tresca ? o.threshold[i] : 0.0, c.A.coeff(pn, pn),
               c.A.coeff(pt, pt)};
    node_of[pn] = node_of[pt] = i;
    role[pn] = 0;
    role[pt] = 1;
  }
  std::vector<NodalUnknowns> x = o.start.empty() ? std::vector<NodalUnknowns>(static_cast<std::size_t>(m)) : o.start;

  FrictionSolution sol;
  Eigen::VectorXd v = Eigen::VectorXd::Zero(n);
  for (int step = 1; step <= o.max_steps; ++step) {
    // 1. The nodal rows, linearized at x.
    std::vector<PivotRow> rows(static_cast<std::size_t>(2 * m));
    bool symmetric = true;
    for (int i = 0; i < m; ++i) {
      const int pn = c.pivots[i], pt = c.pivots[m + i];
      const NodalGradient gn = normal_gradient(x[i], laws[i]);
      const NodalGradient gt = tangential_gradient(x[i], laws[i], o.bounded_gradient);
      rows[i] = pivot_row(gn, gn.dot(x[i]) - normal_function(x[i], laws[i]), 0, c, pn, pt, previous[i]);
      rows[m + i] = pivot_row(gt, gt.dot(x[i]) - tangential_function(x[i], laws[i]), 1, c, pn, pt, previous[i]);
    }
    std::vector<char> known(static_cast<std::size_t>(n), 0);
    Eigen::VectorXd known_value = Eigen::VectorXd::Zero(n);
    for (int k = 0; k < 2 * m; ++k)
      if (rows[k].known) {
        known[c.pivots[k]] = 1;
        known_value[c.pivots[k]] = rows[k].value;
      }
    // A row couples to the other pivot of its node unless that one is prescribed.
    for (int i = 0; i < m; ++i)
      for (int own = 0; own < 2; ++own) {
        const PivotRow& r = rows[own * m + i];
        const int other_pivot = c.pivots[(1 - own) * m + i];
        if (!r.known && (r.kappa[1 - own] != 0 || (r.beta[1 - own] != 0 && !known[other_pivot]))) symmetric = false;
        if (!r.known && r.kappa[own] != 1.0) symmetric = false;
      }

    // 2. The matrix: rows of A off the pivots, the nodal rows at them, prescribed values moved
    //    to the right-hand side.
    SparseMatrix J(n, n);
    Eigen::VectorXd b = c.rhs;
    {
      const ProfilePhase phase("frictional Newton: rows");
      std::vector<Eigen::Triplet<double>> t;
      t.reserve(static_cast<std::size_t>(c.A.nonZeros()) + 8 * static_cast<std::size_t>(m));
      for (Eigen::Index col = 0; col < n; ++col)
        for (SparseMatrix::InnerIterator it(c.A, col); it; ++it) {
          if (role[it.row()] >= 0) continue;
          if (known[col]) b[it.row()] -= it.value() * known_value[col];
          else t.emplace_back(it.row(), col, it.value());
        }
      for (int k = 0; k < 2 * m; ++k) {
        const int i = k % m, p = c.pivots[k];
        const int q_dof[2] = {c.pivots[i], c.pivots[m + i]};
        const PivotRow& r = rows[k];
        if (r.known) {
          t.emplace_back(p, p, 1.0);
          b[p] = r.value;
          continue;
        }
        b[p] = r.rhs;
        for (int q = 0; q < 2; ++q) {
          if (r.kappa[q] != 0)
            for (SparseMatrix::InnerIterator it(c.A, q_dof[q]); it; ++it) {
              if (known[it.row()]) b[p] -= r.kappa[q] * it.value() * known_value[it.row()];
              else t.emplace_back(p, it.row(), r.kappa[q] * it.value());
            }
          if (r.beta[q] != 0) {
            if (known[q_dof[q]]) b[p] -= r.beta[q] * known_value[q_dof[q]];
            else t.emplace_back(p, q_dof[q], r.beta[q]);
          }
        }
      }
      J.setFromTriplets(t.begin(), t.end());
    }

    // 3. One solve: Cholesky while the rows keep A's symmetry, LU when a Coulomb row breaks it.
    bool solved = false;
    if (symmetric) {
      try {
        SpdSolver spd(o.backend);
        spd.factorize(J);
        v = spd.solve(b);
        solved = true;
      } catch (const std::runtime_error&) {
        // not positive definite (a negative shift of a slip row): the LU below takes it
      }
    }
    if (!solved) {
      try {
        const ProfilePhase phase("frictional Newton: sparse LU");
        SparseLu lu;
        lu.factorize(J);
        v = lu.solve(b);
        ++sol.lu_steps;
      } catch (const std::runtime_error& e) {
        const std::string what = e.what();
        const bool singular = what.find("singular") != std::string::npos;
        throw std::runtime_error("frictional Newton, step " + std::to_string(step) + ": " + what +
                                 (singular ? " (does every node slip? then friction cannot hold the load: gross sliding)" : ""));
      }
    }
    sol.steps = step;

    // 4. The new point and its residual.
    for (int i = 0; i < m; ++i) x[i] = nodal_unknowns(c, v, i, previous[i]);
    const Residual r = residual_of(x, laws);
    sol.residuals.push_back(r.value);
    sol.stick.push_back(r.stick);
    sol.slip.push_back(r.slip);
    if (r.value <= o.tolerance) break;
    if (step == o.max_steps) {
      char text[200];
      std::snprintf(text, sizeof text,
                    "frictional Newton: residual %.3e after %d steps (tolerance %.1e; %d nodes stick, %d slip)", r.value,
                    step, o.tolerance, r.stick, r.slip);
      throw std::runtime_error(text);
    }
  }

  sol.u = c.displacement(v);
  sol.nodes = x;
  sol.lambda_n.resize(m);
  sol.lambda_t.resize(m);
  sol.w_n.resize(m);
  sol.w_t.resize(m);
  for (int i = 0; i < m; ++i) {
    sol.lambda_n[i] = x[i].lambda_n;
    sol.lambda_t[i] = x[i].lambda_t;
    sol.w_n[i] = x[i].w_n;
    sol.w_t[i] = x[i].dw_t + previous[i];
    sol.status.push_back(node_status(x[i], laws[i]));
  }
  return sol;
}

FixedPointSolution solve_coulomb_by_fixed_point(const CondensedContact& c, const FrictionOptions& o, int max_outer,
                                                double tolerance) {
  const int m = c.rows() / 2;
  FixedPointSolution out;
  FrictionOptions tresca = o;
  tresca.law = FrictionLaw::tresca;
  tresca.threshold = Eigen::VectorXd::Zero(m);
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
