// Is an exact two-body solution really the solution of the contact problem it is used for?
// Checked at sample points against the equations themselves, independently of any solver:
// grad u against finite differences of u (u is also the Dirichlet data), equilibrium (1) by
// finite differences of sigma, u on Gamma_c against its limit from inside each body (the
// branches of a field with a cut there), the tractions on Gamma_c (4), (5) (sigma_12 is the
// solution's shear: 0 without friction), the sign of the pressure and the complementarity
// (9)-(11) with the initial gap g: [u.n] = g where p > 0, no penetration [u.n] <= g where p = 0.
// Each residual is relative to its own scale; a scene reports the largest.
#pragma once

#include <functional>

#include "common/contact/exact_contact.hpp"

namespace mortar {

struct ExactContactResiduals {  // each body's residuals relative to that body's own sizes
  double gradient = 0;     // |grad u - D_h u| / max |grad u|
  double equilibrium = 0;  // |div sigma + f| d / max |sigma|, d the point's distance to Gamma_c
  double boundary = 0;     // |u(x, 0) - its limit from inside the body| / max |u|, on Gamma_c
  double traction = 0;     // |sigma_yy + p|, |sigma_xy - shear| on Gamma_c (both sides) / max p
  double sign = 0;         // max(0, -p) / max p
  double closed_gap = 0;   // |[u.n] - g| where p > 0, / the size of u_y and g on Gamma_c
  double penetration = 0;  // max(0, [u.n] - g) where p = 0, same scale
  double worst() const;
};

// Samples: 5 depths and the outer side of each body (0, L) x (0, H1), (0, L) x (-H2, 0) at 41
// abscissae; 41 points of Gamma_c, the corners included, for the limit of u; 2001 for the rest.
// Finite differences of order 4 with a step of 2e-4 times the depth, at least 2% of the
// body's height (truncation and round-off both about 1e-11 of the scale for the course's fields).
ExactContactResiduals check_exact_contact(const ExactContact& exact, const std::function<double(double)>& gap,
                                          double L, double H1, double H2);

}  // namespace mortar
