// Cattaneo-Mindlin made exact: each body a piece of an elastic half-plane loaded on its edge by
// the Hertz pressure p (hertz_half_planes.hpp) and by the shear of Cattaneo (1938) and Mindlin
// (1949) (Johnson, Contact Mechanics, 7.2), with X = x - x0 and c = a sqrt(1 - Q / (F P)):
//
//   q(X) = F p0 (sqrt(1 - X^2/a^2) - (c/a) sqrt(1 - X^2/c^2))  on the stick zone |X| < c,
//   q(X) = F p(X)                                              on the slip zone c <= |X| < a,
//
// the difference of two elliptical edge loads (elliptic_edge_load.hpp). P = pi a p0 / 2 is
// Hertz's force and Q = int q = F P (1 - c^2/a^2) the shear force.
//
// The tangential field. In a half-plane's own frame (x along the edge, z >= 0 the depth) take,
// with one analytic G(zeta), zeta = X + i z, the Papkovich-Neuber potentials psi = Re G and
// 2 (1 - nu) Psi, Psi_z = psi (so Psi_x = Im G):
//
//   2 mu U_x = 2 (1 - nu) Im G + z Re G',       2 mu U_z = -(1 - 2 nu) Re G - z Im G',
//   sigma_xz = Re G' - z Im G'',   sigma_zz = -z Re G'',   sigma_xx = 2 Im G' + z Re G''.
//
// It is harmonic in each component (equilibrium, no body force), sigma_zz = 0 on the edge and
// sigma_xz = Re G' there. G' = i (k/b) (zeta - S) = -W'' of an elliptical load has
// Re G' = k sqrt(1 - X^2/b^2) on the edge: the shear q is G' = -W''_a(F p0) - W''_c(-F p0 c/a).
// On the edge 2 mu dU_x/dX = 2 (1 - nu) Im G', and Im G' = (k/b) X inside |X| < b: the two
// loads' terms cancel on |X| < c, where the slip is then constant (Cattaneo's argument).
//
// Body 1 is the half-plane itself (z = y) under +q; body 2 its mirror image (z = -y, u_y = -U_z)
// under -q, so that sigma_12 = q on Gamma_c from both sides. With Dundurs' beta = 0, that is
// (1 - 2 nu1)/mu1 = (1 - 2 nu2)/mu2 (one material, say), the shear moves the two surfaces alike
// in y ([u.n] does not see q) and the pressure moves them alike in x ([u_T] does not see p):
// the normal problem stays Hertz's, and with each body's rigid translation taken away at
// (x0, 0) the slip [u_T] = u^1_x - u^2_x is 0 on the stick zone and positive (the sign of q)
// on the slip zone, growing with Q at every point. A load path Q_0 = 0 < Q_1 < ... therefore
// meets Coulomb's law for increments at every step: with u prescribed on the outer sides of
// any box and the initial gap (x - x0)^2 / (2R), the field of each Q_k is the exact solution
// of step k of the finite two-body problem with Coulomb friction F.
#pragma once

#include "common/contact/hertz_half_planes.hpp"

namespace mortar {

class CattaneoHalfPlanes : public ExactContact {
 public:
  // x0, a, R as for HertzHalfPlanes; q_ratio = Q / (F P) in [0, 1). Throws unless F > 0 and
  // the two materials have beta = 0.
  CattaneoHalfPlanes(const Material& body1, const Material& body2, double x0, double a, double R, double friction,
                     double q_ratio);

  Eigen::Vector2d u(int l, const Eigen::Vector2d& p) const override;
  Eigen::Matrix2d grad_u(int l, const Eigen::Vector2d& p) const override;
  Eigen::Vector2d body_force(int, const Eigen::Vector2d&) const override { return Eigen::Vector2d::Zero(); }
  bool has_body_force() const override { return false; }
  double pressure(double x) const override { return normal_.pressure(x); }
  double shear(double x) const override;  // q: sigma_12 on Gamma_c, the exact lambda_t
  double total_force(double L) const override { return normal_.total_force(L); }

  double slip(double x) const;  // [u_T] = u^1_x - u^2_x on Gamma_c
  double shear_force() const;   // Q = F P (1 - c^2/a^2)
  const HertzHalfPlanes& normal() const { return normal_; }
  double stick_half_width() const { return c_; }
  double friction() const { return F_; }

 private:
  // the tangential field of the shear +q, in the half-plane's frame with body l's material:
  // U (rows U_x, U_z) and grad U (columns d/dX, d/dz) at (X, z), z >= 0
  Eigen::Vector2d shear_displacement(int l, double X, double z) const;
  Eigen::Matrix2d shear_gradient(int l, double X, double z) const;

  HertzHalfPlanes normal_;
  double F_, c_;
  Eigen::Vector2d rigid_[2];  // the shear part of U at (x0, 0) of each body, taken away
};

}  // namespace mortar
