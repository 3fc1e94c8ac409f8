#include "exercise.hpp"

namespace exercise {

Eigen::Matrix<double, 6, 6> element_stiffness(const std::array<Eigen::Vector2d, 3>& x, double E, double nu) {
  // Your code here: the gradients of the barycentric coordinates, the strain matrix B (3 x 6),
  // the plane-strain matrix C (3 x 3), then area * B^T C B.
  (void)x;
  (void)E;
  (void)nu;
  return Eigen::Matrix<double, 6, 6>::Identity();
}

}  // namespace exercise
