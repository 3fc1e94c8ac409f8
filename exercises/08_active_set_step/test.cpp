#include <gtest/gtest.h>

#include "exercise.hpp"
#include "small_contact_problem.hpp"

TEST(ActiveSetStep, predicts_contact_from_multipliers_and_gaps) {
  const Eigen::Vector4d lambda(0.5, 0.0, 0.0, 0.1), gap(0.0, -0.2, 0.3, 1.0);
  // row 0: pressed; row 1: penetrates; row 2: open; row 3: small force, large gap
  EXPECT_EQ(exercise::next_active_set(lambda, gap, 1.0), (std::vector<int>{0, 1}));
  EXPECT_EQ(exercise::next_active_set(lambda, gap, 0.01), (std::vector<int>{0, 1, 3}));
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
