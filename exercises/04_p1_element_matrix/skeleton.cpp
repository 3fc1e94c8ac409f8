#include "exercise.hpp"

namespace exercise {

Eigen::Matrix<double, 6, 6> element_stiffness(const std::array<Eigen::Vector2d, 3>& x, double E, double nu) {
  // Your code here: refuse what the header says; then the matrix of a(u, v) on this triangle in
  // its six nodal unknowns, whichever way round the vertices are listed (README, "What to work
  // out").
  (void)x;
  (void)E;
  (void)nu;
  return Eigen::Matrix<double, 6, 6>::Identity();
}

}  // namespace exercise
