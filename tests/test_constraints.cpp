#include <gtest/gtest.h>

#include "common/contact/constraints.hpp"

using namespace mortar;

namespace {
TwoBodies bodies_with(int n1, int n2, double jitter = 0) {
  TwoBodyGeometry g;
  g.n1 = n1;
  g.m1 = 3;
  g.n2 = n2;
  g.m2 = 4;
  g.jitter = jitter;
  return make_two_bodies(g, Material(1, 0.3), Material(2, 0.25));
}

// u with u_y = f1(x) in body 1 and f2(x) in body 2, u_x arbitrary
template <typename F1, typename F2>
Eigen::VectorXd field(const TwoBodies& b, F1 f1, F2 f2) {
  Eigen::VectorXd u(b.num_dofs());
  for (int l = 0; l < 2; ++l)
    for (int a = 0; a < b.body(l).mesh.num_nodes(); ++a) {
      const Eigen::Vector2d p = b.body(l).mesh.nodes[a];
      u[b.dof(l, a, 0)] = 0.3 * p.y() - p.x();  // tangential motion plays no part
      u[b.dof(l, a, 1)] = l == 0 ? f1(p.x()) : f2(p.x());
    }
  return u;
}

std::vector<bool> nothing_prescribed(const TwoBodies& b) { return std::vector<bool>(b.num_dofs(), false); }
}  // namespace

TEST(Constraints, both_matchings_accept_a_linear_continuous_normal_displacement) {
  const TwoBodies b = bodies_with(7, 11, 0.3);
  const auto u = field(b, [](double x) { return 0.2 + 0.5 * x; }, [](double x) { return 0.2 + 0.5 * x; });
  for (int nonmortar : {0, 1})
    for (Matching m : {Matching::pointwise, Matching::integral}) {
      const Constraints c = build_constraints(b, make_interface(b, nonmortar), m, nothing_prescribed(b));
      EXPECT_LT((c.B * u).cwiseAbs().maxCoeff(), 1e-15) << matching_name(m) << ", non-mortar " << nonmortar;
    }
}

TEST(Constraints, rows_measure_penetration_with_a_positive_sign) {
  // Body 2 pushed up by J into body 1: [u.n] = u2_y - u1_y = J everywhere.
  const double J = 1e-3;
  const TwoBodies b = bodies_with(5, 8, 0.2);
  const auto u = field(b, [](double) { return 0.0; }, [&](double) { return J; });
  const ContactInterface g = make_interface(b, 0);
  const Constraints point = build_constraints(b, g, Matching::pointwise, nothing_prescribed(b));
  ASSERT_EQ(point.B.rows(), 6);  // one row per node of xi^1
  for (int r = 0; r < point.B.rows(); ++r) EXPECT_NEAR((point.B * u)[r], J, 1e-15);
  const Constraints integral = build_constraints(b, g, Matching::integral, nothing_prescribed(b));
  ASSERT_EQ(integral.B.rows(), 4);  // dim M_h = N - 1
  const Eigen::VectorXd Bu = integral.B * u;
  // (B u)_i = J int psi_i, and the int psi_i add up to L
  EXPECT_NEAR(Bu.sum(), J * 1.0, 1e-15);
  for (int r = 0; r < Bu.size(); ++r) EXPECT_GT(Bu[r], 0.0);
}

TEST(Constraints, rows_on_prescribed_dofs_only_are_dropped) {
  const TwoBodies b = bodies_with(4, 6);
  std::vector<bool> prescribed = nothing_prescribed(b);
  // prescribe u_y on the whole of Gamma_c of both bodies
  for (int a : b.body(0).mesh.nodes_on(Side::bottom)) prescribed[b.dof(0, a, 1)] = true;
  for (int a : b.body(1).mesh.nodes_on(Side::top)) prescribed[b.dof(1, a, 1)] = true;
  for (Matching m : {Matching::pointwise, Matching::integral})
    EXPECT_EQ(build_constraints(b, make_interface(b, 0), m, prescribed).B.rows(), 0) << matching_name(m);
  // prescribing only the mortar side keeps every row
  std::vector<bool> mortar_only = nothing_prescribed(b);
  for (int a : b.body(1).mesh.nodes_on(Side::top)) mortar_only[b.dof(1, a, 1)] = true;
  EXPECT_EQ(build_constraints(b, make_interface(b, 0), Matching::integral, mortar_only).B.rows(), 3);
}

TEST(Constraints, pivots_are_the_non_mortar_normal_dofs) {
  const TwoBodies b = bodies_with(6, 4);
  for (int nonmortar : {0, 1}) {
    const ContactInterface g = make_interface(b, nonmortar);
    const Constraints c = build_constraints(b, g, Matching::integral, nothing_prescribed(b));
    for (std::size_t r = 0; r < c.pivot_dof.size(); ++r) {
      EXPECT_EQ(c.pivot_dof[r], b.dof(nonmortar, g.nonmortar_trace.nodes[r + 1], 1));
      EXPECT_NE(c.B.coeff(static_cast<int>(r), c.pivot_dof[r]), 0.0);
    }
  }
}

TEST(Constraints, the_rows_of_each_matching_are_the_mortar_matrices_or_the_nodal_interpolation) {
  // The steps chapters 3 and 4 take one by one give the same B as build_constraints.
  const TwoBodies b = bodies_with(6, 9, 0.25);
  for (int nonmortar : {0, 1}) {
    const ContactInterface g = make_interface(b, nonmortar);
    const MatchingRows integral = integral_matching_rows(g);
    EXPECT_EQ((Eigen::MatrixXd(integral.nonmortar) - Eigen::MatrixXd(g.matrices.D)).norm(), 0.0);
    EXPECT_EQ((Eigen::MatrixXd(integral.mortar) - Eigen::MatrixXd(g.matrices.M)).norm(), 0.0);
    const MatchingRows point = pointwise_matching_rows(contact_traces(b, nonmortar));
    ASSERT_EQ(point.nonmortar.rows(), g.nonmortar_trace.num_nodes());
    for (int a = 0; a < point.mortar.rows(); ++a)  // interpolation weights: two per row, sum 1
      EXPECT_NEAR(Eigen::MatrixXd(point.mortar).row(a).sum(), 1.0, 1e-15);
    for (Matching m : {Matching::pointwise, Matching::integral}) {
      const Constraints whole = build_constraints(b, g, m, nothing_prescribed(b));
      const Constraints steps =
          constraint_rows(b, g, m == Matching::integral ? integral : point, nothing_prescribed(b));
      EXPECT_EQ((Eigen::MatrixXd(whole.B) - Eigen::MatrixXd(steps.B)).norm(), 0.0) << matching_name(m);
      EXPECT_EQ(steps.matching, m);
    }
  }
}
