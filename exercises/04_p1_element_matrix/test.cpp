#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "common/fem/p1_elasticity.hpp"
#include "exercise.hpp"

namespace {
const std::array<Eigen::Vector2d, 3> triangle = {Eigen::Vector2d(0.1, -0.2), Eigen::Vector2d(1.3, 0.15),
                                                 Eigen::Vector2d(0.4, 0.9)};
}

TEST(P1ElementMatrix, equals_the_library_matrix) {
  for (double nu : {0.0, 0.3, 0.45}) {
    const auto K = exercise::element_stiffness(triangle, 2.0, nu);
    const auto reference = mortar::element_stiffness(triangle, mortar::Material(2.0, nu));
    EXPECT_LT((K - reference).norm(), 1e-13 * reference.norm()) << "nu = " << nu;
  }
}

TEST(P1ElementMatrix, has_exactly_three_rigid_modes) {
  const auto K = exercise::element_stiffness(triangle, 1.0, 0.3);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> eig(K);
  const double tol = 1e-12 * eig.eigenvalues().cwiseAbs().maxCoeff();
  int zero = 0;
  for (int i = 0; i < 6; ++i) zero += std::abs(eig.eigenvalues()[i]) < tol;
  EXPECT_EQ(zero, 3);
  EXPECT_GT(eig.eigenvalues().minCoeff(), -tol);
}
