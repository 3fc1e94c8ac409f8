// The traces chapter 1 transfers from side 2 to side 1, on Gamma_c = (0, L):
//  - smooth: w(x) = 1 + x/L + sin(5 pi x / (2L)) / 2, in every H^s;
//  - rough:  w(x) = 1 + |x - x_k| / L with the kink at x_k = (sqrt(2) - 1) L, never a grid
//    node; w is only in H^{3/2 - eps}, so P1 rates drop to 3/2 (L2) and 1/2 (H1).
#pragma once

#include <string>

namespace chapter01 {

struct TraceFunction {
  std::string name;
  double L = 1;
  double value(double x) const;
  double derivative(double x) const;
  double kink() const;  // where the derivative jumps (a point outside [0, L] for smooth)
};

TraceFunction trace_function(const std::string& name, double L);

}  // namespace chapter01
