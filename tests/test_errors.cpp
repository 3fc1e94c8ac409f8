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

// Values by hand, so that a norm off by a constant factor fails (a rate test cannot see one).
// u = (x^2, 0) on the unit square of two triangles; its P1 interpolant is (x, 0), so the error is
// (x^2 - x, 0): int (x^2 - x)^2 = 1/30 against int x^4 = 1/5, and eps_xx = 2x - 1 against 2x,
// int (2x - 1)^2 = 1/3 against int 4x^2 = 4/3, whatever the material (only eps_xx is nonzero).
TEST(Errors, interpolant_of_x_squared_on_one_square_has_the_norms_computed_by_hand) {
  const Mesh mesh = unit_square(1);
  const ExactSolution exact{[](const Eigen::Vector2d& p) { return Eigen::Vector2d(p.x() * p.x(), 0); },
                            [](const Eigen::Vector2d& p) {
                              Eigen::Matrix2d G = Eigen::Matrix2d::Zero();
                              G(0, 0) = 2 * p.x();
                              return G;
                            }};
  Eigen::VectorXd u(mesh.num_dofs());
  for (int a = 0; a < mesh.num_nodes(); ++a) u.segment<2>(2 * a) = Eigen::Vector2d(mesh.nodes[a].x(), 0);
  for (const Material& m : {Material(1, 0.3), Material(210e9, 0.45)}) {
    const ErrorNorms e = error_norms(mesh, m, u, exact);
    EXPECT_NEAR(e.relative_l2(), std::sqrt(1.0 / 6), 1e-14);
    EXPECT_NEAR(e.relative_h1_semi(), 0.5, 1e-14);
    EXPECT_NEAR(e.relative_energy(), 0.5, 1e-14);
    EXPECT_NEAR(e.error.l2, 1.0 / 30, 1e-15);
    EXPECT_NEAR(e.exact.h1_semi, 4.0 / 3, 1e-14);
    EXPECT_NEAR(e.exact.energy, (m.lambda() + 2 * m.mu()) * 4.0 / 3, 1e-14 * m.E());
  }
}

TEST(Errors, zero_approximation_has_relative_energy_and_h1_errors_one) {
  const Mesh mesh = unit_square(4);
  const ExactSolution exact{[](const Eigen::Vector2d& p) { return Eigen::Vector2d(p.x() * p.y(), p.x()); },
                            [](const Eigen::Vector2d& p) {
                              Eigen::Matrix2d G;
                              G << p.y(), p.x(), 1, 0;
                              return G;
                            }};
  const ErrorNorms e = error_norms(mesh, Material(1, 0.3), Eigen::VectorXd::Zero(mesh.num_dofs()), exact);
  EXPECT_NEAR(e.relative_energy(), 1.0, 1e-15);
  EXPECT_NEAR(e.relative_h1_semi(), 1.0, 1e-15);
  // |grad u|^2 = y^2 + x^2 + 1: 1/3 + 1/3 + 1
  EXPECT_NEAR(e.exact.h1_semi, 5.0 / 3, 1e-14);
}
