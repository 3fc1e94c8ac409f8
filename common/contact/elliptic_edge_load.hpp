// The complex potential of an elliptical load on the edge of a half-plane: the harmonic
// function whose edge values are k sqrt(1 - X^2 / b^2) on |X| < b and 0 outside, with its
// derivatives. Hertz's pressure (hertz_half_planes.hpp) and Cattaneo-Mindlin's shear
// (cattaneo_half_planes.hpp) are built from it. With zeta = X + i z, z >= 0 the depth into the
// body and S = sqrt(zeta - b) sqrt(zeta + b) (S ~ zeta at infinity, analytic for z > 0):
//
//   W''(zeta) = -i (k/b) (zeta - S),   Re W'' = -k sqrt(1 - X^2/b^2) on the edge inside, 0 outside,
//   W'(zeta)  = -i (k/b) (zeta (zeta - S) / 2 + (b^2/2) log((zeta + S) / b)),
//   W'''      = -i (k/b) (1 - zeta / S),
//
// decaying like 1/|zeta| (W'') away from the load (Johnson, Contact Mechanics, 2.7 and 7.2).
#pragma once

#include <complex>

namespace mortar {

struct EllipticEdgeLoad {
  std::complex<double> d1, d2, d3;  // W', W'', W''' at zeta
};

// W', W'', W''' at X + i z for an elliptical load of half-width b and peak k. On the edge z = 0
// the values are the limits from inside the body (z -> +0), which pick the branches of S and of
// the logarithm there; W''' is infinite at the ends of the load and is returned as 0 on the
// edge, where it only ever enters multiplied by z.
EllipticEdgeLoad elliptic_edge_load(double X, double z, double b, double k);

}  // namespace mortar
