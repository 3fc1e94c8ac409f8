// Exercise 1: merge two 1D grids on Gamma_c into one, with a tolerance.
#pragma once

#include <vector>

namespace exercise {

// x1, x2: the sorted nodes of the two traces (they need not share their end points). With
// L = x1.back() - x1.front(), tol = rel_tol * L and P the points of x1 and x2 together, return
// the sorted breakpoints y_0 < ... < y_m, points of P, such that
//   1. y_0 = min P and y_m = max P;
//   2. y_{j+1} - y_j > tol (no sliver: nodes 1e-14 apart give one breakpoint);
//   3. every p in P has a j with y_j <= p <= y_j + tol, or max P - tol <= p <= max P.
// Throws std::invalid_argument if x1 has fewer than 2 nodes, L <= 0, or rel_tol is outside [0, 1).
std::vector<double> merge_breakpoints(const std::vector<double>& x1, const std::vector<double>& x2,
                                      double rel_tol);

}  // namespace exercise
