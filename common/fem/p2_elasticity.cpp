#include "common/fem/p2_elasticity.hpp"

namespace mortar {

P2StrainMatrix p2_strain_matrix(const std::array<Eigen::Vector2d, 3>& x, const Eigen::Vector3d& lambda) {
  // grad lambda_k, read off the P1 strain matrix (it checks the orientation of the triangle)
  const StrainMatrix B1 = strain_matrix(x);
  std::array<Eigen::Vector2d, 3> g;
  for (int k = 0; k < 3; ++k) g[k] = Eigen::Vector2d(B1(0, 2 * k), B1(1, 2 * k + 1));
  std::array<Eigen::Vector2d, 6> grad;
  for (int k = 0; k < 3; ++k) {
    const int l = (k + 1) % 3;
    grad[k] = (4 * lambda[k] - 1) * g[k];
    grad[3 + k] = 4 * (lambda[k] * g[l] + lambda[l] * g[k]);
  }
  P2StrainMatrix B = P2StrainMatrix::Zero();
  for (int a = 0; a < 6; ++a) {
    B(0, 2 * a) = grad[a].x();
    B(1, 2 * a + 1) = grad[a].y();
    B(2, 2 * a) = grad[a].y();
    B(2, 2 * a + 1) = grad[a].x();
  }
  return B;
}

P2ElementMatrix p2_element_stiffness(const std::array<Eigen::Vector2d, 3>& x, const Material& material) {
  static const TriangleRule rule = triangle_rule(p2_stiffness_degree);
  return p2_element_stiffness(x, material, rule);
}

P2ElementMatrix p2_element_stiffness(const std::array<Eigen::Vector2d, 3>& x, const Material& material,
                                     const TriangleRule& rule) {
  const double area = 0.5 * ((x[1] - x[0]).x() * (x[2] - x[0]).y() - (x[1] - x[0]).y() * (x[2] - x[0]).x());
  const Eigen::Matrix3d C = material.voigt();
  P2ElementMatrix K = P2ElementMatrix::Zero();
  for (std::size_t q = 0; q < rule.points.size(); ++q) {
    const double s = rule.points[q].x(), t = rule.points[q].y();
    const P2StrainMatrix B = p2_strain_matrix(x, Eigen::Vector3d(1 - s - t, s, t));
    K += (area * rule.weights[q]) * B.transpose() * C * B;
  }
  return K;
}

}  // namespace mortar
