// What the solution says on Gamma_c: the normal jump [u_h.n] and the contact pressure, and
// their L2(Gamma_c) errors against exact functions.
//  - integral matching: the pressure is the multiplier itself, lambda_h = sum_i lambda_i psi_i,
//    a P1 function on the non-mortar trace with nodal values C^T lambda;
//  - pointwise matching: lambda_a is a nodal force, not a pressure. We report
//    lambda_a / (tributary length of a) = lambda_a / (half the two element lengths at a),
//    interpolated P1 on the non-mortar trace: a post-processed pressure, stated as such.
#pragma once

#include <functional>
#include <vector>

#include "common/contact/constraints.hpp"
#include "common/contact/two_bodies.hpp"
#include "common/interface/dual_basis.hpp"

namespace mortar {

// A function on Gamma_c given by its values at the points x: P1 between consecutive points, or
// (degree 2, the traces of P2 bodies) on each [x_{2e}, x_{2e+2}] the quadratic through the
// three points 2e, 2e + 1, 2e + 2, the middle one at the midpoint. Pictures draw the points.
struct InterfaceCurve {
  std::vector<double> x, value;
  int degree = 1;
  int pieces() const { return (static_cast<int>(x.size()) - 1) / degree; }
  // The value on piece e at the local coordinate s in [0, 1].
  double at(int piece, double s) const;
};

// The coefficient of every psi_i of the space, from the multipliers of the kept rows (zero on a
// row dropped by constraint_rows).
Eigen::VectorXd multiplier_coefficients(const ContactInterface& gamma, const Constraints& c,
                                        const Eigen::VectorXd& lambda);
// lambda_h = sum_i lambda_i psi_i as the function it is, element by element (integral matching;
// for the dual basis it jumps at the nodes).
BrokenCurve multiplier_function(const ContactInterface& gamma, const Constraints& c, const Eigen::VectorXd& lambda);

// Nodal pressure on the non-mortar trace, at its nodes (of degree q: for P2 the end points and
// midpoints of its elements). Pointwise matching: lambda_a / int phi_a, the nodal force spread
// over the trace function of its node (half the two element lengths for P1).
InterfaceCurve contact_pressure(const ContactInterface& gamma, const Constraints& c,
                                const Eigen::VectorXd& lambda);

// [u_h.n] = u2_y - u1_y, of the traces' degree q on each merged segment (both traces are one
// polynomial there): exact values at the merged breakpoints (and, for q = 2, the segments'
// midpoints).
InterfaceCurve normal_jump(const TwoBodies& bodies, const ContactInterface& gamma,
                           const Eigen::VectorXd& u);

// int of the total normal force carried by the multipliers, sum_i lambda_i int psi_i (or the
// sum of nodal forces for pointwise matching).
double total_contact_force(const ContactInterface& gamma, const Constraints& c,
                           const Eigen::VectorXd& lambda);

// (int_{Gamma_c} (curve - exact)^2)^{1/2}, by 4-point Gauss on each piece of the curve (exact
// for a polynomial exact function of degree 3 or less).
double l2_error(const InterfaceCurve& curve, const std::function<double(double)>& exact);
double l2_norm(const InterfaceCurve& curve, const std::function<double(double)>& exact_for_grid);
// ||a - b|| / ||b|| in L2 for two P1 curves on the same points (exact: h/3 (d0^2 + d0 d1 + d1^2)
// per piece); 0 when b is zero.
double relative_l2_difference(const InterfaceCurve& a, const InterfaceCurve& b);

// The contact zone read off a nodal pressure: the outermost nodes with p > 0 on each side and
// their first neighbours with p = 0. The half-width estimate puts each edge of the zone at
// the midpoint between the two, so it is off by at most half an element on each side.
struct ContactZone {
  bool empty = true;
  double left_active = 0, right_active = 0;      // outermost nodes in contact
  double left_inactive = 0, right_inactive = 0;  // their first neighbours out of contact
  int active_nodes = 0;
  int active_elements = 0;  // elements of the trace with p > 0 at both ends
  double half_width() const;  // 0 when empty
};
ContactZone contact_zone(const InterfaceCurve& pressure);

}  // namespace mortar
