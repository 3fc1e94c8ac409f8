// The peak of a computed contact pressure, read so that the node-to-node oscillation of a
// multiplier does not move it. On nonmatching traces the nodal pressure oscillates with the
// pattern of h2/h1 (chapter 3): its maximum, or its value at the one node at x = c, is that
// oscillation's extreme, not the peak. We fit the parabola alpha + beta (x - c)^2 to the
// pressure in L2 over the central half of the discrete contact zone, |x - c| <= a_h / 2 (away
// from the edges, where the pressure is a square root), and take its value alpha at c. For
// Hertz's ellipse p0 sqrt(1 - x^2 / a^2) this fit gives 1.00078 p0, whatever p0 and a; we
// divide by that factor (computed, not typed in), so that an exact ellipse returns its p0.
#pragma once

#include "common/contact/contact_fields.hpp"

namespace chapter05 {

// 0 when p vanishes. centre: the centre c of the contact zone (L/2 in the Hertz scene).
double peak_pressure(const mortar::InterfaceCurve& p, double centre);

// The pressure's value at x (P1 interpolation between its points).
double pressure_at(const mortar::InterfaceCurve& p, double x);

}  // namespace chapter05
