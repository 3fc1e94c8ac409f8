// Exercise 4: the P1 plane-strain element stiffness matrix.
#pragma once

#include <Eigen/Dense>
#include <array>

namespace exercise {

// K_T for the triangle with vertices x, listed counter-clockwise or clockwise, Young's modulus E
// and Poisson ratio nu, in plane strain; unknowns ordered (u_x0, u_y0, u_x1, u_y1, u_x2, u_y2).
// Throws std::invalid_argument for a triangle of zero area, E <= 0 or nu outside (-1, 1/2).
Eigen::Matrix<double, 6, 6> element_stiffness(const std::array<Eigen::Vector2d, 3>& x, double E, double nu);

}  // namespace exercise
