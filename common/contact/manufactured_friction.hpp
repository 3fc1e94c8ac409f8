// An exact solution of two-body contact with Tresca friction, with a stick zone and a slip zone
// (chapter 8's manufactured scene). With xi = x / L and the stick-slip point x_c = xi_c L,
// xi_c = 0.4 + sqrt(2)/100 (never a node of a mesh with rational nodes), on Gamma_c:
//
//   pressure    p(x)   = S (1 + 0.3 sin(pi xi)) > 0          (closed everywhere: [u.n] = 0)
//   shear       tau(x) = sigma_12 = F p(x) - K (x_c - x)_+^{1/2},   K = 1.5 F S / sqrt(x_c)
//   slip        j(x)   = u^1_x - u^2_x = C (x - x_c)_+^{3/2},        C = 2 eps / sqrt(L)
//
// so that on x > x_c the bodies slip (j > 0) with tau = F p, the threshold, of the slip's sign,
// and on x < x_c they stick (j = 0) with |tau| < F p (F p - tau = K sqrt(x_c - x) > 0, and
// tau + F p >= 2 F S - 1.5 F S > 0). tau changes sign inside the stick zone (-F S / 2 at x = 0).
// The transition is the generic one, as at the edges of Cattaneo-Mindlin's stick zone: the
// shear leaves the threshold like a square root and the slip starts like a power 3/2. (An
// earlier solution left it like (x_c - x)^2, with the slip like (x - x_c)^3: a degenerate
// transition, whose computed point lay 3 to 7 elements short of x_c at every level.) The scales
// are eps = 1e-3 and S = eps E*, 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2: relative errors do not
// depend on the unit of length or of stress.
//
// u is the sum of a smooth field and the local field of the stick-slip point
// (stick_slip_corner.hpp), singular at (x_c, 0) alone. The smooth field is quadratic in y (the
// y^2 terms vanish on Gamma_c with their first derivatives, so they leave the contact
// conditions alone):
//
//   u^l = ( A(x) + y P_l(x) + y^2 R_l(x),  c(x) + y Q_l(x) + y^2 T_l(x) ),
//
// with P_l, Q_l chosen so that on y = 0
//   sigma_12 = mu_l (P_l + c') = F p   and   sigma_22 = lambda_l A' + (lambda_l + 2 mu_l) Q_l = -p;
// the corner adds the slip j and the shear -K (x_c - x)_+^{1/2} and nothing else on Gamma_c.
// The body force f = -div sigma is smooth but near (x_c, 0), where it grows like r^{-1/2}
// (square integrable); u is in H^{5/2 - eps}. The same pair solves Coulomb friction with
// coefficient F (its threshold F lambda_n is F p): Tresca with s = F p and Coulomb share this
// exact solution, not their discrete ones.
#pragma once

#include "common/contact/exact_contact.hpp"
#include "common/contact/stick_slip_corner.hpp"

namespace mortar {

class ManufacturedFriction : public ExactContact {
 public:
  ManufacturedFriction(const Material& body1, const Material& body2, double L, double friction);

  Eigen::Vector2d u(int l, const Eigen::Vector2d& p) const override;
  Eigen::Matrix2d grad_u(int l, const Eigen::Vector2d& p) const override;
  Eigen::Vector2d body_force(int l, const Eigen::Vector2d& p) const override;
  // the body force is singular at (x_c, 0): the line x = x_c keeps that point at a corner of
  // every piece the load is integrated on
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
  // Body l's smooth profiles at x: A, P, Q (in x) and R, T (the y^2 terms), and c.
  struct Profiles {
    Jet A, P, Q, R, T, c;
  };
  Profiles profiles(int l, double x) const;
  Jet shear_jet(double x) const;
  Jet pressure_jet(double x) const;

  double L_, F_, xc_, eps_, S_;
  StickSlipCorner corner_;  // the slip and the square-root part of the shear
};

}  // namespace mortar
