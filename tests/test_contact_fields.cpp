#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "common/contact/contact_fields.hpp"

using namespace mortar;

namespace {
TwoBodies bodies() {
  TwoBodyGeometry g;
  g.n1 = 6;
  g.m1 = 2;
  g.n2 = 9;
  g.m2 = 3;
  g.jitter = 0.3;
  return make_two_bodies(g, Material(1, 0.3), Material(1, 0.3));
}
std::vector<bool> free_mask(const TwoBodies& b) { return std::vector<bool>(b.num_dofs(), false); }
}  // namespace

TEST(ContactFields, constant_multipliers_give_a_constant_pressure_and_its_force) {
  const TwoBodies b = bodies();
  const ContactInterface g = make_interface(b, 0);
  const double p = 2.5;
  // integral: lambda_h = sum_i lambda_i psi_i = p when every lambda_i = p (sum psi = 1)
  const Constraints ci = build_constraints(b, g, Matching::integral, free_mask(b));
  const Eigen::VectorXd li = Eigen::VectorXd::Constant(ci.B.rows(), p);
  for (double v : contact_pressure(g, ci, li).value) EXPECT_NEAR(v, p, 1e-14);
  EXPECT_NEAR(total_contact_force(g, ci, li), p * 1.0, 1e-14);
  // pointwise: nodal forces p * tributary length
  const Constraints cp = build_constraints(b, g, Matching::pointwise, free_mask(b));
  Eigen::VectorXd lp(cp.B.rows());
  const auto& x = g.nonmortar_trace.x;
  for (int a = 0; a < lp.size(); ++a)
    lp[a] = p * 0.5 * ((a > 0 ? x[a] - x[a - 1] : 0) + (a + 1 < lp.size() ? x[a + 1] - x[a] : 0));
  for (double v : contact_pressure(g, cp, lp).value) EXPECT_NEAR(v, p, 1e-14);
  EXPECT_NEAR(total_contact_force(g, cp, lp), p * 1.0, 1e-14);
}

TEST(ContactFields, jump_is_u2y_minus_u1y_on_the_merged_grid) {
  const TwoBodies b = bodies();
  Eigen::VectorXd u = Eigen::VectorXd::Zero(b.num_dofs());
  for (int l = 0; l < 2; ++l)
    for (int a = 0; a < b.body(l).mesh.num_nodes(); ++a)
      u[b.dof(l, a, 1)] = (l == 0 ? 1.0 : 3.0) * b.body(l).mesh.nodes[a].x();
  for (int nonmortar : {0, 1}) {
    const InterfaceCurve j = normal_jump(b, make_interface(b, nonmortar), u);
    EXPECT_EQ(j.x.size(), make_interface(b, 0).grid.breakpoints.size());
    for (std::size_t k = 0; k < j.x.size(); ++k) EXPECT_NEAR(j.value[k], 2.0 * j.x[k], 1e-14);
    EXPECT_NEAR(l2_error(j, [](double x) { return 2.0 * x; }), 0.0, 1e-14);
    EXPECT_NEAR(l2_norm(j, [](double x) { return 2.0 * x; }), 2.0 / std::sqrt(3.0), 1e-14);
  }
}

// A pressure scales with E, and E may be given in any unit: the L2 distance of a pressure
// to an exact one must scale with it, also where its square would overflow or underflow.
TEST(ContactFields, l2_error_and_norm_scale_with_the_pressure_from_1e_minus300_to_1e300) {
  const std::vector<double> x = {0.0, 0.15, 0.4, 0.55, 0.8, 1.0};
  const auto exact = [](double t) { return 1.5 + std::cos(4.7 * t); };
  InterfaceCurve unit{x, {}};
  for (double t : x) unit.value.push_back(exact(t) + 0.1 * t * t);
  const double error = l2_error(unit, exact), norm = l2_norm(unit, exact);
  ASSERT_GT(error, 0.0);
  for (double scale : {1e-300, 1e-160, 1e160, 1e300}) {
    InterfaceCurve scaled = unit;
    for (double& v : scaled.value) v *= scale;
    const auto scaled_exact = [&](double t) { return scale * exact(t); };
    // the same arithmetic up to rounding: 1e-13 leaves room for the divisions by the scale
    EXPECT_NEAR(l2_error(scaled, scaled_exact) / scale, error, 1e-13 * error) << "scale " << scale;
    EXPECT_NEAR(l2_norm(scaled, scaled_exact) / scale, norm, 1e-13 * norm) << "scale " << scale;
  }
}
