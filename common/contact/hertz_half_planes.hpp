// Hertz contact made exact: each body is a piece of an elastic half-plane loaded on its edge by
// the Hertz pressure (chapter 5 notes, "The exact Hertz scene")
//
//   p(x) = p0 sqrt(1 - (x - x0)^2 / a^2)  on |x - x0| < a,   0 outside,   no shear,
//
// body 1 the half-plane y > 0, body 2 the half-plane y < 0, no body force. With the depth
// z >= 0 into a body and X = x - x0, one harmonic potential phi serves both bodies
// (Papkovich-Neuber with the frictionless choice of Boussinesq's problem):
//
//   2 mu U_x = (1 - 2 nu) phi_x + z phi_xz,     2 mu U_z = -2 (1 - nu) phi_z + z phi_zz,
//   sigma_zz = -phi_zz + z phi_zzz,  sigma_xz = z phi_xzz,  sigma_xx = -phi_zz - z phi_zzz,
//
// so sigma_xz = 0 and sigma_zz = -phi_zz on the edge z = 0. phi = Re Phi(zeta), zeta = X + i z,
// with Phi'' = -i (p0/a) (zeta - S), S = sqrt(zeta - a) sqrt(zeta + a) (S ~ zeta at infinity,
// analytic for z > 0): phi_zz = -Re Phi'' is the harmonic function equal to p on the edge and
// decaying like 1/|zeta| (elliptic_edge_load.hpp, with b = a and k = p0). Each body's
// displacement is fixed up to a rigid motion: the programs take U = 0 at (x0, 0). The edge
// displacements then close the parabola exactly:
//
//   [u.n](x) = u^2_y - u^1_y = X^2 / (2R)  on |X| <= a,   with p0 = a E* / (2R),
//   1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2,
//
// and leave g(x) - [u.n](x) = (p0 / (a E*)) (|X| sqrt(X^2 - a^2) - a^2 acosh(|X|/a)) > 0 open
// outside, like (|X| - a)^{3/2}. With the initial gap g(x) = (x - x0)^2 / (2R) and u prescribed
// on the outer sides of any box (0, L) x (0, H1), (0, L) x (-H2, 0), the pair is the exact
// solution of unilateral contact (9)-(11): the generic contact edge, pressure like
// sqrt(a - |X|), u in H^{5/2 - eps} and no better.
#pragma once

#include "common/contact/exact_contact.hpp"

namespace mortar {

class HertzHalfPlanes : public ExactContact {
 public:
  // x0 the centre and a the half-width of the contact zone, R the radius of the gap's parabola
  HertzHalfPlanes(const Material& body1, const Material& body2, double x0, double a, double R);

  Eigen::Vector2d u(int l, const Eigen::Vector2d& p) const override;
  Eigen::Matrix2d grad_u(int l, const Eigen::Vector2d& p) const override;
  Eigen::Vector2d body_force(int, const Eigen::Vector2d&) const override { return Eigen::Vector2d::Zero(); }
  bool has_body_force() const override { return false; }
  double pressure(double x) const override;
  std::vector<double> pressure_kinks() const override { return {x0_ - a_, x0_ + a_}; }
  double total_force(double) const override;  // pi a p0 / 2, whatever the length of Gamma_c

  double gap(double x) const;  // the initial gap (x - x0)^2 / (2R)
  // g - [u.n] in closed form (the formula above; 0 inside the zone): the open gap
  double open_gap(double x) const;
  double centre() const { return x0_; }
  double half_width() const { return a_; }
  double peak_pressure() const { return p0_; }
  double e_star() const { return e_star_; }

 private:
  // grad U of the half-plane with body l's material at (X, z), z >= 0, in the half-plane's
  // own frame (x along the edge, z into the body): rows U_x, U_z; columns d/dX, d/dz
  Eigen::Matrix2d half_plane_gradient(int l, double X, double z) const;
  Eigen::Vector2d half_plane_displacement(int l, double X, double z) const;

  double x0_, a_, R_, p0_, e_star_;
  Eigen::Vector2d rigid_[2];  // U at (x0, 0) of each body, taken away
};

}  // namespace mortar
