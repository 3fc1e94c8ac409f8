// The smooth manufactured solution of chapter 2 on the unit square:
//   u_x = A sin(pi x) cos(pi y),   u_y = A e^x sin(pi y).
// It is not zero on any side, so the Dirichlet data (left, bottom) are non-homogeneous, and
// the traction sigma(u) n (right, top) and body force f = -div sigma(u) follow exactly from
// its second derivatives: div sigma = mu Lap u + (lambda + mu) grad div u.
#pragma once

#include <Eigen/Dense>

#include "common/fem/errors.hpp"
#include "common/fem/p1_elasticity.hpp"

namespace chapter02 {

class ManufacturedSolution {
 public:
  ManufacturedSolution(const mortar::Material& material, double amplitude);

  Eigen::Vector2d u(const Eigen::Vector2d& p) const;
  Eigen::Matrix2d grad_u(const Eigen::Vector2d& p) const;  // (i, j) = d u_i / d x_j
  Eigen::Matrix2d stress(const Eigen::Vector2d& p) const;
  Eigen::Vector2d body_force(const Eigen::Vector2d& p) const;  // f = -div sigma(u)
  Eigen::Vector2d traction(const Eigen::Vector2d& p, const Eigen::Vector2d& normal) const;
  mortar::ExactSolution exact() const;

 private:
  mortar::Material material_;
  double A_;
};

}  // namespace chapter02
