#include <gtest/gtest.h>

#include <vector>

#include "common/contact/constraints.hpp"
#include "exercise.hpp"

namespace {
// |c - expected| entry by entry, with the entry's index in the message
void expect_row(const Eigen::VectorXd& c, const std::vector<double>& expected, double tol, double xa) {
  ASSERT_EQ(c.size(), static_cast<Eigen::Index>(expected.size())) << "x_a = " << xa << ": one entry per mortar node";
  for (std::size_t k = 0; k < expected.size(); ++k)
    EXPECT_NEAR(c[static_cast<Eigen::Index>(k)], expected[k], tol) << "x_a = " << xa << ", mortar node " << k;
}
}  // namespace

TEST(PointwiseRow, equals_the_library_rows) {
  mortar::TwoBodyGeometry g;
  g.n1 = 7; g.m1 = 2; g.n2 = 5; g.m2 = 2; g.jitter = 0.3;
  const mortar::TwoBodies b = mortar::make_two_bodies(g, mortar::Material(1, 0.3), mortar::Material(1, 0.3));
  const mortar::ContactInterface gamma = mortar::make_interface(b, 0);
  const mortar::Constraints c = mortar::build_constraints(b, gamma, mortar::Matching::pointwise,
                                                          std::vector<bool>(b.num_dofs(), false));
  for (int a = 0; a < gamma.nonmortar_trace.num_nodes(); ++a) {
    const Eigen::VectorXd mine = exercise::pointwise_row(gamma.nonmortar_trace.x[a], gamma.mortar_trace.x);
    ASSERT_EQ(mine.size(), gamma.mortar_trace.num_nodes());
    for (int k = 0; k < gamma.mortar_trace.num_nodes(); ++k)
      EXPECT_NEAR(mine[k], c.B.coeff(a, b.dof(1, gamma.mortar_trace.nodes[k], 1)), 1e-15) << "node " << a << ", mortar node " << k;
  }
}

TEST(PointwiseRow, interpolates_linear_functions_exactly) {
  const std::vector<double> x = {0.0, 0.3, 0.45, 0.8, 1.0};
  for (double xa : {0.0, 0.1, 0.45, 0.7, 1.0}) {
    const Eigen::VectorXd c = exercise::pointwise_row(xa, x);
    ASSERT_EQ(c.size(), 5);
    double value = 0;
    for (std::size_t k = 0; k < x.size(); ++k) value += c[k] * (2 - 3 * x[k]);
    EXPECT_NEAR(value, 2 - 3 * xa, 1e-15) << "x_a = " << xa;
    EXPECT_NEAR(c.sum(), 1.0, 1e-15);
  }
}

// Worked by hand: x_a = 0.1 lies in the mortar element [0, 0.3], a third of the way along, so
// the linear function that is 1 at 0 and 0 at 0.3 is 2/3 there; x_a = 0.7 lies in [0.45, 0.8],
// 0.25 / 0.35 = 5/7 of the way along; a mortar node, end or interior, gets its own function only.
TEST(PointwiseRow, matches_cases_worked_by_hand) {
  const std::vector<double> x = {0.0, 0.3, 0.45, 0.8, 1.0};
  expect_row(exercise::pointwise_row(0.1, x), {2.0 / 3, 1.0 / 3, 0, 0, 0}, 1e-15, 0.1);
  expect_row(exercise::pointwise_row(0.7, x), {0, 0, 2.0 / 7, 5.0 / 7, 0}, 1e-15, 0.7);
  expect_row(exercise::pointwise_row(1.0, x), {0, 0, 0, 0, 1}, 0.0, 1.0);
  expect_row(exercise::pointwise_row(0.45, x), {0, 0, 1, 0, 0}, 0.0, 0.45);
  expect_row(exercise::pointwise_row(0.0, x), {1, 0, 0, 0, 0}, 0.0, 0.0);
}

// The mortar side covers [0.2, 1] only (the library's traces always share their ends, so
// InterfaceTrace::evaluate would extrapolate the first element's line to x_a = 0.1 and give
// (1.25, -0.25, 0)). A node outside gets the zero row, a node on or inside the ends the usual
// one: x_a = 0.5 is 0.3 / 0.4 = 3/4 along [0.2, 0.6]. A node a round-off past an end is still on it.
TEST(PointwiseRow, a_node_the_mortar_side_does_not_cover_gets_a_zero_row) {
  const std::vector<double> x = {0.2, 0.6, 1.0};
  expect_row(exercise::pointwise_row(0.1, x), {0, 0, 0}, 0.0, 0.1);
  expect_row(exercise::pointwise_row(1.05, x), {0, 0, 0}, 0.0, 1.05);
  expect_row(exercise::pointwise_row(-3.0, x), {0, 0, 0}, 0.0, -3.0);
  expect_row(exercise::pointwise_row(0.2, x), {1, 0, 0}, 0.0, 0.2);
  expect_row(exercise::pointwise_row(0.5, x), {0.25, 0.75, 0}, 1e-15, 0.5);
  expect_row(exercise::pointwise_row(1.0, x), {0, 0, 1}, 0.0, 1.0);
  expect_row(exercise::pointwise_row(1.0 + 1e-14, x), {0, 0, 1}, 1e-12, 1.0 + 1e-14);
  expect_row(exercise::pointwise_row(0.2 - 1e-14, x), {1, 0, 0}, 1e-12, 0.2 - 1e-14);
}
