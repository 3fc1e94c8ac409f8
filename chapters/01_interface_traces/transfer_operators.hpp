// The two transfers of chapter 1 as matrices w1 = P w2, and what they do to forces.
//
// By virtual work a transfer P of displacements carries nodal forces the other way: forces F1
// on side 1 become F2 = P^T F1 on side 2. Two properties tell the transfers apart:
//  - sum_k F2_k = sum_j F1_j (equal and opposite total force) holds whenever P reproduces
//    constants, P 1 = 1: pointwise transfer and mortar projection both do;
//  - int w1 = int w2 for every w2 holds exactly when P^T carries the consistent loads of a
//    uniform traction on side 1, int phi^1_j, to those on side 2, int phi^2_k: only the mortar
//    projection does, because the constants lie in M_h^1 (the end modification).
#pragma once

#include <Eigen/Dense>

#include "common/interface/interface_trace.hpp"
#include "common/interface/multiplier_space.hpp"

namespace chapter01 {

// P column by column: the transfer of each side-2 hat. Mortar uses the multipliers `space`.
Eigen::MatrixXd mortar_matrix(const mortar::InterfaceTrace& t1, const mortar::InterfaceTrace& t2,
                              const mortar::MultiplierSpace& space);
Eigen::MatrixXd pointwise_matrix(const mortar::InterfaceTrace& t1, const mortar::InterfaceTrace& t2);

// M_h spanned by the plain interior hats phi^1_1 .. phi^1_{N-1}, without the end modification:
// also N - 1 functions (a square interior system), but they sum to 1 - phi_0 - phi_N.
mortar::MultiplierSpace plain_interior_hats(const mortar::InterfaceTrace& t1);

struct ForceTransfer {
  double total_rel_error = 0;  // |sum F2 - sum F1| / sum F1 for F1 = int phi^1_j
  double nodal_rel_error = 0;  // max_k |F2_k - int phi^2_k| / max_k int phi^2_k
};
ForceTransfer uniform_traction_transfer(const Eigen::MatrixXd& P, const mortar::InterfaceTrace& t1,
                                        const mortar::InterfaceTrace& t2);

// Locality of P: the side-1 nodes reached by the side-2 hat in the middle (|P_jk| > 1e-14 max),
// and the mean decay factor |P_{j+1,k}| / |P_{j,k}| of that column towards the far end.
struct Reach {
  int nodes_reached = 0, nodes = 0;
  double decay_per_element = 0;
};
Reach reach_of_middle_hat(const Eigen::MatrixXd& P);

}  // namespace chapter01
