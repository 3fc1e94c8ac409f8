#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "exercise.hpp"
#include "small_contact_problem.hpp"

namespace {
// max |1 - rho mu| over the eigenvalues mu of S: how much the unprojected error can grow per step
double amplification(const Eigen::MatrixXd& S, double rho) {
  const Eigen::VectorXd mu = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(S).eigenvalues();
  return (Eigen::VectorXd::Ones(mu.size()) - rho * mu).cwiseAbs().maxCoeff();
}
}  // namespace

TEST(UzawaStep, projects_on_nonnegative_multipliers) {
  const Eigen::Vector3d lambda(1.0, 0.2, 0.0), penetration(-0.5, -1.0, 0.3);
  const Eigen::VectorXd next = exercise::uzawa_step(lambda, penetration, 0.5);
  EXPECT_DOUBLE_EQ(next[0], 0.75);
  EXPECT_DOUBLE_EQ(next[1], 0.0);  // would be -0.3: the contact opens
  EXPECT_DOUBLE_EQ(next[2], 0.15);
}

// Worked by hand. (1 -1; -1 1) has the eigenvalues 0 (eigenvector (1, 1)) and 2 (eigenvector
// (1, -1)): 1 - 2 rho stays in (-1, 1) for 0 < rho < 1, so rho* = 1. A power iteration started
// from (1, 1) sees only the eigenvalue 0. (2 1; 1 2) has the eigenvalues 1 and 3: rho* = 2/3.
TEST(UzawaStep, rho_limit_of_two_matrices_worked_by_hand) {
  const Eigen::Matrix2d singular = (Eigen::Matrix2d() << 1.0, -1.0, -1.0, 1.0).finished();
  const Eigen::Matrix2d definite = (Eigen::Matrix2d() << 2.0, 1.0, 1.0, 2.0).finished();
  EXPECT_NEAR(exercise::rho_limit(singular), 1.0, 1e-10);
  EXPECT_NEAR(exercise::rho_limit(definite), 2.0 / 3.0, 1e-10 * 2.0 / 3.0);
}

TEST(UzawaStep, rho_limit_is_where_the_iteration_stops_contracting) {
  const auto c = exercise_support::small_contact();
  const double limit = exercise::rho_limit(c.S);
  ASSERT_GT(limit, 0.0);
  EXPECT_LT(amplification(c.S, (1 - 1e-6) * limit), 1.0) << "rho* = " << limit << " is too large";
  EXPECT_GT(amplification(c.S, (1 + 1e-6) * limit), 1.0) << "rho* = " << limit << " is too small";
}

TEST(UzawaStep, your_uzawa_converges_to_the_contact_solution) {
  const auto c = exercise_support::small_contact();
  const double rho = 0.5 * exercise::rho_limit(c.S);
  ASSERT_GT(rho, 0.0);
  Eigen::VectorXd lambda = Eigen::VectorXd::Zero(c.b.size());
  for (int k = 0; k < 20000; ++k) lambda = exercise::uzawa_step(lambda, c.b - c.S * lambda, rho);
  EXPECT_LT((lambda - c.lambda).norm(), 1e-8 * c.lambda.norm());
  EXPECT_GT(c.lambda.maxCoeff(), 0.0);
  EXPECT_EQ(c.lambda.minCoeff(), 0.0);  // some rows in contact, some not
}
