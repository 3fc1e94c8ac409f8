// A small contact problem for the solver exercises: a chain of springs K (tridiagonal, SPD)
// pressed against obstacles by rows of B, with S = B K^{-1} B^T and b = B K^{-1} f - G formed
// densely, and its exact solution from the library's active-set solver.
#pragma once

#include <Eigen/Dense>

#include "common/contact/contact_solvers.hpp"

namespace exercise_support {

struct SmallContact {
  mortar::ContactProblem problem;
  Eigen::MatrixXd S;
  Eigen::VectorXd b;
  Eigen::VectorXd lambda;  // the exact multipliers
};

inline SmallContact small_contact(int n = 40, int m = 12) {
  SmallContact c;
  std::vector<Eigen::Triplet<double>> k, r;
  for (int i = 0; i < n; ++i) {
    k.emplace_back(i, i, 2.0 + 0.01 * i);
    if (i + 1 < n) {
      k.emplace_back(i, i + 1, -1.0);
      k.emplace_back(i + 1, i, -1.0);
    }
  }
  for (int i = 0; i < m; ++i) {  // row i watches unknowns 3i and 3i + 1
    r.emplace_back(i, 3 * i, 0.6);
    r.emplace_back(i, 3 * i + 1, 0.4);
  }
  c.problem.K.resize(n, n);
  c.problem.K.setFromTriplets(k.begin(), k.end());
  c.problem.B.resize(m, n);
  c.problem.B.setFromTriplets(r.begin(), r.end());
  c.problem.f = Eigen::VectorXd::LinSpaced(n, 1.0, -0.5);
  c.problem.G = Eigen::VectorXd::LinSpaced(m, 0.5, 4.0);
  const Eigen::MatrixXd Kd = Eigen::MatrixXd(c.problem.K), Bd = Eigen::MatrixXd(c.problem.B);
  c.S = Bd * Kd.ldlt().solve(Bd.transpose());
  c.b = Bd * Kd.ldlt().solve(c.problem.f) - c.problem.G;
  mortar::ContactSolverOptions o;
  o.kind = mortar::ContactSolverKind::pdas;
  o.backend = mortar::SpdBackend::simplicial_ldlt;
  c.lambda = mortar::solve_contact(c.problem, o).lambda;
  return c;
}

}  // namespace exercise_support
