// The traces chapter 1 transfers from side 2 to side 1, on Gamma_c = (0, L):
//  - smooth: w(x) = 1 + x/L + sin(5 pi x / (2L)) / 2, in every H^s;
//  - kink:   w(x) = 1 + |x - x_k| / L, one kink at x_k = (sqrt(2) - 1) L, never a node;
//  - rough:  w(x) = 1 + (1/24) sum_j |x - x_j| / L, 24 kinks at x_j = frac(1/2 + j g) L
//            with g the golden ratio, spread evenly but never on a dyadic grid;
//  - edge:   w(x) = sqrt(1 - (x - c)^2 / a^2)_+, the shape of a Hertz pressure, with c = L/2
//            and a = (sqrt(5) - 1) L / 4, so the two edges c -+ a are never nodes.
// A kinked trace is only in H^{3/2 - eps}: P1 errors are at best O(h^{3/2}) in L2 and
// O(h^{1/2}) in H1. With one kink the constant depends on where the kink falls inside its
// element, which changes from level to level; 24 kinks average that out (chapter notes).
// A square-root edge is rougher: w is in H^{1 - eps} only, its derivative is not square
// integrable (so there is no H1 error to report), and the P1 error is O(h) in L2.
#pragma once

#include <string>
#include <vector>

namespace chapter01 {

struct TraceFunction {
  std::string name;
  double L = 1;
  std::vector<double> kinks;  // where the derivative jumps (empty for smooth)
  double edge_center = 0, edge_half_width = 0;  // edge trace only (half-width > 0)

  bool has_edges() const { return edge_half_width > 0; }
  std::vector<double> edges() const;  // where w behaves like sqrt(distance): c -+ a
  double value(double x) const;
  double derivative(double x) const;  // infinite at the edges
};

TraceFunction trace_function(const std::string& name, double L);

}  // namespace chapter01
