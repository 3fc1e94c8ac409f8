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

RectangleSpec body_rectangle(const TwoBodyGeometry& g, int l) {
  RectangleSpec s;
  s.x1 = g.L;
  s.y0 = l == 0 ? 0 : -g.H2;
  s.y1 = l == 0 ? g.H1 : 0;
  s.nx = l == 0 ? g.n1 : g.n2;
  s.ny = l == 0 ? g.m1 : g.m2;
  s.jitter = g.jitter;
  s.seed = l == 0 ? 1 : 2;  // independent jitter: the traces on Gamma_c differ
  return s;
}

TwoBodies make_two_bodies(const TwoBodyGeometry& g, const Material& body1, const Material& body2) {
  const RectangleSpec upper = body_rectangle(g, 0), lower = body_rectangle(g, 1);
  if (g.degree == 2) return TwoBodies({p2_mesh(rectangle_mesh(upper)), body1}, {p2_mesh(rectangle_mesh(lower)), body2});
  if (g.degree != 1) throw std::invalid_argument("make_two_bodies: degree 1 or 2, got " + std::to_string(g.degree));
  return TwoBodies({rectangle_mesh(upper), body1}, {rectangle_mesh(lower), body2});
}

}  // namespace mortar
