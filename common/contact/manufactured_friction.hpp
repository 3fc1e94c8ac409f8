// An exact solution of two-body contact with Tresca friction, with a stick zone and a slip zone
// (chapter 8's manufactured scene). With xi = x / L and the stick-slip point x_c = xi_c L,
// xi_c = 0.4 + sqrt(2)/100 (never a node of a mesh with rational nodes), on Gamma_c:
//
//   pressure    p(x)   = S (1 + 0.3 sin(pi xi)) > 0          (closed everywhere: [u.n] = 0)
//   shear       tau(x) = sigma_12 = F (p(x) - 8 S (xi_c - xi)_+^2)
//   slip        j(x)   = u^1_x - u^2_x = 2 L eps (xi - xi_c)_+^3
//
// so that on x > x_c the bodies slip (j > 0) with tau = F p, the threshold, of the slip's sign,
// and on x < x_c they stick (j = 0) with |tau| < F p (F p - tau = 8 F S (xi_c - xi)^2, and
// tau + F p >= F S (2 - 8 xi_c^2) > 0). tau changes sign inside the stick zone. At x_c the
// shear leaves the threshold like (x_c - x)^2 and the slip starts like (x - x_c)^3: a
// transition O(h) can locate (a smoother one, (x_c - x)^3 and (x - x_c)^4, was tried first: its
// point moved like h^{0.6}, an error of 10 elements at h1 = 1/128). The scales are
// eps = 1e-3 and S = eps E*, 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2: relative errors do not
// depend on the unit of length or of stress.
//
// Each body's field is quadratic in y (the y^2 terms vanish on Gamma_c with their first
// derivatives, so they leave the contact conditions alone):
//
//   u^l = ( A_l(x) + y P_l(x) + y^2 R_l(x),  c(x) + y Q_l(x) + y^2 T_l(x) ),
//
// with A_2 = alpha, A_1 = alpha + j, and P_l, Q_l chosen so that on y = 0
//   sigma_12 = mu_l (P_l + c') = tau   and   sigma_22 = lambda_l A_l' + (lambda_l + 2 mu_l) Q_l = -p.
// The body force is f = -div sigma: bounded, with a jump across x = x_c (j is C^2, tau C^1). The same pair solves Coulomb
// friction with coefficient F (its threshold F lambda_n is F p): Tresca with s = F p and Coulomb
// share this exact solution, not their discrete ones.
#pragma once

#include "common/contact/exact_contact.hpp"

namespace mortar {

class ManufacturedFriction : public ExactContact {
 public:
  ManufacturedFriction(const Material& body1, const Material& body2, double L, double friction);

  Eigen::Vector2d u(int l, const Eigen::Vector2d& p) const override;
  Eigen::Matrix2d grad_u(int l, const Eigen::Vector2d& p) const override;
  Eigen::Vector2d body_force(int l, const Eigen::Vector2d& p) const override;
  std::vector<double> body_force_breaks() const override { return {xc_}; }
  double pressure(double x) const override;
  double shear(double x) const override;  // tau = sigma_12 on Gamma_c, the exact lambda_t
  double slip(double x) const;       // j = u^1_x - u^2_x on Gamma_c
  double threshold(double x) const;  // Tresca's s = F p
  double stick_slip_point() const { return xc_; }
  double friction() const { return F_; }

  // The value and three derivatives in x of a function of x.
  struct Jet {
    double f = 0, d1 = 0, d2 = 0, d3 = 0;
  };

 private:
  // Body l's profiles at x: A, P, Q (in x) and R, T (the y^2 terms), and c.
  struct Profiles {
    Jet A, P, Q, R, T, c;
  };
  Profiles profiles(int l, double x) const;
  Jet shear_jet(double x) const;
  Jet pressure_jet(double x) const;

  double L_, F_, xc_, eps_, S_;
};

}  // namespace mortar
