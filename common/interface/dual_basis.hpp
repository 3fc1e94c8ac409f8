// The dual (biorthogonal) basis of the multiplier space (Wohlmuth 2000; chapter 6): functions
// psi_i of the same dimension N - 1 as M_h^1, on the same nodes, such that
//
//     D_ij = int_{Gamma_c} psi_i phi^1_j = delta_ij int_{Gamma_c} phi^1_j     (i, j interior),
//
// so D is diagonal and the constraint rows can be solved node by node.
//  - On an interior element e with local hats phi_a, phi_b, psi|_e = A_e (phi_a, phi_b) with
//    A_e = D_e M_e^{-1}, M_e the element's P1 mass matrix and D_e = diag(int_e phi_a, int_e phi_b):
//    then int_e psi_a phi_b = 0 and int_e psi_a phi_a = int_e phi_a. For P1, A_e = [2 -1; -1 2]
//    on every element, whatever its length: psi_a = 2 phi_a - phi_b.
//  - On the two end elements, where the paper's M_h^1 is constant, psi_1 = 1 (and psi_{N-1} = 1):
//    int psi_1 phi_2 = 0 still holds (phi_2 is zero there), int psi_1 phi_1 gains the end
//    element's h_0 / 2, and sum_i psi_i = 1 on every element, so constants are reproduced and
//    the patch test can pass.
// The functions jump at the nodes and take negative values (2 phi_a - phi_b = -1 at b): a
// nonnegative coefficient lambda_i does not make sum_i lambda_i psi_i >= 0 (chapter 6's notes).
#pragma once

#include <Eigen/Dense>

#include "common/interface/multiplier_space.hpp"

namespace mortar {

// A_e = D_e M_e^{-1} for an element of length h (the coefficients of the two dual functions
// of the element in its local hats, one row each).
Eigen::Matrix2d dual_element_coefficients(double h);

// The dual basis of M_h^1's dimension on trace 1: space.E holds psi_i element by element,
// space.C the hats of M_h^1 on the same nodes (multiplier_space.hpp). Needs N >= 2 elements.
MultiplierSpace dual_end_modified_p1(const InterfaceTrace& trace1);

// max_{i != j} |D_ij| / D_ii over the interior columns j (the nodes the multipliers sit on):
// zero for a dual basis up to round-off, of order 1/4 for the hats of M_h^1.
double d_offdiagonal_max(const MultiplierSpace& space, const Eigen::SparseMatrix<double, Eigen::RowMajor>& D);

// sum_i lambda_i psi_i as a function: on element e of trace 1 the two end values (left, right),
// so the curve jumps at the nodes where a dual basis does.
struct BrokenCurve {
  std::vector<double> x;                  // the nodes of trace 1
  std::vector<double> left, right;        // per element: values at x_e and x_{e+1}
  double operator()(int element, double s) const { return (1 - s) * left[element] + s * right[element]; }
};
BrokenCurve multiplier_function(const MultiplierSpace& space, const InterfaceTrace& trace1,
                                const Eigen::VectorXd& coefficients);

// ||p - lambda_h||_{L2(Gamma_c)} for a broken curve (5-point Gauss on 4 pieces per element).
double l2_error(const BrokenCurve& lambda_h, const std::function<double(double)>& p);

}  // namespace mortar
