#include <cmath>

#include "exercise.hpp"

namespace exercise {

Eigen::VectorXd uzawa_step(const Eigen::VectorXd& lambda, const Eigen::VectorXd& penetration, double rho) {
  // the cone is a product of half-lines: the nearest point is taken row by row
  return (lambda + rho * penetration).cwiseMax(0.0);
}

double rho_limit(const Eigen::MatrixXd& S) {
  // e <- (I - rho S) e multiplies the eigenvector of mu by 1 - rho mu: |1 - rho mu| < 1 for every
  // mu > 0 exactly when rho < 2 / mu_max. mu_max by power iteration x <- S x / |S x|. The start
  // must not be orthogonal to the top eigenvector: the all-ones vector is, for S = (1 -1; -1 1)
  // (S x = 0). Entries k * golden ratio mod 1, shifted off zero, fall on no such symmetry.
  const Eigen::Index n = S.rows();
  Eigen::VectorXd x(n);
  for (Eigen::Index i = 0; i < n; ++i) x[i] = 0.5 + std::fmod(0.6180339887498949 * static_cast<double>(i + 1), 1.0);
  x.normalize();
  double top = 0;
  for (int k = 0; k < 500; ++k) {
    const Eigen::VectorXd y = S * x;
    top = x.dot(y);
    const double norm = y.norm();
    if (norm == 0) break;  // x in the kernel of S: nothing left to find from this start
    x = y / norm;
  }
  return 2.0 / top;
}

}  // namespace exercise
