// The Lagrange basis of degree 1 or 2 on a 1D element, in its local coordinate s in [0, 1]:
// the traces of P_q triangles on a side (loads on a side) and on Gamma_c (paper section 3):
//     q = 1:  1 - s,  s                                  (nodes s = 0, 1)
//     q = 2:  (1 - s)(1 - 2s),  4 s (1 - s),  s (2s - 1)   (nodes s = 0, 1/2, 1)
// On a trace, the local function l of element e belongs to node q e + l (interface_trace.hpp).
#pragma once

#include <array>
#include <stdexcept>
#include <string>

namespace mortar {

inline void check_trace_degree(int degree) {
  if (degree != 1 && degree != 2)
    throw std::invalid_argument("trace degree must be 1 or 2, got " + std::to_string(degree));
}

// The q + 1 values at s (the unused third entry is 0 for q = 1).
inline std::array<double, 3> lagrange_1d(int degree, double s) {
  if (degree == 1) return {1 - s, s, 0.0};
  return {(1 - s) * (1 - 2 * s), 4 * s * (1 - s), s * (2 * s - 1)};
}

}  // namespace mortar
