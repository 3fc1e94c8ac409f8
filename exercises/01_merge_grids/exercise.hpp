// Exercise 1: merge two 1D grids on Gamma_c into one, with a tolerance.
#pragma once

#include <vector>

namespace exercise {

// x1, x2: the sorted nodes of the two traces, sharing their end points. Return the sorted
// union of both, where points closer than rel_tol * (x1.back() - x1.front()) to the previous
// kept point are dropped (so nodes 1e-14 apart give one breakpoint, not a sliver).
std::vector<double> merge_breakpoints(const std::vector<double>& x1, const std::vector<double>& x2,
                                      double rel_tol);

}  // namespace exercise
