#include "exercise.hpp"

namespace exercise {

Eigen::VectorXd uzawa_step(const Eigen::VectorXd& lambda, const Eigen::VectorXd& penetration, double rho) {
  return (lambda + rho * penetration).cwiseMax(0.0);
}

double rho_limit(const Eigen::MatrixXd& S) {
  // power iteration: x <- S x / |S x| converges to the top eigenvector of an SPD matrix
  Eigen::VectorXd x = Eigen::VectorXd::Ones(S.rows()).normalized();
  double top = 0;
  for (int k = 0; k < 500; ++k) {
    const Eigen::VectorXd y = S * x;
    top = x.dot(y);
    x = y.normalized();
  }
  return 2.0 / top;
}

}  // namespace exercise
