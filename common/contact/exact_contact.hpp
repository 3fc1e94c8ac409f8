// An exact solution of two-body contact on the course's geometry (body 1 above Gamma_c =
// (0, L) x {0}, body 2 below): what convergence studies measure against. Three kinds:
//  - manufactured_contact.hpp: chapter 4's ansatz, with body forces (the bilateral and
//    signorini scenes);
//  - hertz_half_planes.hpp: each body a piece of an elastic half-plane under the Hertz
//    pressure, no body force (chapter 5's hertz-exact scene);
//  - manufactured_friction.hpp and cattaneo_half_planes.hpp: with friction, a shear on Gamma_c
//    (chapter 8).
// Studies read u and grad u (errors, Dirichlet data), the body force f = -div sigma (loads) and
// the contact pressure p = -sigma_N and the shear sigma_12 on Gamma_c; check_exact_contact tests
// them against the contact problem itself.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "common/fem/errors.hpp"
#include "common/fem/p1_elasticity.hpp"

namespace mortar {

class ExactContact {
 public:
  virtual ~ExactContact() = default;

  // l = 0 (body 1, y >= 0) or 1 (body 2, y <= 0)
  virtual Eigen::Vector2d u(int l, const Eigen::Vector2d& p) const = 0;
  virtual Eigen::Matrix2d grad_u(int l, const Eigen::Vector2d& p) const = 0;  // d u_i / d x_j
  virtual Eigen::Vector2d body_force(int l, const Eigen::Vector2d& p) const = 0;  // f = -div sigma
  virtual bool has_body_force() const { return true; }  // false: f = 0, no load to integrate
  // Vertical lines x = b across which the body force jumps (the load is integrated on each side)
  virtual std::vector<double> body_force_breaks() const { return {}; }
  virtual double pressure(double x) const = 0;  // p = -sigma_N on Gamma_c
  // The points of Gamma_c where p is not smooth (the edges of a contact zone, where p behaves
  // like a square root): a quadrature of p must cut there or lose its order
  virtual std::vector<double> pressure_kinks() const { return {}; }
  // the shear sigma_12 on Gamma_c (chapter 8's lambda_t): 0 without friction
  virtual double shear(double) const { return 0.0; }
  // int_0^L p: 8-point Gauss on 64 pieces unless a kind knows it in closed form
  virtual double total_force(double L) const;

  // [u.n] = u^2_y - u^1_y on Gamma_c (positive = penetration)
  double normal_jump(double x) const;
  // sigma = lambda tr(eps) I + 2 mu eps from grad_u and body l's material
  Eigen::Matrix2d stress(int l, const Eigen::Vector2d& p) const;
  ExactSolution exact(int l) const;
  const Material& material(int l) const { return l == 0 ? m1_ : m2_; }

 protected:
  ExactContact(const Material& body1, const Material& body2) : m1_(body1), m2_(body2) {}

 private:
  Material m1_, m2_;
};

}  // namespace mortar
