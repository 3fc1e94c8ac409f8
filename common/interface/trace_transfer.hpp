// Two ways to carry a trace w2 of side 2 over to side 1's grid (chapter 1):
//  - pointwise transfer: w1(a) = w2(a) at every node a of xi^1 (the V_h^P way);
//  - mortar projection: D w1 = M w2, i.e. int (w1 - w2) psi = 0 for all psi in M_h^1
//    (the V_h^I way). D has N - 1 rows for N + 1 unknowns, so two values must come from
//    elsewhere. As a transfer operator we take them from side 2 at the end points a1, a2
//    (nodes of both grids); this is our choice for chapter 1: in the contact problem the
//    non-mortar end values are free unknowns, fixed by the elasticity equations instead.
//    D's interior block is then square and gives the interior values.
// Since sum_i psi_i = 1, the projection keeps int w exactly; the pointwise transfer does not.
// It needs N >= 2 side-1 elements (with N = 1 there are no interior values to adjust).
#pragma once

#include <vector>

#include "common/interface/interface_trace.hpp"
#include "common/interface/mortar_matrices.hpp"

namespace mortar {

std::vector<double> pointwise_transfer(const InterfaceTrace& trace1, const InterfaceTrace& trace2,
                                       const std::vector<double>& w2);

std::vector<double> mortar_projection(const InterfaceTrace& trace1, const InterfaceTrace& trace2,
                                      const MortarMatrices& mortar, const std::vector<double>& w2);

// int_{Gamma_c} w for a nodal P1 function on a trace (trapezoidal rule is exact for P1).
double integral(const InterfaceTrace& trace, const std::vector<double>& w);

}  // namespace mortar
