// Two ways to carry a trace w2 of side 2 over to side 1's grid (chapter 1):
//  - pointwise transfer: w1(a) = w2(a) at every node a of xi^1 (the V_h^P way);
//  - mortar projection: D w1 = M w2, i.e. int (w1 - w2) psi = 0 for all psi in M_h^1
//    (the V_h^I way). M_h^1 has no function for the end nodes a1, a2; these are common nodes
//    of both grids, so w1 takes side 2's values there and D's interior block gives the rest.
// Since sum_i psi_i = 1, the projection keeps int w exactly; the pointwise transfer does not.
#pragma once

#include <vector>

#include "common/interface_trace.hpp"
#include "common/mortar_matrices.hpp"

namespace mortar {

std::vector<double> pointwise_transfer(const InterfaceTrace& trace1, const InterfaceTrace& trace2,
                                       const std::vector<double>& w2);

std::vector<double> mortar_projection(const InterfaceTrace& trace1, const InterfaceTrace& trace2,
                                      const MortarMatrices& mortar, const std::vector<double>& w2);

// int_{Gamma_c} w for a nodal P1 function on a trace (trapezoidal rule is exact for P1).
double integral(const InterfaceTrace& trace, const std::vector<double>& w);

}  // namespace mortar
