// One case of chapter 1: a trace w, side 1 with n1 elements, side 2 with n2; side 2 holds
// the nodal interpolant w2 of w, and both transfers carry it to side 1.
#pragma once

#include <vector>

#include "common/interface/interface_trace.hpp"
#include "common/linalg/physical_limit.hpp"
#include "trace_functions.hpp"

namespace chapter01 {

struct TransferCase {
  int n1 = 12, n2 = 8;
  double jitter = 0;
};

// Relative errors of a transfer against the exact w, on side 1's grid.
struct TransferErrors {
  double l2 = 0, h1 = 0;          // ||w1 - w|| / ||w|| in L2 and H1 seminorm
  double integral_rel_error = 0;  // |int w1 - int w2| / |int w2|
};

struct TransferResult {
  mortar::InterfaceTrace trace1, trace2;
  std::vector<double> w2, pointwise, mortar;
  TransferErrors pointwise_errors, mortar_errors;
  double time_s = 0;   // merged grid + D, M + the projection solve (best of 5)
  double limit_s = 0;  // the 1D floor: assemble side 1's mass matrix, Cholesky, solve (best of 5)
  mortar::TimedLevel timing{};  // both, with their spread and phases
};

// Side 2 has n2 = round(n1 / r) elements for a mesh ratio r = h2 / h1 (at least one).
int side2_elements(int n1, double ratio);

// True when every node of `coarse` is a node of `fine`: then pointwise transfer from coarse
// to fine is exact, and the two transfers cannot be told apart.
bool nested(const mortar::InterfaceTrace& coarse, const mortar::InterfaceTrace& fine);

TransferResult run_transfer_case(const TransferCase& c, const TraceFunction& w);

}  // namespace chapter01
