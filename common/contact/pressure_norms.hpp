// The contact pressure measured in its own norms (paper section 4; chapter 4's notes,
// "What we observe"). Theorem 4.2 with the inf-sup condition bounds the multiplier error in
// H^{-1/2}(Gamma_c) by O(h); in L2 only O(h^{1/2}) follows, through an inverse inequality. So
// a pressure error is reported
//  - in L2(Gamma_c), whole and split into the interior and the two end elements of the
//    non-mortar trace (where M_h^1 is constant and caps the L2 best approximation);
//  - in the mesh-dependent norm (sum_e h_e ||.||^2_{L2(e)})^{1/2}, the computable stand-in for
//    H^{-1/2} of mortar analysis (Wohlmuth 2001), e the elements of the non-mortar trace;
//  - beside the L2 best approximation of p in M_h^1, which says what M_h^1 can do at all.
#pragma once

#include <functional>
#include <vector>

#include "common/contact/constraints.hpp"
#include "common/contact/contact_fields.hpp"

namespace mortar {

// Errors of a contact pressure p_h (an InterfaceCurve, P1 on the non-mortar trace) against an exact p.
struct PressureErrors {
  double l2 = 0;           // ||p - p_h||_{L2(Gamma_c)}
  double l2_interior = 0;  // the same without the two end elements of the non-mortar trace
  double l2_ends = 0;      // on the two end elements only
  double hminus = 0;       // mesh-dependent H^{-1/2} norm: (sum_e h_e ||p - p_h||^2_{L2(e)})^{1/2}, e the elements of the non-mortar trace
  double best_l2 = 0;      // ||p - Pi_h p||_{L2}, Pi_h the L2 projection onto M_h^1 (gamma.space)
  double best_l2_interior = 0;
  double best_hminus = 0;  // the mesh-dependent norm of p - Pi_h p
  // Of p itself, for relative errors: ||p||_{L2}, and |Gamma_c|^{1/2} ||p||_{L2}, the
  // mesh-dependent norm of p on the one-element mesh of Gamma_c. Mesh-independent on purpose:
  // (sum_e h_e ||p||^2_e)^{1/2} shrinks like h^{1/2} and, as a divisor, would hide a rate.
  double norm_l2 = 0, norm_hminus = 0;
};
// kinks: the points where p is not smooth (ExactContact::pressure_kinks, the edges x0 +- a of a
// Hertz zone). Every integral is cut there and at every breakpoint of p_h: a Gauss rule across a
// square-root edge converges like h^{3/2} only, and misstates an error of order h^{3/2} itself.
PressureErrors pressure_errors(const ContactInterface& gamma, const InterfaceCurve& p_h,
                               const std::function<double(double)>& p, const std::vector<double>& kinks = {});

// Pi_h p: the L2(Gamma_c) projection of p onto M_h^1 = span{psi_i} (gamma.space on
// gamma.nonmortar_trace), as nodal values on the non-mortar trace. Solves
// (C M_phi C^T) c = C (int p phi_j)_j, M_phi the P1 mass matrix of the trace.
InterfaceCurve l2_projection(const ContactInterface& gamma, const std::function<double(double)>& p,
                             const std::vector<double>& kinks = {});

}  // namespace mortar
