// The contact conditions of one non-mortar node with friction (chapter 8), written as
// equations C = 0 that a semismooth Newton method can linearize (Hueber, Stadler and Wohlmuth
// 2008; Gitterle et al. 2010). With a dual basis the conditions are nodal: node i has
//
//   lambda_n  the pressure coefficient (>= 0),     w_n  its weighted gap (B_n u - G)_i (<= 0),
//   lambda_t  the tangential coefficient,           w_t  its weighted slip int psi_i (u^1_x - u^2_x),
//
// lambda_t the shear sigma_12 on Gamma_c: the traction body 1 exerts on body 2 along x (body 1
// feels -lambda_t). Friction: |lambda_t| <= s, and where the node slips, lambda_t has the sign
// of the slip. s is Tresca's threshold (given) or Coulomb's F lambda_n. With c_n, c_t > 0:
//
//   normal:     C_n = lambda_n - max(0, lambda_n + c_n w_n)
//   tangential: C_t = max(s, |z|) lambda_t - s z,   z = lambda_t + c_t dw_t,
//
// dw_t the slip of this load step (w_t minus the slip at the end of the last one: Coulomb is a
// law for increments; for one step from rest, dw_t = w_t). C_n = 0 is lambda_n >= 0, w_n <= 0,
// lambda_n w_n = 0. C_t = 0 is: |z| < s (stick) gives dw_t = 0; |z| >= s (slip) gives
// lambda_t = s z / |z|, so |lambda_t| = s and dw_t = (|z| - s) z / (c_t |z|) has lambda_t's sign.
// On a node out of contact (lambda_n + c_n w_n <= 0) the tangential equation is lambda_t = 0:
// nothing is transmitted, and C_t above would be degenerate there (s = 0). The same holds on a
// node in contact with no friction (s = 0: F = 0, or a zero Tresca threshold): it slips freely.
// Coulomb's threshold is s = F max(0, lambda_n + c_n w_n), which is F lambda_n once w_n = 0.
// An infinite Tresca threshold forbids slip on the whole node, in contact or not: C_t / s =
// -c_t dw_t. With it on every node the problem is chapter 6's unilateral contact with the
// tangential motion glued, a convex problem: friction_newton.hpp starts from its solution when
// the Newton steps do not settle, and the fixed point on Tresca thresholds starts with it.
#pragma once

namespace mortar {

enum class FrictionLaw { tresca, coulomb };

// What a node does: out of contact, in contact and stuck, in contact and slipping.
enum class NodeStatus { open, stick, slip };
const char* node_status_name(NodeStatus s);

struct NodalUnknowns {
  double lambda_n = 0, w_n = 0;  // pressure coefficient, weighted gap
  double lambda_t = 0, dw_t = 0;  // tangential coefficient, weighted slip of this step
};

struct NodalLaw {
  FrictionLaw law = FrictionLaw::coulomb;
  double friction = 0;   // F (Coulomb)
  double threshold = 0;  // s (Tresca)
  double c_n = 1, c_t = 1;
};

// s of the node: Tresca's given threshold, or F max(0, lambda_n + c_n w_n).
double friction_threshold(const NodalUnknowns& x, const NodalLaw& law);
NodeStatus node_status(const NodalUnknowns& x, const NodalLaw& law);

double normal_function(const NodalUnknowns& x, const NodalLaw& law);      // C_n
double tangential_function(const NodalUnknowns& x, const NodalLaw& law);  // C_t

// The two equations of the node in the unit of the multipliers, each beside the size it is
// measured against (the stopping test of friction_newton.hpp):
//   normal:     C_n, against max(|lambda_n|, c_n |w_n|), the node's pressure or its gap;
//   tangential: C_t / max(s, |z|) = lambda_t - s z / max(s, |z|), lambda_t minus the
//               projection of z onto [-s, s], against s (in contact with s > 0); elsewhere
//               lambda_t, against the normal size.
// On a slip node the tangential residual over s is the relative distance of |lambda_t| from
// its threshold; on a stick node it is c_t |dw_t| / s, the slip in units of the threshold.
// C_t itself is a multiplier times a threshold: measured against a multiplier it would depend
// on the unit of E.
struct NodalResidual {
  double normal = 0, normal_size = 0;
  double tangential = 0, tangential_size = 0;
};
NodalResidual nodal_residual(const NodalUnknowns& x, const NodalLaw& law);

// A generalized derivative of C with respect to (lambda_n, w_n, lambda_t, dw_t): the Newton
// row of the node. The max and the absolute value are differentiated on the side the status
// says (at a kink either side is a generalized derivative).
struct NodalGradient {
  double lambda_n = 0, w_n = 0, lambda_t = 0, dw_t = 0;
  double dot(const NodalUnknowns& x) const { return lambda_n * x.lambda_n + w_n * x.w_n + lambda_t * x.lambda_t + dw_t * x.dw_t; }
};
NodalGradient normal_gradient(const NodalUnknowns& x, const NodalLaw& law);
// `bounded`: the slip rows use lambda_t / max(1, |lambda_t| / s) in place of lambda_t, so a
// step taken from a point with |lambda_t| > s is taken as if |lambda_t| = s (the modification
// of Hueber, Stadler and Wohlmuth 2008); at |lambda_t| <= s both gradients agree. Without it,
// the exact generalized derivative.
NodalGradient tangential_gradient(const NodalUnknowns& x, const NodalLaw& law, bool bounded = true);

}  // namespace mortar
