// Contact with the dual basis (common/contact/dual_condensation.hpp): the condensed solve is
// the saddle point's solution, the semismooth Newton method solves the same discrete problem
// as chapter 5's active set on S, and a basis that is not dual is refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/contact/bilateral_contact.hpp"
#include "common/contact/contact_solvers.hpp"
#include "common/contact/dual_condensation.hpp"
#include "common/interface/dual_basis.hpp"

using namespace mortar;

namespace {
struct Built {
  TwoBodies bodies;
  SaddlePointProblem problem;
};

// Two bodies of n1 and n1 / ratio elements along Gamma_c, pressed by delta (Hertz-like gap
// with the given curvature; curvature 0 and delta 0 with a load: bilateral tests), multipliers
// in the dual basis (or the hats of M_h^1).
Built pressed(int n1, double ratio, double delta, double curvature, bool dual, double E2 = 1) {
  TwoBodyGeometry g;
  g.n1 = n1;
  g.m1 = n1;
  g.n2 = std::max(2, static_cast<int>(std::lround(n1 / ratio)));
  g.m2 = g.n2;
  g.H1 = g.H2 = 1;
  g.jitter = 0.2;
  TwoBodies bodies = make_two_bodies(g, Material(1, 0.3), Material(E2, 0.3));
  const SceneData scene = pressed_between_plates(bodies, delta);
  ContactInterface gamma = contact_traces(bodies, 0);
  gamma.grid = merge_traces(gamma.nonmortar_trace, gamma.mortar_trace);
  gamma.space = dual ? dual_end_modified_p1(gamma.nonmortar_trace) : end_modified_p1(gamma.nonmortar_trace);
  gamma.matrices = mortar_matrices(gamma.nonmortar_trace, gamma.mortar_trace, gamma.grid, gamma.space);
  const Constraints c = constraint_rows(bodies, gamma, integral_matching_rows(gamma),
                                        scene.prescribed_mask(bodies.num_dofs()));
  const Eigen::VectorXd G = tested_gap(gamma, c, [curvature](double x) { return curvature * (x - 0.5) * (x - 0.5) / 2; });
  const ReducedSystem system = eliminate_dirichlet(bodies.stiffness(), scene.F, scene.dirichlet);
  return {std::move(bodies), reduce_to_free_dofs(system, c, G)};
}

double relative(const Eigen::VectorXd& a, const Eigen::VectorXd& b) { return (a - b).norm() / b.norm(); }
}  // namespace

TEST(DualCondensation, bilateral_solve_is_the_saddle_point_solution) {
  for (double ratio : {1.5, 1.0 / 3, 3.0}) {
    // pressed by 0.01 with no gap and B u = 0: glued, the multipliers carry the load
    const Built b = pressed(12, ratio, 0.01, 0.0, true);
    const SaddlePointSolution reference = solve_saddle_point_lu(b.problem);
    CondensedContact c = condense_contact(b.problem);
    DualContactOptions o;
    o.unilateral = false;
    const DualContactSolution x = solve_dual_contact(c, o);
    EXPECT_LT(relative(x.u, reference.u), 1e-10) << "h2/h1 = " << ratio;
    EXPECT_LT(relative(x.lambda, reference.lambda), 1e-9) << "h2/h1 = " << ratio;
    EXPECT_EQ(x.iterations, 1);
    EXPECT_LT((b.problem.B * x.u).cwiseAbs().maxCoeff(), 1e-13 * x.u.cwiseAbs().maxCoeff());
  }
}

TEST(DualCondensation, newton_solves_the_same_problem_as_the_active_set_on_S) {
  for (const double E2 : {1.0, 1e3}) {
    const Built b = pressed(24, 1.5, 0.02, 1.0, true, E2);
    ContactSolverOptions pdas;
    pdas.tol = 1e-12;
    const ContactSolution reference =
        solve_contact({b.problem.K, b.problem.f, b.problem.B, b.problem.G}, pdas);
    CondensedContact c = condense_contact(b.problem);
    const DualContactSolution x = solve_dual_contact(c, {});
    EXPECT_LT(relative(x.lambda, reference.lambda), 1e-8) << "E2 = " << E2;
    EXPECT_LT(relative(x.u, reference.u), 1e-8) << "E2 = " << E2;
    EXPECT_EQ(x.residual, 0.0);
    // the weighted gap: zero where active, <= 0 elsewhere; lambda >= 0, zero where inactive
    for (int i = 0; i < c.rows(); ++i) {
      EXPECT_GE(x.lambda[i], 0.0);
      EXPECT_LE(x.w[i], 0.0);
      if (x.active[i]) EXPECT_EQ(x.w[i], 0.0);
      else EXPECT_EQ(x.lambda[i], 0.0);
    }
    const long active = std::count(x.active.begin(), x.active.end(), true);
    EXPECT_GT(active, 2);
    EXPECT_LT(active, c.rows());
    EXPECT_GE(x.iterations, 2);  // from an empty active set: at least the free bodies, then contact
  }
}

TEST(DualCondensation, the_right_first_active_set_takes_one_step) {
  const Built b = pressed(24, 1.5, 0.02, 1.0, true);
  CondensedContact c = condense_contact(b.problem);
  const DualContactSolution first = solve_dual_contact(c, {});
  DualContactOptions o;
  o.initial_active = first.active;
  const DualContactSolution again = solve_dual_contact(c, o);
  EXPECT_EQ(again.iterations, 1);
  EXPECT_LT(relative(again.lambda, first.lambda), 1e-12);
}

// The Newton method's active-set rule is strict, lambda_i + c_i w_i > 0: a row with zero
// multiplier and exactly zero weighted gap stays inactive and the method ends after one step.
// Two rows, T = I (Z the identity, b = 1), A = diag(4, 3), r = (0, -3): the free solve gives
// w = (0, -1), row 0 exactly closed, row 1 open. A ">= 0" would make row 0 active, a second step.
TEST(DualCondensation, newton_leaves_a_row_with_zero_gap_and_zero_force_inactive_in_one_step) {
  CondensedContact c;
  c.pivots = {0, 1};
  c.b = Eigen::VectorXd::Ones(2);
  c.Z.resize(2, 2);
  c.Z.setIdentity();
  c.g = Eigen::VectorXd::Zero(2);
  c.A.resize(2, 2);
  c.A.insert(0, 0) = 4;
  c.A.insert(1, 1) = 3;
  c.rhs = Eigen::Vector2d(0, -3);
  const DualContactSolution s = solve_dual_contact(c, {});
  EXPECT_EQ(s.iterations, 1);
  EXPECT_EQ(s.active_set_changes, 0);
  EXPECT_EQ(s.w[0], 0.0);
  EXPECT_DOUBLE_EQ(s.w[1], -1.0);
  EXPECT_EQ(s.lambda.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_DOUBLE_EQ(s.u[1], -1.0);  // u = T v + g
}

// With no load the bodies touch where the gap g = (x - 1/2)^2 / 2 vanishes. The standard
// psi_i >= 0 give G_i = int g psi_i >= 0, so nothing is pressed. The dual psi_i change sign:
// at a node where g is smaller than about g'' h^2 / 6, G_i = int g psi_i < 0, the unloaded
// bodies violate the weighted gap condition, and the dual problem pushes them apart there, with
// a force that vanishes as h -> 0 (the discrete problem is consistent, not exact).
TEST(DualCondensation, zero_load_presses_only_where_the_weighted_gap_is_negative) {
  double previous_force = 1;
  for (int n1 : {12, 24, 48}) {
    const Built b = pressed(n1, 1.5, 0.0, 1.0, true);
    CondensedContact c = condense_contact(b.problem);
    const DualContactSolution x = solve_dual_contact(c, {});
    int negative = 0;
    for (int i = 0; i < c.rows(); ++i) {
      const bool below = b.problem.G[i] < 0;
      negative += below;
      EXPECT_EQ(x.active[i], below) << "n1 = " << n1 << ", row " << i << ", G_i = " << b.problem.G[i];
    }
    EXPECT_GE(negative, 1) << "n1 = " << n1;
    const double force = x.lambda.sum();
    std::printf("n1 = %d: %d rows with G_i < 0, sum of lambda_i %.3e\n", n1, negative, force);
    EXPECT_GT(force, 0.0);
    EXPECT_LT(force, 0.5 * previous_force) << "n1 = " << n1;
    previous_force = force;
    EXPECT_TRUE(x.u.allFinite());
    // the standard basis: G >= 0, nothing pressed
    const Built s = pressed(n1, 1.5, 0.0, 1.0, false);
    EXPECT_GE(s.problem.G.minCoeff(), 0.0);
    const ContactSolution standard = solve_contact({s.problem.K, s.problem.f, s.problem.B, s.problem.G}, {});
    EXPECT_EQ(standard.lambda.cwiseAbs().maxCoeff(), 0.0);
  }
  // a gap bounded away from zero (0.01 > g'' h^2 / 6): no contact with the dual basis either
  const Built lifted = pressed(12, 1.5, 0.0, 1.0, true);
  SaddlePointProblem p = lifted.problem;
  p.G.array() += 0.01 * 1.0 / 12;  // int 0.01 psi_i >= 0.01 h_min, the same order
  CondensedContact c = condense_contact(p);
  const DualContactSolution x = solve_dual_contact(c, {});
  EXPECT_EQ(std::count(x.active.begin(), x.active.end(), true), 0);
}

TEST(DualCondensation, refuses_a_basis_that_is_not_dual) {
  const Built b = pressed(12, 1.5, 0.01, 1.0, false);
  EXPECT_THROW(condense_contact(b.problem), std::invalid_argument);
}

TEST(DualCondensation, records_the_round_off_it_drops) {
  const Built b = pressed(12, 1.0 / 3, 0.01, 1.0, true);
  const CondensedContact c = condense_contact(b.problem);
  EXPECT_LT(c.dropped_max, 1e-13);
}

TEST(SpdSolverRefactorize, reuses_the_analysis_for_new_values_on_the_same_pattern) {
  const Built b = pressed(8, 1.5, 0.01, 1.0, true);
  SparseMatrix K = b.problem.K;
  SpdSolver solver;
  solver.factorize(K);
  for (int k = 0; k < K.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(K, k); it; ++it)
      if (it.row() == it.col()) it.valueRef() *= 2;  // still SPD, same pattern
  solver.refactorize(K);
  SpdSolver fresh;
  fresh.factorize(K);
  const Eigen::VectorXd rhs = Eigen::VectorXd::LinSpaced(K.rows(), -1, 1);
  EXPECT_LT(relative(solver.solve(rhs), fresh.solve(rhs)), 1e-12);
  SpdSolver never;
  EXPECT_THROW(never.refactorize(K), std::logic_error);
}

// A load path condenses once: new loads through update_condensed_loads give the r and g of a
// condensation from scratch, since T and A do not depend on the loads.
TEST(DualCondensation, new_loads_on_the_same_rows_equal_a_fresh_condensation) {
  const Built a = pressed(12, 1.5, 0.01, 1.0, true), b = pressed(12, 1.5, 0.03, 1.0, true);
  CondensedContact updated = condense_contact(a.problem);
  update_condensed_loads(updated, b.problem.K, b.problem.f, b.problem.G);
  const CondensedContact fresh = condense_contact(b.problem);
  EXPECT_LT((updated.rhs - fresh.rhs).norm(), 1e-13 * fresh.rhs.norm());
  EXPECT_LT((updated.g - fresh.g).norm(), 1e-13 * fresh.g.norm());
  EXPECT_GT((condense_contact(a.problem).rhs - fresh.rhs).norm(), 0.01 * fresh.rhs.norm());  // the loads differ (by 20%)
}
