// Error norms of a P1 or P2 displacement against an exact solution: L2, H1 seminorm and energy.
#pragma once

#include <Eigen/Dense>
#include <functional>

#include "common/fem/mesh.hpp"
#include "common/fem/p1_elasticity.hpp"

namespace mortar {

struct ExactSolution {
  VectorField u;                                                 // displacement
  std::function<Eigen::Matrix2d(const Eigen::Vector2d&)> grad_u;  // (grad u)_{ij} = d u_i / d x_j
};

// Squared norms over one body, so that several bodies add up before the square root.
struct SquaredNorms {
  double l2 = 0;       // int |u - u_h|^2
  double h1_semi = 0;  // int |grad (u - u_h)|^2
  double energy = 0;   // int sigma(u - u_h) : eps(u - u_h)
  SquaredNorms& operator+=(const SquaredNorms& o);
};

struct ErrorNorms {
  SquaredNorms error;  // of u - u_h
  SquaredNorms exact;  // of u, for relative errors
  ErrorNorms& operator+=(const ErrorNorms& o);
  double relative_l2() const;
  double relative_h1_semi() const;
  double relative_energy() const;
};

// Integrates with a triangle rule of the given degree (u is smooth; u_h is linear per element,
// or on a P2 mesh quadratic, evaluated by the six shape functions at every point).
ErrorNorms error_norms(const Mesh& mesh, const Material& material, const Eigen::VectorXd& u_h,
                       const ExactSolution& exact, int degree = 6);

}  // namespace mortar
