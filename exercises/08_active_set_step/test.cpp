#include <gtest/gtest.h>

#include <vector>

#include "exercise.hpp"
#include "small_contact_problem.hpp"

TEST(ActiveSetStep, predicts_contact_from_multipliers_and_gaps) {
  const Eigen::Vector4d lambda(0.5, 0.0, 0.0, 0.1), gap(0.0, -0.2, 0.3, 1.0);
  // row 0: pressed; row 1: penetrates; row 2: open; row 3: small force, large gap
  EXPECT_EQ(exercise::next_active_set(lambda, gap, 1.0), (std::vector<int>{0, 1}));
  EXPECT_EQ(exercise::next_active_set(lambda, gap, 0.01), (std::vector<int>{0, 1, 3}));
}

// Worked by hand (and checked in exact rational arithmetic): S = (2 1 0; 1 2 1; 0 1 2), b = (1, 1, 1).
// A = {0, 2}: S_AA = 2 I, so lambda = (1/2, 0, 1/2). A = {0, 1}: (2 1; 1 2) lambda_A = (1, 1) gives
// lambda_A = (1/3, 1/3), row 2 carries nothing. A = {1}: 2 lambda_1 = 1. A = {}: no row carries a force.
TEST(ActiveSetStep, solves_four_active_sets_worked_by_hand) {
  const Eigen::Matrix3d S = (Eigen::Matrix3d() << 2, 1, 0, 1, 2, 1, 0, 1, 2).finished();
  const Eigen::Vector3d b(1, 1, 1);
  const struct {
    std::vector<int> active;
    Eigen::Vector3d lambda;
  } cases[] = {{{0, 2}, {0.5, 0.0, 0.5}}, {{0, 1}, {1.0 / 3, 1.0 / 3, 0.0}}, {{1}, {0.0, 0.5, 0.0}}, {{}, {0.0, 0.0, 0.0}}};
  for (const auto& c : cases) {
    const Eigen::VectorXd lambda = exercise::solve_on_active_set(S, b, c.active);
    ASSERT_EQ(lambda.size(), 3);
    EXPECT_LT((lambda - c.lambda).cwiseAbs().maxCoeff(), 1e-14) << "active set of " << c.active.size()
                                                                 << " rows: got " << lambda.transpose();
  }
}

TEST(ActiveSetStep, your_steps_find_the_contact_solution) {
  const auto c = exercise_support::small_contact();
  const double scale = 1.0 / c.S.diagonal().maxCoeff();
  Eigen::VectorXd lambda = Eigen::VectorXd::Zero(c.b.size());
  std::vector<int> active = exercise::next_active_set(lambda, -c.b, scale);  // where it would penetrate
  int steps = 0;
  for (; steps < 50; ++steps) {
    lambda = exercise::solve_on_active_set(c.S, c.b, active);
    const std::vector<int> next = exercise::next_active_set(lambda, c.S * lambda - c.b, scale);
    if (next == active) break;
    active = next;
  }
  EXPECT_LT(steps, 50) << "the active set never settled";
  EXPECT_LT((lambda - c.lambda).norm(), 1e-10 * c.lambda.norm());
}
