#include "exercise.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace exercise {

Eigen::Matrix<double, 6, 6> element_stiffness(const std::array<Eigen::Vector2d, 3>& x, double E, double nu) {
  if (!(std::isfinite(E) && E > 0)) throw std::invalid_argument("element_stiffness: E must be > 0");
  if (!(std::isfinite(nu) && nu > -1 && nu < 0.5))
    throw std::invalid_argument("element_stiffness: nu must be in (-1, 1/2)");
  // signed: > 0 counter-clockwise, < 0 clockwise
  const double twice_area = (x[1] - x[0]).x() * (x[2] - x[0]).y() - (x[1] - x[0]).y() * (x[2] - x[0]).x();
  const double scale = std::max({(x[1] - x[0]).squaredNorm(), (x[2] - x[1]).squaredNorm(), (x[0] - x[2]).squaredNorm()});
  if (!(std::abs(twice_area) > 1e-14 * scale))
    throw std::invalid_argument("element_stiffness: the triangle has zero area");
  Eigen::Matrix<double, 3, 6> B = Eigen::Matrix<double, 3, 6>::Zero();
  for (int k = 0; k < 3; ++k) {
    // grad lambda_k: the edge opposite vertex k turned by 90 degrees, over the signed twice-area;
    // the sign makes it point towards vertex k in either orientation
    const Eigen::Vector2d& p = x[(k + 1) % 3];
    const Eigen::Vector2d& q = x[(k + 2) % 3];
    const double gx = (p.y() - q.y()) / twice_area, gy = (q.x() - p.x()) / twice_area;
    B(0, 2 * k) = gx;      // eps_xx = d u_x / dx
    B(1, 2 * k + 1) = gy;  // eps_yy = d u_y / dy
    B(2, 2 * k) = gy;      // 2 eps_xy = d u_x / dy + d u_y / dx
    B(2, 2 * k + 1) = gx;
  }
  // plane strain: eps_zz = 0 gives sigma_zz = nu (sigma_xx + sigma_yy), and then
  // sigma = lambda tr(eps) I + 2 mu eps in the plane
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  Eigen::Matrix3d C;
  C << lambda + 2 * mu, lambda, 0, lambda, lambda + 2 * mu, 0, 0, 0, mu;
  return 0.5 * std::abs(twice_area) * B.transpose() * C * B;
}

}  // namespace exercise
