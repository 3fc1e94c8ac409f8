// The local field of a generic stick-slip point (chapter 8's manufactured scene): two bodies
// above and below Gamma_c whose slip starts like (x - x_c)^{3/2} and whose shear leaves the
// friction threshold like sqrt(x_c - x), singular at the point (x_c, 0) alone, like r^{3/2}.
// With X = x - x_c, zeta = X + i y in body 1 (y >= 0) and zeta' = X - i y in body 2 (y <= 0),
// principal branches (the cut x < x_c lies on Gamma_c, approached from inside each body):
//
//   body 1:  u_x = C Re zeta^{3/2} + G y Im zeta^{1/2},   u_y = E y Re zeta^{1/2},
//   body 2:  u_x = -D y Im zeta'^{1/2},                     u_y = 0.
//
// On Gamma_c (y = 0): Re zeta^{3/2} = X_+^{3/2}, Re zeta^{1/2} = X_+^{1/2}, Im zeta^{1/2} =
// (-X)_+^{1/2}, and the y terms vanish. d/dy of Re zeta^{3/2} is -(3/2) Im zeta^{1/2}, d/dy of
// y Im zeta^{1/2} is Im zeta^{1/2}. So, with G = (3/2) C - K / mu1, D = K / mu2 and
// E = -(3/2) C lambda1 / (lambda1 + 2 mu1):
//
//   slip   [u_T] = u^1_x - u^2_x = C (x - x_c)_+^{3/2},          [u.n] = 0,
//   shear  sigma_12 = -K (x_c - x)_+^{1/2} from both sides,
//   sigma_22 = (lambda1 (3/2) C + (lambda1 + 2 mu1) E) X_+^{1/2} = 0 from both sides.
//
// C and K are free: the slip's size and the shear's. Not an elastic field: its body force
// -div sigma is of order r^{-1/2} near (x_c, 0), square integrable, and smooth elsewhere; u
// is in H^{5/2 - eps}, the regularity of a generic contact edge (chapter 5's hertz-exact).
#pragma once

#include <Eigen/Dense>

#include "common/fem/p1_elasticity.hpp"

namespace mortar {

class StickSlipCorner {
 public:
  // the slip C (x - x_c)_+^{3/2} and the shear -K (x_c - x)_+^{1/2}
  StickSlipCorner(const Material& body1, const Material& body2, double xc, double C, double K);

  Eigen::Vector2d u(int l, const Eigen::Vector2d& p) const;
  Eigen::Matrix2d grad_u(int l, const Eigen::Vector2d& p) const;  // d u_i / d x_j
  Eigen::Vector2d div_sigma(int l, const Eigen::Vector2d& p) const;
  double shear(double x) const;  // sigma_12 on Gamma_c
  double slip(double x) const;   // [u_T] on Gamma_c

 private:
  // u_i, its gradient and its Hessian (rows: u_x, u_y) of body l at p
  struct Local {
    Eigen::Vector2d u;
    Eigen::Matrix2d grad;
    Eigen::Matrix2d hessian[2];
  };
  Local local(int l, const Eigen::Vector2d& p) const;

  Material m1_, m2_;
  double xc_, C_, K_, D_, E_, G_;
};

}  // namespace mortar
