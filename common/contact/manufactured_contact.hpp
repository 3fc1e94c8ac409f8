// Exact solutions of frictionless contact between two different materials (chapter 3 notes),
// for convergence studies. On body l (l = 1 upper, 2 lower), for an x-profile (v, w = v', c):
//
//   u^l = ( alpha_l cos(y/L) v(x) - y c'(x),  beta_l L sin(y/L) w(x) + c(x) ),    times A,
//
// where L is the length of Gamma_c. Every profile is a function of x/L with v and c of the
// size of L, so u(x, y) = L u_1(x/L, y/L): strains, stresses and pressures do not depend on the
// unit of length and neither does any relative error.
//
// On y = 0: u^1_y = u^2_y = c(x)                                   (3) normal continuity
//           sigma_12 = mu_l (alpha_l (-sin 0) v - c' + beta_l sin 0 w' + c') = 0   (5)
//           sigma_22 = (lambda_l alpha_l + (lambda_l + 2 mu_l) beta_l) w(x)        (4)
// and (4) holds on both sides by the choice of beta_2. The tangential displacement jumps,
// (alpha_1 - alpha_2) v(x): the bodies slide on each other. The pressure is
// p = -sigma_N = 2 mu_1 A w(x), so the profile decides where the bodies press:
//  - sloped_profile: w = s0 + cos(k x), k = 1.5 pi / L, w >= s0 - 1 > 0: contact everywhere,
//    and p' != 0 at x = L (chapters 3-5);
//  - flat_ends_profile: k = 2 pi / L, so p' = 0 at both ends of Gamma_c;
//  - signorini_profile: w = (x* - x)_+^3: pressure on (0, x*), none beyond. With the gap
//    g = A kappa (x - x*)_+^2 (signorini_gap) it is the exact solution of unilateral contact
//    (9)-(11) with a contact zone (0, x*) and a separation zone (x*, L).
#pragma once

#include <Eigen/Dense>
#include <functional>

#include "common/contact/exact_contact.hpp"

namespace mortar {

// The x-profile at one point: v, w = v' and two derivatives of w, c and three of c.
struct ProfileValues {
  double v = 0, w = 0, dw = 0, ddw = 0;
  double c = 0, dc = 0, ddc = 0, dddc = 0;
};
using ContactProfile = std::function<ProfileValues(double x)>;

ContactProfile sloped_profile(double L);
ContactProfile flat_ends_profile(double L);
ContactProfile signorini_profile(double L, double x_star);

// The contact point of the signorini scene: x* = L (1/2 + sqrt(2)/10), never a node of a
// mesh whose nodes are rational multiples of L.
double signorini_contact_point(double L);
// The initial gap of the signorini scene, A kappa (x - x*)_+^2 with kappa = 1 / L.
double signorini_gap(double L, double x);

class ManufacturedContact : public ExactContact {
 public:
  ManufacturedContact(const Material& body1, const Material& body2, double L);  // sloped
  // profile: one of the profiles above, made for the same L
  ManufacturedContact(const Material& body1, const Material& body2, ContactProfile profile, double L);

  // l = 0 (body 1, y > 0) or 1 (body 2, y < 0)
  Eigen::Vector2d u(int l, const Eigen::Vector2d& p) const override;
  Eigen::Matrix2d grad_u(int l, const Eigen::Vector2d& p) const override;
  Eigen::Vector2d body_force(int l, const Eigen::Vector2d& p) const override;  // f = -div sigma
  double pressure(double x) const override;    // -sigma_N on Gamma_c
  double normal_displacement(double x) const;  // u^1_y = u^2_y = c(x) on Gamma_c

 private:
  ContactProfile profile_;
  double L_;  // the length of Gamma_c, the scale of y in cos(y/L), sin(y/L)
  double alpha_[2], beta_[2];
};

}  // namespace mortar
