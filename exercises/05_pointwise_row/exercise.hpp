// Exercise 5: one row of pointwise matching.
#pragma once

#include <Eigen/Dense>
#include <vector>

namespace exercise {

// The mortar side's part of the pointwise row at a non-mortar node x_a: the coefficients
// c_k = phi^2_k(x_a) of its nodal normal displacements, one per node of the sorted P1 mortar
// trace mortar_x. The whole row reads  u_nm(a).n_nm + sum_k c_k u_m,k.n_m = 0. A node the mortar
// trace does not cover (x_a below mortar_x.front() or above mortar_x.back(), by more than
// 1e-12 (mortar_x.back() - mortar_x.front())) gets the zero row: nothing to match there.
Eigen::VectorXd pointwise_row(double x_a, const std::vector<double>& mortar_x);

}  // namespace exercise
