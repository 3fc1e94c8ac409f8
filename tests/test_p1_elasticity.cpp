#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "common/fem/p1_elasticity.hpp"

using namespace mortar;

namespace {
const std::array<Eigen::Vector2d, 3> skewed_triangle = {
    Eigen::Vector2d(0.1, -0.2), Eigen::Vector2d(1.3, 0.15), Eigen::Vector2d(0.4, 0.9)};
}

TEST(P1Elasticity, element_stiffness_is_symmetric_psd_with_three_rigid_modes) {
  for (double nu : {0.0, 0.3, 0.49}) {
    const ElementMatrix K = element_stiffness(skewed_triangle, Material(2.5, nu));
    EXPECT_LT((K - K.transpose()).norm(), 1e-14 * K.norm());
    const Eigen::SelfAdjointEigenSolver<ElementMatrix> eig(K);
    const auto ev = eig.eigenvalues();  // ascending
    const double tol = 1e-12 * ev.maxCoeff();
    for (int i = 0; i < 3; ++i) EXPECT_LT(std::fabs(ev[i]), tol) << "nu = " << nu << ", mode " << i;
    for (int i = 3; i < 6; ++i) EXPECT_GT(ev[i], tol) << "nu = " << nu << ", mode " << i;
  }
}

TEST(P1Elasticity, rigid_motions_produce_no_force) {
  const ElementMatrix K = element_stiffness(skewed_triangle, Material(1, 0.3));
  Eigen::Matrix<double, 6, 1> tx, ty, rot;
  for (int k = 0; k < 3; ++k) {
    tx.segment<2>(2 * k) << 1, 0;
    ty.segment<2>(2 * k) << 0, 1;
    rot.segment<2>(2 * k) << -skewed_triangle[k].y(), skewed_triangle[k].x();
  }
  EXPECT_LT((K * tx).norm(), 1e-14);
  EXPECT_LT((K * ty).norm(), 1e-14);
  EXPECT_LT((K * rot).norm(), 1e-14);
}

TEST(P1Elasticity, assembly_of_a_linear_field_gives_zero_residual) {
  // u linear => sigma constant => K u equals the boundary load of the traction sigma n:
  // zero at interior nodes, and K u - F_traction = 0 everywhere.
  RectangleSpec s;
  s.x1 = 2; s.nx = 9; s.ny = 7; s.jitter = 0.4;
  const Mesh mesh = rectangle_mesh(s);
  const Material mat(3.0, 0.35);
  Eigen::Matrix2d G;
  G << 0.3, -0.1, 0.25, -0.2;
  Eigen::VectorXd u(mesh.num_dofs());
  for (int a = 0; a < mesh.num_nodes(); ++a) u.segment<2>(2 * a) = G * mesh.nodes[a];
  const Eigen::Matrix2d eps = 0.5 * (G + G.transpose());
  const Eigen::Matrix2d sigma = mat.lambda() * eps.trace() * Eigen::Matrix2d::Identity() + 2 * mat.mu() * eps;
  Eigen::VectorXd F = Eigen::VectorXd::Zero(mesh.num_dofs());
  const std::pair<Side, Eigen::Vector2d> sides[] = {{Side::bottom, {0, -1}}, {Side::right, {1, 0}},
                                                    {Side::top, {0, 1}}, {Side::left, {-1, 0}}};
  for (const auto& [side, n] : sides)
    add_traction(F, mesh, side, [&](const Eigen::Vector2d&) -> Eigen::Vector2d { return sigma * n; }, 1);
  const SparseMatrix K = assemble_stiffness(mesh, mat);
  EXPECT_LT((K * u - F).norm(), 1e-12 * (K * u).norm() + 1e-14);
  const Eigen::VectorXd stress = element_stresses(mesh, mat, u)[5];
  EXPECT_NEAR(stress[0], sigma(0, 0), 1e-13);
  EXPECT_NEAR(stress[1], sigma(1, 1), 1e-13);
  EXPECT_NEAR(stress[2], sigma(0, 1), 1e-13);
}

TEST(P1Elasticity, body_force_load_integrates_exactly) {
  // For a constant body force, the sum of the load components is f times the area.
  RectangleSpec s;
  s.nx = 5; s.ny = 4; s.jitter = 0.3;
  const Mesh mesh = rectangle_mesh(s);
  const Eigen::VectorXd F = body_force_vector(mesh, [](const Eigen::Vector2d&) { return Eigen::Vector2d(2, -3); }, 1);
  double fx = 0, fy = 0;
  for (int a = 0; a < mesh.num_nodes(); ++a) {
    fx += F[2 * a];
    fy += F[2 * a + 1];
  }
  EXPECT_NEAR(fx, 2.0, 1e-13);
  EXPECT_NEAR(fy, -3.0, 1e-13);
}

TEST(P1Elasticity, material_rejects_bad_parameters) {
  EXPECT_THROW(Material(-1, 0.3), std::invalid_argument);
  EXPECT_THROW(Material(0, 0.3), std::invalid_argument);
  EXPECT_THROW(Material(1, 0.5), std::invalid_argument);
  EXPECT_THROW(Material(1, -1), std::invalid_argument);
  EXPECT_THROW(Material(std::nan(""), 0.3), std::invalid_argument);
  const Material m(1, 0.25);
  EXPECT_NEAR(m.lambda(), 0.4, 1e-15);
  EXPECT_NEAR(m.mu(), 0.4, 1e-15);
}

TEST(P1Elasticity, degenerate_triangle_is_reported) {
  const std::array<Eigen::Vector2d, 3> flat = {Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 0), Eigen::Vector2d(2, 0)};
  EXPECT_THROW(element_stiffness(flat, Material(1, 0.3)), std::invalid_argument);
}
