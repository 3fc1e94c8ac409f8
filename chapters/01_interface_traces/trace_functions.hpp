// The traces chapter 1 transfers from side 2 to side 1, on Gamma_c = (0, L):
//  - smooth: w(x) = 1 + x/L + sin(5 pi x / (2L)) / 2, in every H^s;
//  - kink:   w(x) = 1 + |x - x_k| / L, one kink at x_k = (sqrt(2) - 1) L, never a node;
//  - rough:  w(x) = 1 + (1/24) sum_j |x - x_j| / L, 24 kinks at x_j = frac(1/2 + j g) L
//            with g the golden ratio, spread evenly but never on a dyadic grid.
// A kinked trace is only in H^{3/2 - eps}: P1 errors are at best O(h^{3/2}) in L2 and
// O(h^{1/2}) in H1. With one kink the constant depends on where the kink falls inside its
// element, which changes from level to level; 24 kinks average that out (chapter notes).
#pragma once

#include <string>
#include <vector>

namespace chapter01 {

struct TraceFunction {
  std::string name;
  double L = 1;
  std::vector<double> kinks;  // where the derivative jumps (empty for smooth)

  double value(double x) const;
  double derivative(double x) const;
};

TraceFunction trace_function(const std::string& name, double L);

}  // namespace chapter01
