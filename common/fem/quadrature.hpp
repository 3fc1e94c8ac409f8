// Quadrature rules: Gauss-Legendre on segments (GSL's glfixed tables) and a collapsed
// (Duffy) Gauss-Legendre rule on triangles. (Stroud's conical product rule uses Gauss-Jacobi
// points in the collapsed direction and gains one degree; GSL has Legendre tables only.)
#pragma once

#include <Eigen/Dense>
#include <vector>

namespace mortar {

// n-point Gauss-Legendre rule on [0, 1]; weights sum to 1. Exact for degree 2n - 1.
struct SegmentRule {
  std::vector<double> points;
  std::vector<double> weights;
};
SegmentRule gauss_legendre(int n);

// Rule on a triangle: points (s, t) in the reference triangle
// {s, t >= 0, s + t <= 1}, weights summing to 1, so that
//   int_T f = area(T) * sum_q w_q f(x0 + s_q (x1 - x0) + t_q (x2 - x0)).
// Built from n x n Gauss-Legendre points mapped by (a, b) -> (a, b (1 - a)), whose Jacobian
// (1 - a) raises the degree in a by one: exact for polynomials of degree 2n - 2.
struct TriangleRule {
  std::vector<Eigen::Vector2d> points;
  std::vector<double> weights;
  int degree = 0;  // the stated degree of exactness
};
TriangleRule triangle_rule(int degree);

}  // namespace mortar
