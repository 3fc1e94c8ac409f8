// The six-node element: symmetric, exactly three rigid-body modes, its stated rule exact, and
// the energy of every quadratic field right.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>

#include "common/fem/p2_elasticity.hpp"

using namespace mortar;

namespace {
const std::array<Eigen::Vector2d, 3> skewed = {Eigen::Vector2d(0.1, -0.2), Eigen::Vector2d(1.3, 0.1),
                                               Eigen::Vector2d(0.4, 0.9)};

// The six nodes: the vertices, then the midpoints of the edges 0-1, 1-2, 2-0.
std::array<Eigen::Vector2d, 6> nodes(const std::array<Eigen::Vector2d, 3>& x) {
  return {x[0], x[1], x[2], 0.5 * (x[0] + x[1]), 0.5 * (x[1] + x[2]), 0.5 * (x[2] + x[0])};
}

// Nodal values of a displacement field.
Eigen::Matrix<double, 12, 1> interpolate(const std::array<Eigen::Vector2d, 3>& x,
                                         const std::function<Eigen::Vector2d(const Eigen::Vector2d&)>& u) {
  Eigen::Matrix<double, 12, 1> v;
  const auto p = nodes(x);
  for (int a = 0; a < 6; ++a) v.segment<2>(2 * a) = u(p[a]);
  return v;
}
}  // namespace

TEST(P2Elasticity, element_matrix_is_symmetric) {
  const P2ElementMatrix K = p2_element_stiffness(skewed, Material(2.0, 0.3));
  EXPECT_LT((K - K.transpose()).cwiseAbs().maxCoeff(), 1e-14 * K.cwiseAbs().maxCoeff());
}

TEST(P2Elasticity, has_exactly_three_rigid_body_modes) {
  const P2ElementMatrix K = p2_element_stiffness(skewed, Material(1.0, 0.25));
  const Eigen::SelfAdjointEigenSolver<P2ElementMatrix> eig(K);
  const auto& ev = eig.eigenvalues();
  const double largest = ev.maxCoeff();
  int zero = 0;
  for (int k = 0; k < 12; ++k) {
    EXPECT_GT(ev[k], -1e-12 * largest);
    if (std::fabs(ev[k]) < 1e-12 * largest) ++zero;
  }
  EXPECT_EQ(zero, 3);
  EXPECT_GT(ev[3], 1e-4 * largest);  // the fourth is well away from zero
  // the three are the translations and the rotation
  for (const auto& mode : {std::function<Eigen::Vector2d(const Eigen::Vector2d&)>(
                               [](const Eigen::Vector2d&) { return Eigen::Vector2d(1, 0); }),
                           std::function<Eigen::Vector2d(const Eigen::Vector2d&)>(
                               [](const Eigen::Vector2d&) { return Eigen::Vector2d(0, 1); }),
                           std::function<Eigen::Vector2d(const Eigen::Vector2d&)>(
                               [](const Eigen::Vector2d& p) { return Eigen::Vector2d(-p.y(), p.x()); })})
    EXPECT_LT((K * interpolate(skewed, mode)).norm(), 1e-13 * largest);
}

// B^T C B is a quadratic: the rule of degree 2 gives K to round-off, as one of degree 6 does;
// the one-point rule (degree 1 here: n = 1 gives degree 0) does not.
TEST(P2Elasticity, the_stated_rule_is_exact) {
  const Material m(3.0, 0.2);
  EXPECT_EQ(triangle_rule(p2_stiffness_degree).degree, 2);
  const P2ElementMatrix K2 = p2_element_stiffness(skewed, m), K6 = p2_element_stiffness(skewed, m, triangle_rule(6));
  EXPECT_LT((K2 - K6).cwiseAbs().maxCoeff(), 1e-13 * K6.cwiseAbs().maxCoeff());
  const P2ElementMatrix K0 = p2_element_stiffness(skewed, m, triangle_rule(0));
  EXPECT_GT((K0 - K6).cwiseAbs().maxCoeff(), 1e-2 * K6.cwiseAbs().maxCoeff());
}

// u^T K u = int_T eps(u) : C eps(u) for a quadratic u, the integral taken independently: the
// strain of u from its exact derivatives, by a rule of degree 6.
TEST(P2Elasticity, energy_of_a_quadratic_field_is_exact) {
  const Material m(1.5, 0.35);
  const auto u = [](const Eigen::Vector2d& p) {
    const double x = p.x(), y = p.y();
    return Eigen::Vector2d(0.3 * x * x - 0.7 * x * y + 0.2 * y + 1.1 * y * y, -0.4 * x * y + 0.9 * x * x + 0.5 * x - y);
  };
  const auto strain = [](const Eigen::Vector2d& p) {
    const double x = p.x(), y = p.y();
    const double ux_x = 0.6 * x - 0.7 * y, ux_y = -0.7 * x + 0.2 + 2.2 * y;
    const double uy_x = -0.4 * y + 1.8 * x + 0.5, uy_y = -0.4 * x - 1;
    return Eigen::Vector3d(ux_x, uy_y, ux_y + uy_x);
  };
  const TriangleRule rule = triangle_rule(6);
  const auto& x = skewed;
  const double area = 0.5 * ((x[1] - x[0]).x() * (x[2] - x[0]).y() - (x[1] - x[0]).y() * (x[2] - x[0]).x());
  double energy = 0;
  for (std::size_t q = 0; q < rule.points.size(); ++q) {
    const Eigen::Vector2d p = x[0] + rule.points[q].x() * (x[1] - x[0]) + rule.points[q].y() * (x[2] - x[0]);
    const Eigen::Vector3d e = strain(p);
    energy += area * rule.weights[q] * e.dot(m.voigt() * e);
  }
  const Eigen::Matrix<double, 12, 1> v = interpolate(x, u);
  EXPECT_NEAR(v.dot(p2_element_stiffness(x, m) * v), energy, 1e-13 * energy);
}

TEST(P2Elasticity, refuses_a_triangle_of_the_wrong_orientation) {
  const std::array<Eigen::Vector2d, 3> flipped = {skewed[0], skewed[2], skewed[1]};
  EXPECT_THROW(p2_element_stiffness(flipped, Material(1, 0.3)), std::invalid_argument);
}
