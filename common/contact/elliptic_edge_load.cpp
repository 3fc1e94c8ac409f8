#include "common/contact/elliptic_edge_load.hpp"

#include <cmath>

namespace mortar {

EllipticEdgeLoad elliptic_edge_load(double X, double z, double b, double k) {
  using Complex = std::complex<double>;
  const Complex zeta(X, z + 0.0), minus_i_k(0.0, -k / b);  // z + 0.0: never -0
  const Complex S = std::sqrt(zeta - b) * std::sqrt(zeta + b);
  // zeta - S = b^2 / (zeta + S): the same number without the cancellation of two large ones
  // far from the load (|zeta + S| >= b for z >= 0)
  const Complex zeta_minus_S = b * b / (zeta + S);
  EllipticEdgeLoad f;
  f.d1 = minus_i_k * (0.5 * zeta * zeta_minus_S + 0.5 * b * b * std::log((zeta + S) / b));
  f.d2 = minus_i_k * zeta_minus_S;
  // W''' = -i (k/b) (1 - zeta/S) = i (k/b) b^2 / ((zeta + S) S), written without the cancellation
  f.d3 = z > 0 ? -minus_i_k * zeta_minus_S / S : Complex(0.0, 0.0);
  return f;
}

}  // namespace mortar
