// A residual a posteriori error estimator for frictionless two-body contact discretized by
// mortar P1 elements with a multiplier lambda_h = sum_i lambda_i psi_i on the non-mortar trace
// (chapter 10, adaptivity). Its pattern is the residual estimator of Hild and Nicaise,
// "Residual a posteriori error estimators for contact problems in elasticity", M2AN 41 (2007)
// 897-923 (one body on a rigid foundation, P1, a multiplier on Gamma_c), carried to two bodies
// on non-matching meshes as in Wohlmuth, "An a posteriori error estimator for two-body contact
// problems on non-matching meshes", J. Sci. Comput. 33 (2007) 25-45 (dual multipliers, where
// lambda_h is the Neumann datum of both bodies on Gamma_c). Wohlmuth's own estimator is of
// equilibrated type (Arnold-Winther stresses, equilibrated fluxes); only its use of lambda_h as
// each body's traction is taken over here. (Written from the papers' abstracts and the
// residual estimator's usual form: the full texts were not at hand, so no equation numbers.)
//
// Per triangle T of body l (E_l its Young's modulus, h the diameter of T or the length of an
// edge E, sigma_h = sigma(u_h) constant on T, n the outward normal of the body):
//
//   volume            h_T^2 / E_l ||f + div sigma_h||_T^2 = h_T^2 / E_l ||f||_T^2   (P1)
//   jump              h_E / E_l ||[sigma_h n]||_E^2, interior edges, half to each side
//   neumann           h_E / E_l ||g_N - sigma_h n||_E^2, edges on traction sides
//   contact_normal    h_E / E_l ||sigma_h n.n + lambda_h||_E^2, edges on Gamma_c (both bodies)
//   contact_tangential h_E / E_l ||sigma_h n.t||_E^2, edges on Gamma_c (both bodies)
//   penetration       E* / h_E ||([u_h.n] - g)^+||_E^2, non-mortar edges
//   complementarity   int_E lambda_h^+ (g - [u_h.n])^+, non-mortar edges
//
// The first five are the residual of the equilibrium in the dual norm of the energy: each is
// (h^{1/2} or h) times an L2 norm of a force density over sqrt(E), so eta has the units of
// (int sigma : eps)^{1/2}, and multiplying both E by a factor (with the loads) leaves eta /
// ||u - u_h|| unchanged. The last two measure how far u_h is from the convex set and how far
// (u_h, lambda_h) is from complementarity; contact_estimator.cpp says where each comes from.
#pragma once

#include <array>
#include <functional>
#include <utility>
#include <vector>

#include "common/contact/constraints.hpp"
#include "common/contact/two_bodies.hpp"

namespace mortar {

enum class EstimatorTerm { volume, jump, neumann, contact_normal, contact_tangential, penetration, complementarity };
constexpr int estimator_terms = 7;
const char* estimator_term_name(EstimatorTerm t);

struct EstimatorData {
  std::array<VectorField, 2> body_force;  // per body; empty function = none
  // Per body, the sides with a prescribed traction g_N (free sides: list them with zero
  // traction, or an empty function). The contact side (body 1 bottom, body 2 top) is Gamma_c;
  // every side not listed is Dirichlet (no term).
  std::array<std::vector<std::pair<Side, VectorField>>, 2> neumann;
  std::function<double(double)> gap;  // initial gap g(x) >= 0; empty = 0
  bool unilateral = true;  // false: bilateral, [u.n] = g (penetration on |[u_h.n] - g|, no complementarity)
};

struct ContactEstimate {
  std::array<std::vector<double>, 2> indicator2;  // eta_T^2 per triangle of each body, all terms
  std::array<double, estimator_terms> term2{};     // each term's share, squared, both bodies
  double total() const;                            // sqrt of the sum
  double term(EstimatorTerm t) const;              // sqrt of one share
};

// E* of the two bodies in plane strain: 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2.
double combined_modulus(const Material& body1, const Material& body2);

// u: both bodies, every dof (prescribed ones included); lambda: one multiplier per row of c
// (integral matching: the coefficients of psi_i). P1 meshes only (std::invalid_argument else).
ContactEstimate estimate_contact_error(const TwoBodies& bodies, const Eigen::VectorXd& u,
                                       const ContactInterface& gamma, const Constraints& c,
                                       const Eigen::VectorXd& lambda, const EstimatorData& data);

}  // namespace mortar
