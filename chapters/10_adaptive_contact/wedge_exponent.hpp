// The singular exponent at the punch's corners: an elastic wedge of angle phi resting without
// friction on an elastic half-plane (plane strain). Near the corner u ~ r^lambda and the
// contact pressure ~ r^(lambda - 1), with 0 < lambda < 1 the smallest root of
//
//   (1 - alpha)(sin 2 lambda phi + lambda sin 2 phi) sin lambda pi
//       + 2 (1 + alpha) cos lambda pi (sin^2 lambda phi - lambda^2 sin^2 phi) = 0,
//
// alpha = (E1* - E2*) / (E1* + E2*) Dundurs' first parameter with E* = E / (1 - nu^2), body 1 the
// wedge. Derived for this course from Williams' expansion r^(lambda+1) F(theta) of the Airy
// function in each body: the wedge's free face, no shear on either side of the contact face,
// equal normal tractions and equal normal displacements across it (chapter notes, "The punch").
// Only the normal compliances couple, so Dundurs' beta drops out. Checks: a rigid wedge
// (alpha = 1) gives lambda = 1/2, the flat punch's square-root pressure; a rigid base
// (alpha = -1) lambda = 1, no singularity; phi = pi (a half-plane on a half-plane) lambda = 1/2
// for every alpha. For phi = pi/2 the equation reads
// (1 - alpha) sin^2 lambda pi + (1 + alpha) cos lambda pi (1 - cos lambda pi - 2 lambda^2) = 0.
#pragma once

namespace chapter10 {

double dundurs_alpha(double E1, double nu1, double E2, double nu2);
// lambda in (0, 1), by bisection on a fine scan; 1 when there is no root below 1 (alpha = -1).
double wedge_on_half_plane_exponent(double alpha, double phi);

}  // namespace chapter10
