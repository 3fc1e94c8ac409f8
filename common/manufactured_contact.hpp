// An exact solution of bilateral frictionless contact between two different materials
// (DESIGN.md), for convergence studies. On body l (l = 1 upper, 2 lower):
//
//   u^l = ( alpha_l cos(y) v(x) - y c'(x),  beta_l sin(y) w(x) + c(x) ),    times A,
//   v(x) = s0 x + sin(k x) / k,   w(x) = v'(x) = s0 + cos(k x),   c(x) = gamma sin(k x) / k.
//
// On y = 0: u^1_y = u^2_y = c(x)                                   (3) normal continuity
//           sigma_12 = mu_l (alpha_l (-sin 0) v - c' + beta_l sin 0 w' + c') = 0   (5)
//           sigma_22 = (lambda_l alpha_l + (lambda_l + 2 mu_l) beta_l) w(x)        (4)
// and (4) holds on both sides by the choice of beta_2. The tangential displacement jumps,
// (alpha_1 - alpha_2) v(x): the bodies slide on each other. With s0 > 1 the pressure
// p = -sigma_N = -(...) w(x) keeps one sign: the bodies press on each other everywhere.
#pragma once

#include <Eigen/Dense>

#include "common/errors.hpp"
#include "common/p1_elasticity.hpp"

namespace mortar {

class ManufacturedContact {
 public:
  ManufacturedContact(const Material& body1, const Material& body2, double L);

  // l = 0 (body 1, y > 0) or 1 (body 2, y < 0)
  Eigen::Vector2d u(int l, const Eigen::Vector2d& p) const;
  Eigen::Matrix2d grad_u(int l, const Eigen::Vector2d& p) const;
  Eigen::Matrix2d stress(int l, const Eigen::Vector2d& p) const;
  Eigen::Vector2d body_force(int l, const Eigen::Vector2d& p) const;  // f = -div sigma
  double pressure(double x) const;           // -sigma_N on Gamma_c
  double normal_displacement(double x) const;  // u^1_y = u^2_y = c(x) on Gamma_c
  ExactSolution exact(int l) const;
  const Material& material(int l) const { return l == 0 ? m1_ : m2_; }

 private:
  Material m1_, m2_;
  double k_, alpha_[2], beta_[2];
};

}  // namespace mortar
