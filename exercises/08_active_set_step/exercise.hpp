// Exercise 8: one step of the primal-dual active set method.
#pragma once

#include <Eigen/Dense>
#include <vector>

namespace exercise {

// The active set at (lambda, gap), gap = G - B u the remaining gap: the rows i where the max in
// lambda_i = max(0, lambda_i - c gap_i) takes its right side strictly (where both sides are equal,
// the left side counts), in increasing order.
std::vector<int> next_active_set(const Eigen::VectorXd& lambda, const Eigen::VectorXd& gap, double c);

// The Newton step for the given active set: the lambda that solves the equations
// lambda_i = max(0, lambda_i - c gap_i) with each row taken on the side the active set says,
// where gap = S lambda - b, S = B K^{-1} B^T and b = B K^{-1} f - G.
Eigen::VectorXd solve_on_active_set(const Eigen::MatrixXd& S, const Eigen::VectorXd& b,
                                    const std::vector<int>& active);

}  // namespace exercise
