// Unilateral contact solvers on small two-body problems: the answers satisfy the
// complementarity conditions, both solvers agree, and the hard cases give clear results.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "common/contact/bilateral_contact.hpp"
#include "common/contact/contact_fields.hpp"
#include "common/contact/contact_solvers.hpp"

using namespace mortar;

namespace {
struct Built {
  TwoBodies bodies;
  Constraints constraints;
  ContactInterface gamma;
  ContactProblem problem;
  ReducedSystem system;
};

// Two bodies pressed together by delta, gap curvature (x - 1/2)^2 / 2: a Hertz-like contact.
Built pressed(int n1, double ratio, double delta, Matching m, double E2 = 1, double shift = 0,
              double curvature = 1) {
  TwoBodyGeometry g;
  g.n1 = n1;
  g.m1 = n1;
  g.n2 = std::max(2, static_cast<int>(std::lround(n1 / ratio)));
  g.m2 = g.n2;
  g.H1 = g.H2 = 1;
  TwoBodies bodies = make_two_bodies(g, Material(1, 0.3), Material(E2, 0.3));
  if (shift != 0) {  // move body 2's interior trace nodes by +-shift
    Mesh mesh = bodies.body(1).mesh;
    const auto& top = mesh.nodes_on(Side::top);
    for (std::size_t i = 1; i + 1 < top.size(); ++i) mesh.nodes[top[i]].x() += (i % 2 ? shift : -shift);
    bodies = TwoBodies(bodies.body(0), {mesh, bodies.body(1).material});
  }
  const SceneData scene = pressed_between_plates(bodies, delta);
  ContactInterface gamma = make_interface(bodies, 0);
  Constraints c = build_constraints(bodies, gamma, m, scene.prescribed_mask(bodies.num_dofs()));
  const Eigen::VectorXd G = tested_gap(gamma, c, [curvature](double x) { return curvature * (x - 0.5) * (x - 0.5) / 2; });
  ReducedSystem system = eliminate_dirichlet(bodies.stiffness(), scene.F, scene.dirichlet);
  const SaddlePointProblem p = reduce_to_free_dofs(system, c, G);
  return {std::move(bodies), std::move(c), std::move(gamma), {p.K, p.f, p.B, p.G}, std::move(system)};
}

ContactSolverOptions with(ContactSolverKind kind, bool accelerate = true) {
  ContactSolverOptions o;
  o.kind = kind;
  o.accelerate = accelerate;
  o.tol = 1e-10;
  return o;
}

// lambda >= 0, B u <= G, lambda (G - B u) = 0 and K u + B^T lambda = f, to tolerance
void expect_kkt(const ContactProblem& p, const ContactSolution& s, const std::string& what) {
  const Eigen::VectorXd gap = p.G - p.B * s.u;
  const double gscale = std::max(1e-300, gap.cwiseAbs().maxCoeff());
  const double lscale = std::max(1e-300, s.lambda.cwiseAbs().maxCoeff());
  EXPECT_GE(s.lambda.minCoeff(), 0.0) << what;
  EXPECT_GE(gap.minCoeff(), -1e-8 * gscale) << what;
  for (Eigen::Index i = 0; i < gap.size(); ++i)
    EXPECT_LT(std::fabs(s.lambda[i] * gap[i]), 1e-8 * lscale * gscale) << what << ", row " << i;
  EXPECT_LT((p.K * s.u + p.B.transpose() * s.lambda - p.f).norm(), 1e-8 * p.f.norm() + 1e-12) << what;
}
}  // namespace

TEST(ContactSolvers, pdas_and_uzawa_satisfy_complementarity_and_agree) {
  for (Matching m : {Matching::integral, Matching::pointwise}) {
    const Built b = pressed(24, 1.5, 0.02, m);
    const ContactSolution pd = solve_contact(b.problem, with(ContactSolverKind::pdas));
    const ContactSolution uz = solve_contact(b.problem, with(ContactSolverKind::uzawa));
    const ContactSolution plain = solve_contact(b.problem, with(ContactSolverKind::uzawa, false));
    expect_kkt(b.problem, pd, "pdas " + matching_name(m));
    expect_kkt(b.problem, uz, "uzawa " + matching_name(m));
    const double force = total_contact_force(b.gamma, b.constraints, pd.lambda);
    EXPECT_GT(force, 0.0);
    EXPECT_NEAR(total_contact_force(b.gamma, b.constraints, uz.lambda), force, 1e-7 * force);
    EXPECT_NEAR(total_contact_force(b.gamma, b.constraints, plain.lambda), force, 1e-7 * force);
    EXPECT_LE(pd.residual, 1e-10);
    EXPECT_LE(uz.residual, 1e-10);
    // some rows separate, some touch: a real contact problem
    EXPECT_GT((pd.lambda.array() == 0).count(), 0);
    EXPECT_GT((pd.lambda.array() > 0).count(), 0);
  }
}

// With CHOLMOD, S = B K^{-1} B^T is formed whole from the trailing block of a factor with
// the contact unknowns ordered last; with SimplicialLDLT its columns come from solves with K.
// Both are the same operator, so both solvers must reach the same u and lambda, to rounding
// and the solvers' tolerance: an entry of S wrong or misplaced in the Schur complement path
// changes the answer.
TEST(ContactSolvers, schur_complement_and_column_solves_give_the_same_answer) {
  if (!cholmod_available()) GTEST_SKIP() << "the Schur complement path needs CHOLMOD";
  for (Matching m : {Matching::integral, Matching::pointwise}) {
    const Built b = pressed(24, 1.5, 0.02, m);
    for (ContactSolverKind kind : {ContactSolverKind::pdas, ContactSolverKind::uzawa}) {
      ContactSolverOptions schur = with(kind), columns = with(kind);
      schur.backend = SpdBackend::cholmod;
      columns.backend = SpdBackend::simplicial_ldlt;
      const ContactSolution a = solve_contact(b.problem, schur), c = solve_contact(b.problem, columns);
      const std::string what = contact_solver_name(kind) + ", " + matching_name(m);
      expect_kkt(b.problem, a, what);
      ASSERT_GT(c.lambda.norm(), 0.0) << what;
      EXPECT_LT((a.u - c.u).norm(), 1e-9 * c.u.norm()) << what;
      EXPECT_LT((a.lambda - c.lambda).norm(), 1e-9 * c.lambda.norm()) << what;
      EXPECT_NEAR(a.S_norm, c.S_norm, 1e-9 * c.S_norm) << what;
      EXPECT_EQ(a.columns, static_cast<int>(b.problem.B.rows())) << what << ": S formed whole";
    }
  }
}

TEST(ContactSolvers, plain_uzawa_needs_more_iterations_as_h_shrinks_and_pdas_does_not) {
  const Built coarse = pressed(12, 1.5, 0.02, Matching::integral), fine = pressed(48, 1.5, 0.02, Matching::integral);
  const int u1 = solve_contact(coarse.problem, with(ContactSolverKind::uzawa, false)).iterations;
  const int u2 = solve_contact(fine.problem, with(ContactSolverKind::uzawa, false)).iterations;
  const int p2 = solve_contact(fine.problem, with(ContactSolverKind::pdas)).iterations;
  EXPECT_GT(u2, 2 * u1) << "plain Uzawa: " << u1 << " then " << u2 << " iterations";
  EXPECT_LT(p2, 20);
}

// Once the active set settles, plain Uzawa is gradient descent on S_AA and contracts by
// 1 - rho lambda_min(S_AA) per step at best: rho = 2 / (lambda_max + lambda_min) about halves
// the count of rho = 1 / ||S|| (measured: 2441 against 4835 iterations
// integral, 487 against 925 pointwise). The band 0.7 says "clearly
// fewer", with room for the steps taken at 1 / ||S|| before the active set settles.
TEST(ContactSolvers, step_from_both_ends_needs_fewer_plain_uzawa_iterations_than_one_over_norm) {
  for (Matching m : {Matching::integral, Matching::pointwise}) {
    const Built b = pressed(24, 1.5, 0.02, m);
    ContactSolverOptions both = with(ContactSolverKind::uzawa, false), norm = both;
    norm.step_from_both_ends = false;
    const ContactSolution fast = solve_contact(b.problem, both), slow = solve_contact(b.problem, norm);
    expect_kkt(b.problem, fast, "both ends, " + matching_name(m));
    EXPECT_LT(fast.iterations, 0.7 * slow.iterations)
        << matching_name(m) << ": " << fast.iterations << " against " << slow.iterations << " iterations";
    EXPECT_FALSE(fast.step_fell_back) << matching_name(m);
    EXPECT_GT(fast.lambda_min, 0.0) << matching_name(m);
    EXPECT_LT(fast.rho * fast.S_norm, 2.0) << matching_name(m) << ": the step must stay below 2 / ||S||";
    EXPECT_GT(fast.rho * fast.S_norm, 1.0) << matching_name(m) << ": the step did not leave 1 / ||S||";
    EXPECT_DOUBLE_EQ(slow.rho * slow.S_norm, 1.0);
    const double force = total_contact_force(b.gamma, b.constraints, slow.lambda);
    EXPECT_NEAR(total_contact_force(b.gamma, b.constraints, fast.lambda), force, 1e-7 * force) << matching_name(m);
  }
}

TEST(ContactSolvers, grazing_contact_gives_zero_force_and_an_empty_active_set) {
  for (ContactSolverKind kind : {ContactSolverKind::pdas, ContactSolverKind::uzawa}) {
    const Built b = pressed(12, 1.5, 0.0, Matching::integral);  // the bodies just touch at x = 1/2
    const ContactSolution s = solve_contact(b.problem, with(kind));
    EXPECT_TRUE(s.lambda.allFinite());
    EXPECT_EQ(s.lambda.cwiseAbs().maxCoeff(), 0.0);
    EXPECT_LT(s.u.cwiseAbs().maxCoeff(), 1e-14);
    EXPECT_EQ(s.residual, 0.0);
  }
}

TEST(ContactSolvers, uzawa_with_rho_too_large_fails_loudly) {
  const Built b = pressed(12, 1.5, 0.02, Matching::integral);
  ContactSolverOptions o = with(ContactSolverKind::uzawa, false);
  const double S_norm = solve_contact(b.problem, with(ContactSolverKind::pdas)).S_norm;
  // at the stability limit 2 / ||S|| and five times beyond it
  for (double factor : {2.0, 10.0}) {
    o.rho = factor / S_norm;
    try {
      solve_contact(b.problem, o);
      ADD_FAILURE() << "Uzawa with rho = " << factor << " / ||S|| did not fail";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("Uzawa diverges"), std::string::npos) << e.what();
    }
  }
}

// The Uzawa step lambda <- (lambda + rho (b - S lambda))_+ on problems small enough to follow
// by hand: K = I, B = I, f = (1, -1), G = 0, so S = I and b = (1, -1). With rho = 1 one step
// lands on the answer lambda = (1, 0) (the projection removes the second row's pull); with
// rho = 1/2 the first row halves its distance to 1 at each step, 1 - 2^-k, and never lands.
TEST(ContactSolvers, one_plain_uzawa_step_is_the_projected_gradient_step) {
  ContactProblem p;
  p.K.resize(2, 2);
  p.K.setIdentity();
  p.B = p.K;
  p.f = Eigen::Vector2d(1, -1);
  p.G = Eigen::Vector2d::Zero();
  ContactSolverOptions o = with(ContactSolverKind::uzawa, false);
  o.rho = 1;
  const ContactSolution one = solve_contact(p, o);
  EXPECT_EQ(one.iterations, 1);
  EXPECT_EQ(one.lambda[0], 1.0);
  EXPECT_EQ(one.lambda[1], 0.0);
  EXPECT_EQ(one.u[0], 0.0);   // K u = f - B^T lambda
  EXPECT_EQ(one.u[1], -1.0);  // row 1 is open: u_1 = -1 < G_1 = 0
  o.rho = 0.5;
  o.max_iterations = 3;
  try {
    solve_contact(p, o);
    ADD_FAILURE() << "rho = 1/2 reached the tolerance in 3 steps";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("did not reach"), std::string::npos) << e.what();
  }
  o.max_iterations = 100;
  const ContactSolution half = solve_contact(p, o);
  EXPECT_GT(half.iterations, 20);  // 1 - 2^-k: about 27 halvings to 1e-8
  EXPECT_LT(half.iterations, 35);
  EXPECT_NEAR(half.lambda[0], 1.0, 1e-7);
}

// The refusal bound is 2 / ||S|| itself: just below it Uzawa is accepted and converges (slowly,
// the error multiplied by |1 - rho mu| ~ 0.9 on the largest eigenvalue); at it the run is
// refused before any step, by the up-front test and not by the blow-up test in the loop.
TEST(ContactSolvers, uzawa_is_refused_from_rho_equal_to_two_over_the_norm_of_S) {
  const Built b = pressed(12, 1.5, 0.02, Matching::integral);
  const double S_norm = solve_contact(b.problem, with(ContactSolverKind::pdas)).S_norm;
  ContactSolverOptions o = with(ContactSolverKind::uzawa, false);
  o.rho = 1.9 / S_norm;
  const ContactSolution below = solve_contact(b.problem, o);
  EXPECT_LE(below.residual, o.tol);
  EXPECT_EQ(below.rho, o.rho);
  o.rho = 2.0 / S_norm;
  try {
    solve_contact(b.problem, o);
    ADD_FAILURE() << "rho = 2 / ||S|| was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("rho must stay below 2 / ||B K^{-1} B^T||"), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find("iterations"), std::string::npos) << "refused inside the loop: " << e.what();
  }
}

TEST(ContactSolvers, unilateral_equals_bilateral_when_contact_is_everywhere) {
  TwoBodyGeometry g;
  g.n1 = 12; g.m1 = 6; g.n2 = 8; g.m2 = 4;
  const ManufacturedContact exact(Material(1, 0.3), Material(3, 0.25), 1.0);
  const TwoBodies bodies = make_two_bodies(g, exact.material(0), exact.material(1));
  const SceneData scene = manufactured_scene(bodies, exact);
  const BilateralSolution bi = solve_bilateral(bodies, scene, {Matching::integral, 0, SaddleSolver::lu, fastest_spd_backend()});
  const ReducedSystem system = eliminate_dirichlet(bodies.stiffness(), scene.F, scene.dirichlet);
  const SaddlePointProblem p = reduce_to_free_dofs(system, bi.constraints, Eigen::VectorXd::Zero(bi.constraints.B.rows()));
  const ContactSolution uni = solve_contact({p.K, p.f, p.B, p.G}, with(ContactSolverKind::pdas));
  EXPECT_LT((system.expand(uni.u) - bi.u).norm(), 1e-9 * bi.u.norm());
  EXPECT_LT((uni.lambda - bi.lambda).norm(), 1e-8 * bi.lambda.norm());
  EXPECT_EQ((uni.lambda.array() > 0).count(), uni.lambda.size()) << "every multiplier active";
}

TEST(ContactSolvers, hard_cases_give_a_clear_answer) {
  // stiffness ratios 1e-6 .. 1e6 and mesh ratios 1/10 .. 10, both solvers, both matchings
  for (double E2 : {1e-6, 1.0, 1e6})
    for (double ratio : {0.1, 1.5, 10.0})
      for (Matching m : {Matching::integral, Matching::pointwise}) {
        const Built b = pressed(16, ratio, 0.02, m, E2);
        const ContactSolution pd = solve_contact(b.problem, with(ContactSolverKind::pdas));
        const ContactSolution uz = solve_contact(b.problem, with(ContactSolverKind::uzawa));
        const std::string what = "E2 " + std::to_string(E2) + ", ratio " + std::to_string(ratio) + ", " + matching_name(m);
        expect_kkt(b.problem, pd, "pdas, " + what);
        const double f1 = total_contact_force(b.gamma, b.constraints, pd.lambda);
        const double f2 = total_contact_force(b.gamma, b.constraints, uz.lambda);
        EXPECT_GT(f1, 0.0) << what;
        EXPECT_NEAR(f2, f1, 1e-6 * f1) << what;
      }
}

TEST(ContactSolvers, nearly_coincident_trace_nodes_change_nothing) {
  const Built matching = pressed(16, 1.0, 0.02, Matching::integral);
  const Built near = pressed(16, 1.0, 0.02, Matching::integral, 1.0, 1e-14);
  const ContactSolution a = solve_contact(matching.problem, with(ContactSolverKind::pdas));
  const ContactSolution b = solve_contact(near.problem, with(ContactSolverKind::pdas));
  ASSERT_EQ(a.lambda.size(), b.lambda.size());
  EXPECT_LT((a.lambda - b.lambda).norm(), 1e-8 * a.lambda.norm());
}

// Where delta is tiny, the penetration b_i = (B K^{-1} f - G)_i of the unconstrained bodies is
// of size delta near the centre but of size g (order one) where the gap is open. A stopping
// test in units of max |b_i| then accepts lambda = 0 at once; it must be in units of the
// penetration itself. Two families: the gap fixed (pointwise matching sees the narrow zone at
// its centre node; integral matching rightly finds no contact below delta ~ h^2), and the gap
// scaled with delta, where the exact discrete answer is proportional to delta.
TEST(ContactSolvers, uzawa_and_pdas_agree_for_loads_from_1e_12_to_1e_2) {
  struct Case {
    Matching m;
    bool gap_scaled;
  };
  for (const Case c : {Case{Matching::pointwise, false}, Case{Matching::pointwise, true}, Case{Matching::integral, true}})
    for (double delta : {1e-12, 1e-6, 1e-2}) {
      const Built b = pressed(24, 1.5, delta, c.m, 1, 0, c.gap_scaled ? delta / 1e-2 : 1.0);
      const ContactSolution pd = solve_contact(b.problem, with(ContactSolverKind::pdas));
      char what[96];
      std::snprintf(what, sizeof what, "%s, delta %.0e, gap %s", matching_name(c.m).c_str(), delta,
                    c.gap_scaled ? "scaled" : "fixed");
      expect_kkt(b.problem, pd, std::string("pdas, ") + what);
      const double f_pd = total_contact_force(b.gamma, b.constraints, pd.lambda);
      ASSERT_GT(f_pd, 0.0) << what;
      for (bool accelerate : {true, false}) {
        const ContactSolution uz = solve_contact(b.problem, with(ContactSolverKind::uzawa, accelerate));
        expect_kkt(b.problem, uz, std::string("uzawa, ") + what);
        EXPECT_NEAR(total_contact_force(b.gamma, b.constraints, uz.lambda) / delta, f_pd / delta,
                    1e-6 * f_pd / delta)
            << what << (accelerate ? ", accelerated" : ", plain") << ", " << uz.iterations << " iterations";
      }
    }
}

// A stiff body on a soft one (and the reverse): the plain active-set update can cycle. Every
// ratio from 1e-8 to 1e8 must end at the KKT point, for both matchings.
TEST(ContactSolvers, pdas_converges_for_stiffness_ratios_from_1e_8_to_1e8) {
  int cycled = 0;
  for (Matching m : {Matching::integral, Matching::pointwise})
    for (double E2 : {1e-8, 1e-7, 1e-6, 1e-4, 1e-2, 1.0, 1e2, 1e4, 1e6, 1e7, 1e8}) {
      const Built b = pressed(64, 1.5, 0.02, m, E2);
      char what[64];
      std::snprintf(what, sizeof what, "%s, E2 %.0e", matching_name(m).c_str(), E2);
      ContactSolution pd;
      ASSERT_NO_THROW(pd = solve_contact(b.problem, with(ContactSolverKind::pdas))) << what;
      expect_kkt(b.problem, pd, what);
      EXPECT_GT(total_contact_force(b.gamma, b.constraints, pd.lambda), 0.0) << what;
      if (pd.cycled_at > 0) ++cycled;
    }
  // the plain update cycles for some of these (measured: integral 1e-8), so the way out is tested
  EXPECT_GT(cycled, 0);
}

// The active-set rules are strict: a row that would neither penetrate nor open (b_i = 0,
// lambda_i = 0, gap exactly 0) stays inactive and the method ends after one step, with no row
// moved. A ">= 0" in either rule would make it enter the set and take a second step.
// K = diag(2, 1), f = (1, 0), B = [[0, 1], [1, 0]], G = (0, 1/2): the unconstrained u = (1/2, 0)
// touches row 1 (gap 0) and sits exactly on row 0's limit (u_y = 0 = G_0).
TEST(ContactSolvers, pdas_leaves_a_row_with_zero_gap_and_zero_force_inactive_in_one_step) {
  ContactProblem p;
  p.K.resize(2, 2);
  p.K.insert(0, 0) = 2;
  p.K.insert(1, 1) = 1;
  p.f = Eigen::Vector2d(1, 0);
  p.B.resize(2, 2);
  p.B.insert(0, 1) = 1;
  p.B.insert(1, 0) = 1;
  p.G = Eigen::Vector2d(0, 0.5);
  const ContactSolution s = solve_contact(p, with(ContactSolverKind::pdas));
  EXPECT_EQ(s.iterations, 1);
  EXPECT_EQ(s.active_set_changes, 0);
  EXPECT_EQ(s.lambda.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_NEAR(s.u[0], 0.5, 1e-15);
  EXPECT_EQ(s.residual, 0.0);
}
