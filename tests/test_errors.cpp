#include <gtest/gtest.h>

#include <cmath>

#include "common/fem/errors.hpp"

using namespace mortar;

namespace {
Mesh unit_square(int n) {
  RectangleSpec s;
  s.nx = n; s.ny = n;
  return rectangle_mesh(s);
}
}  // namespace

TEST(Errors, interpolant_of_a_linear_field_has_zero_error) {
  const Mesh mesh = unit_square(5);
  Eigen::Matrix2d G;
  G << 1, 2, -0.5, 0.3;
  const ExactSolution exact{[&](const Eigen::Vector2d& p) -> Eigen::Vector2d { return G * p; },
                            [&](const Eigen::Vector2d&) { return G; }};
  Eigen::VectorXd u(mesh.num_dofs());
  for (int a = 0; a < mesh.num_nodes(); ++a) u.segment<2>(2 * a) = G * mesh.nodes[a];
  const ErrorNorms e = error_norms(mesh, Material(1, 0.3), u, exact);
  EXPECT_LT(e.relative_l2(), 1e-14);
  EXPECT_LT(e.relative_energy(), 1e-14);
}

TEST(Errors, zero_approximation_has_relative_error_one_and_exact_norms) {
  const Mesh mesh = unit_square(8);
  const double pi = std::acos(-1.0);
  const ExactSolution exact{
      [&](const Eigen::Vector2d& p) { return Eigen::Vector2d(std::sin(pi * p.x()), 0); },
      [&](const Eigen::Vector2d& p) {
        Eigen::Matrix2d G = Eigen::Matrix2d::Zero();
        G(0, 0) = pi * std::cos(pi * p.x());
        return G;
      }};
  const ErrorNorms e = error_norms(mesh, Material(1, 0.3), Eigen::VectorXd::Zero(mesh.num_dofs()), exact, 8);
  EXPECT_NEAR(e.relative_l2(), 1.0, 1e-15);
  EXPECT_NEAR(e.exact.l2, 0.5, 1e-9);             // int sin^2(pi x) over the square
  EXPECT_NEAR(e.exact.h1_semi, pi * pi / 2, 1e-8);
}
