#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "exercise.hpp"
#include "small_contact_problem.hpp"

TEST(UzawaStep, projects_on_nonnegative_multipliers) {
  const Eigen::Vector3d lambda(1.0, 0.2, 0.0), penetration(-0.5, -1.0, 0.3);
  const Eigen::VectorXd next = exercise::uzawa_step(lambda, penetration, 0.5);
  EXPECT_DOUBLE_EQ(next[0], 0.75);
  EXPECT_DOUBLE_EQ(next[1], 0.0);  // would be -0.3: the contact opens
  EXPECT_DOUBLE_EQ(next[2], 0.15);
}

TEST(UzawaStep, rho_limit_is_two_over_the_largest_eigenvalue) {
  const auto c = exercise_support::small_contact();
  const double top = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(c.S).eigenvalues().maxCoeff();
  EXPECT_NEAR(exercise::rho_limit(c.S), 2.0 / top, 1e-6 * 2.0 / top);
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
