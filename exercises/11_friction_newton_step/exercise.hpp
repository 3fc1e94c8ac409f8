// Exercise 11: one semismooth Newton step for one node with Coulomb friction.
#pragma once

#include <Eigen/Dense>

namespace exercise {

// One non-mortar node after chapter 8's condensation: the unknowns are v = (w_n, w_t), its
// weighted gap and weighted slip, and its multipliers are lambda = r - A v, lambda = (lambda_n,
// lambda_t): pressure and shear. With c_n = A(0,0), c_t = A(1,1), z = lambda_t + c_t w_t and
// s = F max(0, lambda_n + c_n w_n), the node's equations C(v) = 0 are
//
//   C_n = lambda_n - max(0, lambda_n + c_n w_n),
//   C_t = max(s, |z|) lambda_t - s z    where lambda_n + c_n w_n > 0 (in contact),
//   C_t = lambda_t                       elsewhere (open).
//
// Returns the next v of the semismooth Newton method, v - J^{-1} C(v), with J the generalized
// derivative dC/dv taken on the side of each max and |.| where v lies.
Eigen::Vector2d newton_step(const Eigen::Matrix2d& A, const Eigen::Vector2d& r, double F, const Eigen::Vector2d& v);

}  // namespace exercise
