#include "common/contact/two_bodies.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "common/fem/p2_elasticity.hpp"

#include "common/timing/profile.hpp"

namespace mortar {

TwoBodies::TwoBodies(Body body1, Body body2) : bodies_{std::move(body1), std::move(body2)} {}

SparseMatrix TwoBodies::stiffness() const {
  const ProfilePhase phase("assembly");
  std::vector<Eigen::Triplet<double>> triplets;
  for (int l = 0; l < 2; ++l) add_stiffness_triplets(bodies_[l].mesh, bodies_[l].material, offset(l), triplets);
  SparseMatrix K(num_dofs(), num_dofs());
  K.setFromTriplets(triplets.begin(), triplets.end());
  return K;
}

Eigen::VectorXd TwoBodies::part(const Eigen::VectorXd& u, int l) const {
  return u.segment(offset(l), bodies_[l].mesh.num_dofs());
}

double TwoBodies::max_edge_length() const {
  return std::max(bodies_[0].mesh.max_edge_length(), bodies_[1].mesh.max_edge_length());
}

TwoBodies make_two_bodies(const TwoBodyGeometry& g, const Material& body1, const Material& body2) {
  RectangleSpec upper, lower;
  upper.x1 = lower.x1 = g.L;
  upper.y0 = 0;
  upper.y1 = g.H1;
  upper.nx = g.n1;
  upper.ny = g.m1;
  lower.y0 = -g.H2;
  lower.y1 = 0;
  lower.nx = g.n2;
  lower.ny = g.m2;
  upper.jitter = lower.jitter = g.jitter;
  upper.seed = 1;
  lower.seed = 2;  // independent jitter: the traces on Gamma_c differ
  if (g.degree == 2) return TwoBodies({p2_mesh(rectangle_mesh(upper)), body1}, {p2_mesh(rectangle_mesh(lower)), body2});
  if (g.degree != 1) throw std::invalid_argument("make_two_bodies: degree 1 or 2, got " + std::to_string(g.degree));
  return TwoBodies({rectangle_mesh(upper), body1}, {rectangle_mesh(lower), body2});
}

}  // namespace mortar
