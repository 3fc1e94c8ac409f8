// Exercise 7: the Uzawa projection step and the choice of rho.
#pragma once

#include <Eigen/Dense>

namespace exercise {

// One Uzawa step: lambda_new = max(0, lambda + rho * penetration), componentwise,
// where penetration = B u - G for the u of the current lambda.
Eigen::VectorXd uzawa_step(const Eigen::VectorXd& lambda, const Eigen::VectorXd& penetration, double rho);

// The largest step for which Uzawa converges, 2 / ||S|| for S = B K^{-1} B^T (symmetric
// positive semidefinite), computed from S by power iteration or an eigenvalue solver.
double rho_limit(const Eigen::MatrixXd& S);

}  // namespace exercise
