// Exercise 7: the Uzawa projection step and the choice of rho.
#pragma once

#include <Eigen/Dense>

namespace exercise {

// One Uzawa step: the point of the cone { lambda_i >= 0 for every i } nearest (in the Euclidean
// norm) to lambda + rho * penetration, where penetration = B u - G for the u of the current lambda.
Eigen::VectorXd uzawa_step(const Eigen::VectorXd& lambda, const Eigen::VectorXd& penetration, double rho);

// For S = B K^{-1} B^T (symmetric positive semidefinite, not zero): the supremum rho* of the steps
// rho > 0 for which the unprojected Uzawa error e <- (I - rho S) e does not grow in any direction
// and shrinks in every direction S does not annihilate.
double rho_limit(const Eigen::MatrixXd& S);

}  // namespace exercise
