// Exercise 14: the Nitsche contact term of one segment of the merged grid, and its Newton
// derivative (chapter 11).
#pragma once

#include <Eigen/Dense>
#include <functional>

namespace exercise {

using Vector12 = Eigen::Matrix<double, 12, 1>;
using Matrix12 = Eigen::Matrix<double, 12, 12>;

// One segment [a, b] of the merged grid and the 12 local dofs of its two triangles (body 1's,
// then body 2's). Each field is a functional of the local displacement v:
//   p       the traction p(v) = w p^1(v) + (1 - w) p^2(v), constant on the segment,
//   jump_a  [v.n] at x = a,   jump_b  [v.n] at x = b   ([v.n] is linear between),
//   gamma   Nitsche's parameter on the segment.
struct Segment {
  double a = 0, b = 1;
  Vector12 p = Vector12::Zero(), jump_a = Vector12::Zero(), jump_b = Vector12::Zero();
  double gamma = 1;
};

struct SegmentTerm {
  Vector12 residual = Vector12::Zero();
  Matrix12 jacobian = Matrix12::Zero();
};

// With P_gamma(u)(x) = p(u) + gamma ([u.n](x) - g(x)) and P_theta(v)(x) = theta p(v) + gamma [v.n](x),
//   residual_i = - int_a^b (theta / gamma) p(u) p(e_i) dx + int_a^b (1 / gamma) [P_gamma(u)(x)]_+ P_theta(e_i)(x) dx
// (e_i the i-th local unit vector), and jacobian = d residual / d u with the derivative of
// [t]_+ taken as 1 where t > 0 and 0 elsewhere. g is any smooth function on [a, b]: the
// integrals must be exact up to round-off where g is a polynomial of degree 3 or less.
SegmentTerm nitsche_segment_term(const Segment& s, double theta, const std::function<double(double)>& gap,
                                 const Vector12& u);

}  // namespace exercise
