#include <algorithm>
#include <cmath>

#include "exercise.hpp"

namespace exercise {

Eigen::Vector2d newton_step(const Eigen::Matrix2d& A, const Eigen::Vector2d& r, double F, const Eigen::Vector2d& v) {
  const Eigen::Vector2d lambda = r - A * v;
  const double c_n = A(0, 0), c_t = A(1, 1);
  const double ln = lambda[0], lt = lambda[1], wn = v[0], wt = v[1];
  // Each equation's derivative with respect to (lambda_n, lambda_t) and to (w_n, w_t).
  Eigen::Vector2d C;
  Eigen::Matrix2d d_lambda = Eigen::Matrix2d::Zero(), d_w = Eigen::Matrix2d::Zero();
  const bool contact = ln + c_n * wn > 0;
  if (contact) {
    C[0] = -c_n * wn;  // lambda_n - (lambda_n + c_n w_n)
    d_w(0, 0) = -c_n;
    const double s = F * (ln + c_n * wn), z = lt + c_t * wt;
    const double ds_dln = F, ds_dwn = F * c_n;
    if (std::fabs(z) < s) {  // stick: C_t = s lambda_t - s z = -s c_t w_t
      C[1] = -s * c_t * wt;
      d_lambda(1, 0) = -c_t * wt * ds_dln;
      d_w(1, 0) = -c_t * wt * ds_dwn;
      d_w(1, 1) = -s * c_t;
    } else {  // slip: C_t = |z| lambda_t - s z
      const double sign = z >= 0 ? 1.0 : -1.0;
      C[1] = std::fabs(z) * lt - s * z;
      d_lambda(1, 1) = sign * lt + std::fabs(z) - s;
      d_w(1, 1) = c_t * (sign * lt - s);
      d_lambda(1, 0) = -z * ds_dln;
      d_w(1, 0) = -z * ds_dwn;
    }
  } else {  // open: C_n = lambda_n, C_t = lambda_t
    C = lambda;
    d_lambda = Eigen::Matrix2d::Identity();
  }
  const Eigen::Matrix2d J = -d_lambda * A + d_w;  // d lambda / dv = -A
  return v - J.partialPivLu().solve(C);
}

}  // namespace exercise
