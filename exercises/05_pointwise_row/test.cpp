#include <gtest/gtest.h>

#include "common/contact/constraints.hpp"
#include "exercise.hpp"

TEST(PointwiseRow, equals_the_library_rows) {
  mortar::TwoBodyGeometry g;
  g.n1 = 7; g.m1 = 2; g.n2 = 5; g.m2 = 2; g.jitter = 0.3;
  const mortar::TwoBodies b = mortar::make_two_bodies(g, mortar::Material(1, 0.3), mortar::Material(1, 0.3));
  const mortar::ContactInterface gamma = mortar::make_interface(b, 0);
  const mortar::Constraints c = mortar::build_constraints(b, gamma, mortar::Matching::pointwise,
                                                          std::vector<bool>(b.num_dofs(), false));
  for (int a = 0; a < gamma.nonmortar_trace.num_nodes(); ++a) {
    const Eigen::VectorXd mine = exercise::pointwise_row(gamma.nonmortar_trace.x[a], gamma.mortar_trace.x);
    for (int k = 0; k < gamma.mortar_trace.num_nodes(); ++k)
      EXPECT_NEAR(mine[k], c.B.coeff(a, b.dof(1, gamma.mortar_trace.nodes[k], 1)), 1e-15) << "node " << a << ", mortar node " << k;
  }
}

TEST(PointwiseRow, interpolates_linear_functions_exactly) {
  const std::vector<double> x = {0.0, 0.3, 0.45, 0.8, 1.0};
  for (double xa : {0.0, 0.1, 0.45, 0.7, 1.0}) {
    const Eigen::VectorXd c = exercise::pointwise_row(xa, x);
    double value = 0;
    for (std::size_t k = 0; k < x.size(); ++k) value += c[k] * (2 - 3 * x[k]);
    EXPECT_NEAR(value, 2 - 3 * xa, 1e-15) << "x_a = " << xa;
    EXPECT_NEAR(c.sum(), 1.0, 1e-15);
  }
}
