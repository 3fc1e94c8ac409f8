// Exercise 8: one step of the primal-dual active set method.
#pragma once

#include <Eigen/Dense>
#include <vector>

namespace exercise {

// The rows predicted to be in contact: { i : lambda_i + c * (-gap_i) > 0 }, where
// gap = G - B u >= 0 is the remaining gap, in increasing order.
std::vector<int> next_active_set(const Eigen::VectorXd& lambda, const Eigen::VectorXd& gap, double c);

// The multipliers for a given active set: S_AA lambda_A = b_A on the active rows (they touch,
// with zero gap), lambda = 0 on the others. S = B K^{-1} B^T, b = B K^{-1} f - G.
Eigen::VectorXd solve_on_active_set(const Eigen::MatrixXd& S, const Eigen::VectorXd& b,
                                    const std::vector<int>& active);

}  // namespace exercise
