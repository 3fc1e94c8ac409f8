// The nodal conditions of friction (common/contact/friction_conditions.hpp): each case of the
// complementarity functions (open, stick, slip), their zeros where the friction law holds, and
// their generalized derivatives against central differences away from the kinks.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "common/contact/friction_conditions.hpp"

using namespace mortar;

namespace {
NodalLaw coulomb(double F) {
  NodalLaw law;
  law.law = FrictionLaw::coulomb;
  law.friction = F;
  law.c_n = 2.0;
  law.c_t = 3.0;
  return law;
}
NodalLaw tresca(double s) {
  NodalLaw law = coulomb(0);
  law.law = FrictionLaw::tresca;
  law.threshold = s;
  return law;
}
}  // namespace

TEST(FrictionConditions, a_node_out_of_contact_transmits_nothing) {
  const NodalLaw law = coulomb(0.5);
  const NodalUnknowns x{0.0, -0.2, 0.0, 0.7};  // gap open, no multipliers, any slip
  EXPECT_EQ(node_status(x, law), NodeStatus::open);
  EXPECT_EQ(normal_function(x, law), 0.0);
  EXPECT_EQ(tangential_function(x, law), 0.0);
  const NodalUnknowns pulled{0.0, -0.2, 0.3, 0.0};  // a shear on an open node violates the law
  EXPECT_EQ(tangential_function(pulled, law), 0.3);
  EXPECT_EQ(friction_threshold(x, law), 0.0);
}

TEST(FrictionConditions, stick_and_slip_solve_the_tangential_equation_exactly_where_the_law_holds) {
  const NodalLaw law = coulomb(0.4);
  // stick: closed, |lambda_t| = 0.3 < F lambda_n = 0.4, no slip
  const NodalUnknowns stick{1.0, 0.0, 0.3, 0.0};
  EXPECT_EQ(node_status(stick, law), NodeStatus::stick);
  EXPECT_EQ(normal_function(stick, law), 0.0);
  EXPECT_EQ(tangential_function(stick, law), 0.0);
  // slip: lambda_t = s in the direction of the slip
  for (double sign : {1.0, -1.0}) {
    const NodalUnknowns slip{1.0, 0.0, 0.4 * sign, 0.25 * sign};
    EXPECT_EQ(node_status(slip, law), NodeStatus::slip);
    EXPECT_NEAR(tangential_function(slip, law), 0.0, 1e-15);
    // slipping against the shear violates the law
    const NodalUnknowns wrong{1.0, 0.0, 0.4 * sign, -0.25 * sign};
    EXPECT_GT(std::fabs(tangential_function(wrong, law)), 0.1);
  }
  // a stuck node that moves, or a shear above the threshold, does not solve it
  EXPECT_GT(std::fabs(tangential_function({1.0, 0.0, 0.3, 0.01}, law)), 1e-3);
  EXPECT_GT(std::fabs(tangential_function({1.0, 0.0, 0.5, 0.0}, law)), 1e-3);
  // penetration and a negative pressure both violate the normal law
  EXPECT_NE(normal_function({1.0, 0.1, 0, 0}, law), 0.0);
  EXPECT_NE(normal_function({-1.0, -0.1, 0, 0}, law), 0.0);
}

TEST(FrictionConditions, tresca_uses_its_threshold_and_coulomb_the_pressure) {
  const NodalUnknowns x{2.0, 0.0, 0.0, 0.0};
  EXPECT_EQ(friction_threshold(x, tresca(0.7)), 0.7);
  EXPECT_DOUBLE_EQ(friction_threshold(x, coulomb(0.3)), 0.6);
  const NodalUnknowns penetrating{2.0, 0.1, 0.0, 0.0};  // F max(0, lambda_n + c_n w_n)
  EXPECT_DOUBLE_EQ(friction_threshold(penetrating, coulomb(0.3)), 0.3 * 2.2);
}

TEST(FrictionConditions, zero_friction_means_lambda_t_is_zero) {
  const NodalUnknowns x{1.0, 0.0, 0.2, 0.0};
  EXPECT_EQ(tangential_function(x, coulomb(0)), 0.2);
  EXPECT_EQ(tangential_gradient(x, coulomb(0)).lambda_t, 1.0);
}

TEST(FrictionConditions, generalized_derivatives_match_central_differences_away_from_the_kinks) {
  const double h = 1e-7;
  const NodalUnknowns points[] = {
      {1.0, 0.01, 0.3, 0.02},    // stick (Coulomb stick with a slip: C_t depends on lambda_n)
      {1.0, -0.1, 0.5, 0.2},     // slip, positive
      {0.8, 0.05, -0.9, -0.4},   // slip, negative, |lambda_t| > s
      {-0.5, -0.3, 0.2, 0.1},    // open
  };
  for (const NodalLaw& law : {coulomb(0.4), tresca(0.35)})
    for (const NodalUnknowns& x : points) {
      const NodalGradient gn = normal_gradient(x, law), gt = tangential_gradient(x, law, false);
      const double analytic_n[4] = {gn.lambda_n, gn.w_n, gn.lambda_t, gn.dw_t};
      const double analytic_t[4] = {gt.lambda_n, gt.w_n, gt.lambda_t, gt.dw_t};
      for (int k = 0; k < 4; ++k) {
        NodalUnknowns plus = x, minus = x;
        double* p[4] = {&plus.lambda_n, &plus.w_n, &plus.lambda_t, &plus.dw_t};
        double* q[4] = {&minus.lambda_n, &minus.w_n, &minus.lambda_t, &minus.dw_t};
        *p[k] += h;
        *q[k] -= h;
        ASSERT_EQ(node_status(plus, law), node_status(x, law));
        ASSERT_EQ(node_status(minus, law), node_status(x, law));
        const double fd_n = (normal_function(plus, law) - normal_function(minus, law)) / (2 * h);
        const double fd_t = (tangential_function(plus, law) - tangential_function(minus, law)) / (2 * h);
        EXPECT_NEAR(analytic_n[k], fd_n, 1e-7) << node_status_name(node_status(x, law)) << " variable " << k;
        EXPECT_NEAR(analytic_t[k], fd_t, 1e-7) << node_status_name(node_status(x, law)) << " variable " << k;
      }
    }
}

TEST(FrictionConditions, the_bounded_gradient_differs_only_where_lambda_t_exceeds_the_threshold) {
  const NodalLaw law = coulomb(0.4);
  const NodalUnknowns inside{1.0, 0.0, 0.3, 0.2}, outside{1.0, 0.0, 0.9, 0.2};
  ASSERT_EQ(node_status(inside, law), NodeStatus::slip);
  const NodalGradient a = tangential_gradient(inside, law, true), b = tangential_gradient(inside, law, false);
  EXPECT_EQ(a.lambda_t, b.lambda_t);
  EXPECT_EQ(a.dw_t, b.dw_t);
  const NodalGradient c = tangential_gradient(outside, law, true), d = tangential_gradient(outside, law, false);
  EXPECT_NE(c.lambda_t, d.lambda_t);
  // as if lambda_t = s: d C_t / d dw_t = c_t (sign(z) lambda_t - s) = 0
  EXPECT_NEAR(c.dw_t, 0.0, 1e-15);
}

// The law (README.md, "The problem"): |lambda_t| < s is stick, |lambda_t| = s is slip with a
// rate alpha lambda_t, alpha >= 0, zero included. A node in contact with z = lambda_t + c_t dw_t
// exactly on the threshold has, where C_t = 0, lambda_t = z and dw_t = 0: its shear equals its
// threshold, so the law puts it among the slipping nodes, however little it moves.
TEST(FrictionConditions, a_shear_exactly_at_its_threshold_slips_by_the_law) {
  const NodalUnknowns on_threshold{1.0, 0.0, 0.5, 0.0};  // s = F lambda_n = 0.5 = |z|, exactly
  for (const NodalLaw& law : {coulomb(0.5), tresca(0.5)}) {
    ASSERT_EQ(friction_threshold(on_threshold, law), 0.5);
    EXPECT_EQ(node_status(on_threshold, law), NodeStatus::slip);
    EXPECT_EQ(tangential_function(on_threshold, law), 0.0);  // the law holds there
    const NodalUnknowns negative{1.0, 0.0, -0.5, 0.0};
    EXPECT_EQ(node_status(negative, law), NodeStatus::slip);
    // just inside the threshold it sticks
    EXPECT_EQ(node_status({1.0, 0.0, 0.4999, 0.0}, law), NodeStatus::stick);
  }
}

// The stopping test's nodal residuals are in the unit of the multipliers: a slip node's
// tangential residual over its size is the relative distance of |lambda_t| from s, and scaling
// every multiplier and c by the same factor (a change of the unit of E) scales residual and
// size alike.
TEST(FrictionConditions, nodal_residuals_are_relative_to_the_node_and_free_of_the_unit_of_E) {
  const NodalUnknowns slip{1.0, 0.0, 0.49, 0.1};  // z = 0.49 + 3 x 0.1 > s = 0.5
  ASSERT_EQ(node_status(slip, coulomb(0.5)), NodeStatus::slip);
  const NodalResidual r = nodal_residual(slip, coulomb(0.5));
  EXPECT_NEAR(r.tangential / r.tangential_size, (0.49 - 0.5) / 0.5, 1e-15);
  for (double E : {1e-100, 1e100}) {
    NodalLaw law = coulomb(0.5);
    law.c_n *= E;
    law.c_t *= E;
    const NodalUnknowns scaled{E * slip.lambda_n, slip.w_n, E * slip.lambda_t, slip.dw_t};
    const NodalResidual s = nodal_residual(scaled, law);
    EXPECT_NEAR(s.tangential / s.tangential_size, r.tangential / r.tangential_size, 1e-14) << "E = " << E;
    EXPECT_NEAR(s.normal_size / E, r.normal_size, 1e-14) << "E = " << E;
  }
}

// An infinite Tresca threshold forbids slip on every node, in contact or not: the tangential
// row is dw_t = 0 (the no-slip start of friction_newton.cpp).
TEST(FrictionConditions, an_infinite_threshold_forbids_slip_everywhere) {
  const NodalLaw law = tresca(std::numeric_limits<double>::infinity());
  for (const NodalUnknowns& x : {NodalUnknowns{1.0, 0.0, 5.0, 0.2}, NodalUnknowns{0.0, -0.3, 0.0, 0.2}}) {
    EXPECT_DOUBLE_EQ(tangential_function(x, law), -3.0 * 0.2);
    const NodalGradient g = tangential_gradient(x, law);
    EXPECT_EQ(g.dw_t, -3.0);
    EXPECT_EQ(g.lambda_t, 0.0);
  }
  EXPECT_EQ(node_status({1.0, 0.0, 1e300, 0.0}, law), NodeStatus::stick);
}
