#include "exercise.hpp"

namespace exercise {

Eigen::Matrix<double, 6, 6> element_stiffness(const std::array<Eigen::Vector2d, 3>& x, double E, double nu) {
  const double twice_area = (x[1] - x[0]).x() * (x[2] - x[0]).y() - (x[1] - x[0]).y() * (x[2] - x[0]).x();
  Eigen::Matrix<double, 3, 6> B = Eigen::Matrix<double, 3, 6>::Zero();
  for (int k = 0; k < 3; ++k) {
    // grad lambda_k: the edge opposite vertex k, turned by 90 degrees, over twice the area
    const Eigen::Vector2d& p = x[(k + 1) % 3];
    const Eigen::Vector2d& q = x[(k + 2) % 3];
    const double gx = (p.y() - q.y()) / twice_area, gy = (q.x() - p.x()) / twice_area;
    B(0, 2 * k) = gx;      // eps_xx = d u_x / dx
    B(1, 2 * k + 1) = gy;  // eps_yy = d u_y / dy
    B(2, 2 * k) = gy;      // 2 eps_xy = d u_x / dy + d u_y / dx
    B(2, 2 * k + 1) = gx;
  }
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  Eigen::Matrix3d C;
  C << lambda + 2 * mu, lambda, 0, lambda, lambda + 2 * mu, 0, 0, 0, mu;
  return 0.5 * twice_area * B.transpose() * C * B;
}

}  // namespace exercise
