// The merged grid of two traces: the union of their breakpoints, so that on each merged
// segment every product phi^1_j phi^2_k is a single quadratic and 2-point Gauss is exact.
//
// Breakpoints closer than rel_tol * L are merged into one, so traces whose nodes are 1e-14
// apart give no sliver segment (and no 0/0 in a Jacobian), only the segments of the
// matching case.
#pragma once

#include <vector>

#include "common/interface/interface_trace.hpp"

namespace mortar {

struct MergedSegment {
  double a = 0, b = 0;  // end points
  int element1 = 0;     // element of trace 1 that contains the segment
  int element2 = 0;     // element of trace 2 that contains the segment
};

struct MergedGrid {
  std::vector<double> breakpoints;
  std::vector<MergedSegment> segments;
};

MergedGrid merge_traces(const InterfaceTrace& trace1, const InterfaceTrace& trace2,
                        double rel_tol = 1e-12);

}  // namespace mortar
