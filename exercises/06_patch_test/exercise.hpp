// Exercise 6: the exact solution of the patch test.
#pragma once

#include <Eigen/Dense>

namespace exercise {

struct PatchData {
  double E1 = 1, nu1 = 0.3, E2 = 3, nu2 = 0.25;
  double pressure = 0.01;  // p, pushing down on the top of body 1
  double H2 = 0.5;         // body 2 = (0, L) x (-H2, 0), body 1 above it
};

// The displacement of body l (0 = body 1 above Gamma_c, 1 = body 2 below) at point p, for
// the two stacked blocks of chapter 4: uniform pressure p on top, rollers under body 2
// (u_y = 0 at y = -H2) and on the left sides (u_x = 0 at x = 0), right sides free.
Eigen::Vector2d patch_displacement(int l, const Eigen::Vector2d& p, const PatchData& d);

}  // namespace exercise
