// A hard case of dual bases: a non-mortar element that the mortar side covers only in part
// (the mortar trace ends inside it). The course's scenes never have one (both traces span
// (0, L) and share a1, a2, the paper's assumption), so it is measured on 1D traces: D and M
// integrated over the covered part only, as any mortar code must when the sides end apart.
#pragma once

#include <string>
#include <vector>

namespace chapter06 {

struct PartialCoverage {
  double covered = 1;  // the fraction theta of the last interior element that the mortar side covers
  // max |D_ij| / D_ii off the diagonal: psi_a = 2 phi_a - phi_b is biorthogonal on the whole
  // element only
  double offdiagonal = 0;
  // min_i D_ii / int phi_i over the covered part: 1 where psi_i is biorthogonal; at the node
  // inside the partly covered element it is (theta^3 - theta^2 / 2) / (theta^2 / 2) = 2 theta - 1:
  // zero at theta = 1/2, negative below it (the condensation divides by it).
  double diagonal_ratio_min = 1;
  // A constant carried from the mortar side: max |w1 - 1| over the covered nodes of the
  // non-mortar side, solving D w1 = M 1 with D whole, and node by node with D's diagonal only
  // (the condensation of a dual basis).
  double constant_error_full = 0, constant_error_diagonal = 0;
};

// Non-mortar trace: n uniform elements on (0, 1); mortar trace: uniform elements of 3/2 times
// the size on (0, x_{n-2} + theta h), for each theta.
std::vector<PartialCoverage> partial_coverage(int n, const std::vector<double>& thetas);

void write_partial_coverage_csv(const std::string& path, const std::vector<PartialCoverage>& cases);

}  // namespace chapter06
