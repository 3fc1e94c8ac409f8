// The L2 best approximation of a Hertz pressure p(x) = sqrt(1 - ((x - x0)/a)^2) (0 outside the
// zone) in M_h^1, the end-modified P1 multipliers on a uniform trace of n elements of (0, L),
// computed without any of the course's quadrature: the loads (p, phi_j) from the
// antiderivatives of sqrt(1 - t^2) and t sqrt(1 - t^2), the Gram matrix from the P1 element
// mass matrix, ||p||^2 = 4a/3 (the zone inside (0, L)), and ||p - Pi_h p||^2 = ||p||^2 -
// (Pi_h p, p). What the pressure norms of the programs must reproduce at the square-root edges.
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace hertz_best {

// int sqrt(1 - t^2) and int t sqrt(1 - t^2), t clamped to [-1, 1]
inline double area_primitive(double t) {
  t = std::clamp(t, -1.0, 1.0);
  return 0.5 * (t * std::sqrt(1 - t * t) + std::asin(t));
}
inline double moment_primitive(double t) {
  t = std::clamp(t, -1.0, 1.0);
  return -std::pow(1 - t * t, 1.5) / 3;
}

// (p, phi_j), j = 0..n, for the P1 hats of the uniform trace
inline Eigen::VectorXd hat_loads(double L, int n, double x0, double a) {
  Eigen::VectorXd load = Eigen::VectorXd::Zero(n + 1);
  const double h = L / n;
  for (int e = 0; e < n; ++e) {
    const double xl = e * h, xr = (e + 1) * h;
    const double tl = (xl - x0) / a, tr = (xr - x0) / a;
    // int p = a (A(tr) - A(tl)); int x p = x0 int p + a^2 (M(tr) - M(tl)), x = x0 + a t
    const double m0 = a * (area_primitive(tr) - area_primitive(tl));
    const double m1 = x0 * m0 + a * a * (moment_primitive(tr) - moment_primitive(tl));
    load[e] += (xr * m0 - m1) / h;      // phi_e = (xr - x) / h
    load[e + 1] += (m1 - xl * m0) / h;  // phi_{e+1} = (x - xl) / h
  }
  return load;
}

// C: psi_i = phi_i for the interior nodes i = 1..n-1, the end hats added to their neighbours
// (psi_1 = phi_0 + phi_1, psi_{n-1} = phi_{n-1} + phi_n); n >= 2
inline Eigen::MatrixXd end_modified(int n) {
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(n - 1, n + 1);
  for (int i = 1; i < n; ++i) C(i - 1, i) = 1;
  C(0, 0) = 1;
  C(n - 2, n) = 1;
  return C;
}

inline Eigen::MatrixXd p1_mass(double L, int n) {
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(n + 1, n + 1);
  const double h = L / n;
  for (int e = 0; e < n; ++e) {
    M(e, e) += h / 3;
    M(e + 1, e + 1) += h / 3;
    M(e, e + 1) += h / 6;
    M(e + 1, e) += h / 6;
  }
  return M;
}

// ||p - Pi_h p||_{L2} / ||p||_{L2}
inline double relative_best_error(double L, int n, double x0, double a) {
  const Eigen::MatrixXd C = end_modified(n);
  const Eigen::MatrixXd gram = C * p1_mass(L, n) * C.transpose();
  const Eigen::VectorXd b = C * hat_loads(L, n, x0, a);
  const double norm2 = 4 * a / 3;
  return std::sqrt((norm2 - b.dot(gram.ldlt().solve(b))) / norm2);
}

}  // namespace hertz_best
